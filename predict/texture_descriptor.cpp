#include "predict/texture_descriptor.hpp"

#include <bit>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace haptex::predict {
namespace {

constexpr double kFloor = 1e-12;  // keeps log() finite on a flat image

// The grey image weighs R, G and B by 0.114, 0.587 and 0.299: OpenCV's BGR weights applied to the
// RGB images the descriptor has always been given (texture_descriptor/1, the models trained on it).
// Correcting it to Rec. 601's 0.299 R is texture_descriptor/2 and means retraining every model; what
// matters for the models is that training and prediction see the channels in the same order.
cv::Mat grey_float(const cv::Mat& image) {
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);  // on RGB pixels: above
  cv::Mat out;
  grey.convertTo(out, CV_32F);
  return out;
}

// An image as the descriptor sees it: grey and area-averaged to size x size. Area averaging is
// linear, so the difference of two reduced images is the reduced difference.
cv::Mat reduced(const cv::Mat& image, int size) {
  cv::Mat out;
  cv::resize(grey_float(image), out, {size, size}, 0, 0, cv::INTER_AREA);
  return out;
}

cv::Mat power_spectrum(const cv::Mat& image) {
  cv::Mat window;
  cv::createHanningWindow(window, image.size(), CV_32F);
  cv::Mat spectrum;
  cv::dft(image.mul(window), spectrum, cv::DFT_COMPLEX_OUTPUT);
  cv::Mat planes[2];
  cv::split(spectrum, planes);
  cv::Mat power;
  cv::magnitude(planes[0], planes[1], power);
  return power.mul(power);
}

// Frequency of DFT index i on n points, in cycles per pixel (-0.5 .. 0.5).
double frequency(int i, int n) { return double(i <= n / 2 ? i : i - n) / n; }

void spectral_features(const cv::Mat& power, const TextureDescriptorSpec& spec, std::vector<float>& out) {
  const int n = power.rows;
  std::vector<double> radial(std::size_t(spec.radial_bins), 0.0), wedges(std::size_t(spec.orientations * spec.octaves), 0.0);
  std::vector<int> radial_count(radial.size(), 0);
  for (int v = 0; v < n; ++v)
    for (int u = 0; u < n; ++u) {
      const double fx = frequency(u, n), fy = frequency(v, n), r = std::hypot(fx, fy);
      if (r <= 0 || r > 0.5) continue;
      const double p = power.at<float>(v, u);
      const int ring = std::min(spec.radial_bins - 1, int(r / 0.5 * spec.radial_bins));
      radial[std::size_t(ring)] += p;
      ++radial_count[std::size_t(ring)];
      // Octave o covers (0.5 / 2^(o+1), 0.5 / 2^o]; orientation folded to [0, pi).
      const int octave = int(std::floor(std::log2(0.5 / r)));
      if (octave < 0 || octave >= spec.octaves) continue;
      double angle = std::atan2(fy, fx);
      if (angle < 0) angle += std::numbers::pi;
      const int wedge = std::min(spec.orientations - 1, int(angle / std::numbers::pi * spec.orientations));
      wedges[std::size_t(octave * spec.orientations + wedge)] += p;
    }
  for (std::size_t i = 0; i < radial.size(); ++i)
    out.push_back(float(std::log10(radial[i] / std::max(1, radial_count[i]) + kFloor)));
  for (double w : wedges) out.push_back(float(std::log10(w + kFloor)));
}

// Mean and spread of the slope, and the coherence of its direction (0: no preferred direction, 1: all one way).
void gradient_features(cv::Mat image, int scales, std::vector<float>& out) {
  for (int s = 0; s < scales; ++s) {
    cv::Mat gx, gy;
    cv::Sobel(image, gx, CV_32F, 1, 0, 3);
    cv::Sobel(image, gy, CV_32F, 0, 1, 3);
    cv::Mat magnitude;
    cv::magnitude(gx, gy, magnitude);
    cv::Scalar mean, deviation;
    cv::meanStdDev(magnitude, mean, deviation);
    const double jxx = cv::sum(gx.mul(gx))[0], jyy = cv::sum(gy.mul(gy))[0], jxy = cv::sum(gx.mul(gy))[0];
    const double coherence = std::sqrt((jxx - jyy) * (jxx - jyy) + 4 * jxy * jxy) / (jxx + jyy + kFloor);
    out.push_back(float(std::log10(mean[0] + 1e-6)));
    out.push_back(float(std::log10(deviation[0] + 1e-6)));
    out.push_back(float(coherence));
    cv::Mat smaller;
    cv::pyrDown(image, smaller);
    image = smaller;
  }
}

}  // namespace

std::size_t descriptor_length(const TextureDescriptorSpec& spec) {
  return std::size_t(spec.radial_bins + spec.orientations * spec.octaves + 3 * spec.gradient_scales);
}

std::string spec_problem(const TextureDescriptorSpec& spec) {
  if (spec.size < 16 || spec.size > 4096 || (spec.size & (spec.size - 1)) != 0) return "size must be a power of two in 16..4096";
  const int log2_size = std::countr_zero(unsigned(spec.size));
  if (spec.radial_bins < 1 || spec.radial_bins > 1024) return "radial_bins must be in 1..1024";
  if (spec.orientations < 1 || spec.orientations > 180) return "orientations must be in 1..180";
  if (spec.octaves < 1 || spec.octaves > log2_size) return "octaves must be in 1.." + std::to_string(log2_size);
  if (spec.gradient_scales < 1 || spec.gradient_scales > log2_size - 2)
    return "gradient_scales must be in 1.." + std::to_string(log2_size - 2);
  return "";
}

namespace {

// From the reduced peak and reference: the contact image (their difference, mean removed) described.
std::vector<float> describe(const cv::Mat& peak, const cv::Mat& reference, const TextureDescriptorSpec& spec) {
  cv::Mat contact = peak - reference;
  contact -= cv::mean(contact)[0];
  std::vector<float> out;
  out.reserve(descriptor_length(spec));
  spectral_features(power_spectrum(contact), spec, out);
  gradient_features(contact, spec.gradient_scales, out);
  return out;
}

}  // namespace

std::vector<float> texture_descriptor(const cv::Mat& peak, const cv::Mat& reference, const TextureDescriptorSpec& spec) {
  if (peak.empty() || peak.size() != reference.size())
    throw failure("texture_descriptor: the peak and reference images must be non-empty and of one size");
  if (const std::string problem = spec_problem(spec); !problem.empty()) throw failure("texture_descriptor: " + problem);
  return describe(reduced(peak, spec.size), reduced(reference, spec.size), spec);
}

std::vector<float> texture_descriptor_self_referenced(const cv::Mat& peak, const TextureDescriptorSpec& spec) {
  if (peak.empty()) throw failure("texture_descriptor: the peak image is empty");
  if (const std::string problem = spec_problem(spec); !problem.empty()) throw failure("texture_descriptor: " + problem);
  const cv::Mat small = reduced(peak, spec.size);
  cv::Mat reference;
  const double sigma = spec.size / 16.0;
  cv::GaussianBlur(small, reference, {0, 0}, sigma, sigma, cv::BORDER_REFLECT);
  return describe(small, reference, spec);
}

}  // namespace haptex::predict
