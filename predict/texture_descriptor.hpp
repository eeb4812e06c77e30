#pragma once
// The fixed, hand-made half of the texture encoder (issue 6): a GelSight peak image, taken relative
// to its no-contact reference, described at several scales by
//   - the radially averaged log power spectrum of the contact image (how rough, at which scales),
//   - the log power in oriented frequency wedges per octave (direction of grooves, weaves, brushing),
//   - gradient statistics at three scales (mean and spread of slope, and how aligned the slopes are).
// Learned layers (predict/) map it to the texture latent. Comparing to the reference removes the
// sensor's lighting and vignetting, which say nothing about the surface.
#include <cstddef>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace haptex::predict {

struct TextureDescriptorSpec {
  int size = 256;          // the contact image is resized to size x size (power of two)
  int radial_bins = 24;    // of the radially averaged spectrum, up to the Nyquist frequency
  int orientations = 6;    // wedges over 180 degrees
  int octaves = 4;         // frequency bands for the oriented energies, the highest ending at Nyquist
  int gradient_scales = 3; // 1, 1/2, 1/4 of the image size
};

std::size_t descriptor_length(const TextureDescriptorSpec& spec = {});
// "" when texture_descriptor can compute this spec; otherwise what is wrong with it (a model file's
// spec is checked with this before use).
std::string spec_problem(const TextureDescriptorSpec& spec);

// peak and reference: RGB (the order haptex files store; readers convert to it) or grey images of
// one size (8-bit or float). Throws haptex::Error when they differ in size or are empty.
std::vector<float> texture_descriptor(const cv::Mat& peak, const cv::Mat& reference, const TextureDescriptorSpec& spec = {});

// The same without a reference, for a user who has only the press image: the image blurred at 1/16
// of its size stands in for the no-contact frame (it keeps the sensor's lighting and vignetting and
// drops the texture); the descriptor's lowest radial bins are less reliable with it. The blur runs
// on the image reduced to spec.size, so a 3280 x 2464 frame costs about what a 640 x 480 one does.
std::vector<float> texture_descriptor_self_referenced(const cv::Mat& peak, const TextureDescriptorSpec& spec = {});

}  // namespace haptex::predict
