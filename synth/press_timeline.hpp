#pragma once
// The course of one hand press of a GelSight sensor, frame by frame at the camera's rate: a quiet
// lead-in with no contact, a ramp to the deepest contact, a brief hold, a release and a few quiet
// frames. It carries its own ground truth (peak frame, contact interval), which the sidecar records
// and `capture extract` must recover from the pixels alone.
#include <cstdint>
#include <vector>

namespace haptex::synth {

struct PressTimelineOptions {
  double fps = 30;
  int lead_frames = 15;         // no-contact frames before contact, at least (seeded jitter adds 0..2)
  double peak_depth_mm = 0.12;  // before the seeded jitter
  double peak_jitter = 0.15;    // the peak depth varies by up to this share either way
  double max_drift = 0.003;     // the exposure gain drifts by at most this share over the press:
                                // under one grey level even at full scale (0.003 x 255 = 0.77)
};

struct PressTimeline {
  double fps = 30;
  std::vector<double> depth_mm;       // contact depth per frame; 0 = no contact
  std::vector<double> exposure_gain;  // the camera's slow exposure drift per frame, about 1
  int peak_frame = 0;                 // the single frame of largest depth
  int contact_first = 0;              // first and last frames with depth > 0
  int contact_last = 0;

  int frames() const { return int(depth_mm.size()); }
  double peak_depth_mm() const { return depth_mm.at(std::size_t(peak_frame)); }
};

// 31 to 41 frames: 15-17 quiet, a 6-9 frame ramp, a 3-5 frame hold whose middle frame is the unique
// deepest, a 4-6 frame release, 3-4 quiet. Deterministic for a seed.
PressTimeline make_press_timeline(std::uint64_t seed, const PressTimelineOptions& options = {});

}  // namespace haptex::synth
