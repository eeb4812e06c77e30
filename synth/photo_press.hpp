#pragma once
// GelSight-like press videos made from a HaTT texture photograph (<Material>_square.jpg), so the whole
// GelSight path (capture extract, align, the texture encoder) can run on real surfaces: five crops at
// separate places of the photograph, each a press video whose frames blend from a flat, evenly lit
// gel into the crop and back as contact rises and falls, with the camera noise and exposure drift of
// the rendered presses. Written like every press (synth/press_video_writer.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "synth/press_timeline.hpp"
#include "synth/press_video_writer.hpp"

namespace haptex::synth {

struct PhotoPressOptions {
  int presses = 5;
  int width = 640, height = 480;  // of each crop, and so of the video
  int min_separation_px = 96;     // between crop corners (both axes), relaxed on small photographs
  double noise_grey = 1.0;
  PressTimelineOptions timeline;
};

// `presses` distinct crop rectangles inside an image of this size, deterministic for the seed.
// Throws haptex::Error (failure) when the image is smaller than a crop.
std::vector<cv::Rect> photo_crops(cv::Size image, std::uint64_t seed, const PhotoPressOptions& options = {});

// Writes press_0 .. press_<n-1> (frames and sidecars) of the photograph into out_directory. Throws
// haptex::Error (bad_input) when the image cannot be read or is smaller than a crop.
std::vector<PressSidecar> write_photo_presses(const std::string& image_path, const std::string& out_directory,
                                              const std::string& material, std::uint64_t seed,
                                              const std::string& source = "haptex synth hatt",
                                              const PhotoPressOptions& options = {});

}  // namespace haptex::synth
