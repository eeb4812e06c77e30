#pragma once
// From a source's frames to its presses: score every frame against the no-contact reference, cut the
// scores into presses, and per press keep its peak (the highest-scoring frame) and the peak's
// neighbours, 12 frames in all (schemas/hdf5-layout.md "GelSight file": training presses use all 12).
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/extraction/frame_source.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/press_segmenter.hpp"

namespace haptex::capture {

// Sensors send a few black frames right after stream start; a mean grey this dark (of 255) is not a
// gel image, in a video or as a --reference.
inline constexpr double kBlackLevel = 10.0;

struct ExtractSettings {
  int reference_frames = 10;   // leading no-contact frames averaged into the reference
  int frames_per_press = 12;   // the peak and its neighbours
  int margin_frames = 10;      // frames before and after the contact kept in each press's score curve
  // --pixel-threshold and --trigger: replace what the footage (or a given image's floors) gives
  // (contact_score.hpp).
  std::optional<float> pixel_threshold, trigger;
  SegmenterSettings segmenter; // its trigger and release come from the reference
  cv::Mat reference_image;     // BGR; when given it replaces the leading frames and stored references
  std::string reference_image_path;
};

// Where a source's no-contact reference came from (docs/capture.md, "The no-contact reference").
enum class ReferenceKind { start, end, least_contact, image, press_file };
const char* reference_kind_name(ReferenceKind kind);  // "start", "end", "least contact", "image", "press file"

struct SourceScores {
  std::vector<float> scores;  // one per frame; NaN for black start-up frames and frames that do not decode
  cv::Mat reference;          // BGR, frame size
  std::optional<ContactReference> contact;
  ReferenceKind reference_kind = ReferenceKind::start;
  std::int64_t reference_first = -1, reference_last = -1;  // the frames averaged into it; -1: an image
  std::string reference_note; // where the reference came from, for the file's attributes
  std::int64_t black_frames = 0, unreadable_frames = 0;
  std::int64_t stale_frames = 0;  // start-up frames of an earlier moment, before a jump (source_scores.cpp)
  // With the start's reference: the median score of the video's last frames when they too are a
  // steady stretch (the gel may settle a little differently after a grasp); NaN otherwise.
  float end_level = std::numeric_limits<float>::quiet_NaN();
};

// The score settings for a source: its defaults (lossy or lossless) and the overrides.
ScoreSettings score_settings(const FrameSource& source, const ExtractSettings& settings);

// Every frame's score against the source's no-contact reference (source_scores.cpp). Throws
// haptex::Error (bad_input) naming the source when it has too few usable frames, or when a given
// reference has another size.
SourceScores score_source(FrameSource& source, const ExtractSettings& settings);

struct PressPlan {
  int press_in_source = 0;
  PressInterval contact;
  std::int64_t range_first = 0, range_last = 0;  // the frames whose scores are stored with the press
  std::vector<std::int64_t> frame_indices;       // the frames kept: consecutive, containing the peak
};

// The presses in the scores, with the frames each keeps: the run of frames_per_press consecutive
// frames that contains the peak and scores highest in total, inside the press's own range when it
// is long enough (so neighbouring presses never share frames), all decoded (else anywhere in the
// source; a press with no such run is left out and counted in *left_out, review 6: one damaged
// frame beside a peak refused the whole video).
// With an end_level (SourceScores), a last press that lasts to the end hovering at the trigger is the
// video's settled end, not a press (peak_frames.cpp, without_settled_end).
std::vector<PressPlan> plan_presses(const std::vector<float>& scores, const SegmenterSettings& segmenter,
                                    int frames_per_press, int margin_frames,
                                    float end_level = std::numeric_limits<float>::quiet_NaN(), int* left_out = nullptr);

// A press's kept frames (frame_indices order) and its peak, decoded (BGR), and the source's own bytes
// of each when it gave them for all (else the byte lists are empty).
struct PressFrames {
  std::vector<cv::Mat> frames;
  cv::Mat peak;
  std::vector<dataset::EncodedImage> frames_encoded;
  dataset::EncodedImage peak_encoded;
};

// Second pass: reads every planned frame once, in order, and hands each press over as soon as its
// frames are in.
using PressFramesHandler = std::function<void(const PressPlan& plan, PressFrames frames)>;
void read_press_frames(FrameSource& source, const std::vector<PressPlan>& plans, const PressFramesHandler& handle);

}  // namespace haptex::capture
