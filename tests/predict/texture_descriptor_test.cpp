#include "predict/texture_descriptor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace haptex::predict {
namespace {

const TextureDescriptorSpec kSpec;  // 24 radial bins, 6 orientations x 4 octaves, 3 gradient scales
constexpr int kRadial = 24, kWedges = 24;

cv::Mat reference_image(int size, double brightness) {
  cv::Mat image(size, size, CV_32FC3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double r = std::hypot(x - size / 2.0, y - size / 2.0) / size;  // vignetting
      image.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(brightness * (1 - 0.3 * r * r)));
    }
  return image;
}

cv::Mat noise(int size, double amplitude, int seed) {
  cv::Mat n(size, size, CV_32FC3);
  cv::RNG rng{std::uint64_t(seed)};
  rng.fill(n, cv::RNG::NORMAL, 0, amplitude);
  return n;
}

cv::Mat grooves(int size, double period_px, bool vertical) {
  cv::Mat g(size, size, CV_32FC3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      g.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(20 * std::sin(2 * std::numbers::pi * (vertical ? x : y) / period_px)));
  return g;
}

int strongest_wedge(const std::vector<float>& d, int octave) {
  int best = 0;
  for (int w = 1; w < 6; ++w)
    if (d[std::size_t(kRadial + octave * 6 + w)] > d[std::size_t(kRadial + octave * 6 + best)]) best = w;
  return best;
}

TEST(TextureDescriptor, FixedLengthAndDeterministic) {
  const cv::Mat reference = reference_image(320, 120), peak = reference + noise(320, 5, 1);
  const auto a = texture_descriptor(peak, reference), b = texture_descriptor(peak, reference);
  EXPECT_EQ(a.size(), descriptor_length());
  EXPECT_EQ(a.size(), std::size_t(kRadial + kWedges + 9));
  EXPECT_EQ(a, b);
  for (float v : a) EXPECT_TRUE(std::isfinite(v));
}

TEST(TextureDescriptor, DescribesTheContactNotTheLighting) {
  const cv::Mat contact = noise(256, 6, 2);
  const cv::Mat dim = reference_image(256, 90), bright = reference_image(256, 160);
  const auto a = texture_descriptor(dim + contact, dim), b = texture_descriptor(bright + contact, bright);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-4) << i;
}

TEST(TextureDescriptor, RougherContactHasMorePower) {
  const cv::Mat reference = reference_image(256, 120);
  const auto smooth = texture_descriptor(reference + noise(256, 2, 3), reference);
  const auto rough = texture_descriptor(reference + noise(256, 8, 3), reference);
  for (int k = 0; k < kRadial; ++k)  // 4x the amplitude: 16x the power, log10(16) = 1.2
    EXPECT_NEAR(rough[std::size_t(k)] - smooth[std::size_t(k)], std::log10(16.0), 0.05) << k;
  EXPECT_GT(rough[std::size_t(kRadial + kWedges)], smooth[std::size_t(kRadial + kWedges)]);  // mean slope
}

TEST(TextureDescriptor, GroovesShowTheirDirectionAndRotateWithTheImage) {
  const cv::Mat reference = reference_image(256, 120);
  const auto across_x = texture_descriptor(reference + grooves(256, 8, true), reference);
  const auto across_y = texture_descriptor(reference + grooves(256, 8, false), reference);
  // Period 8 px at 256 -> 0.125 cycles/px: octave 1 (0.125 .. 0.25]. Direction rotates by 90 degrees = 3 wedges.
  EXPECT_EQ((strongest_wedge(across_x, 1) + 3) % 6, strongest_wedge(across_y, 1));
  const float coherence_grooves = across_x[std::size_t(kRadial + kWedges + 2)];
  const float coherence_noise = texture_descriptor(reference + noise(256, 6, 4), reference)[std::size_t(kRadial + kWedges + 2)];
  EXPECT_GT(coherence_grooves, 0.8f);
  EXPECT_LT(coherence_noise, 0.2f);
  // Rotating the whole press by 90 degrees leaves the radial spectrum as it was.
  cv::Mat peak = reference + noise(256, 5, 5), peak_rotated, reference_rotated;
  cv::rotate(peak, peak_rotated, cv::ROTATE_90_CLOCKWISE);
  cv::rotate(reference, reference_rotated, cv::ROTATE_90_CLOCKWISE);
  const auto a = texture_descriptor(peak, reference), b = texture_descriptor(peak_rotated, reference_rotated);
  for (int k = 0; k < kRadial; ++k) EXPECT_NEAR(a[std::size_t(k)], b[std::size_t(k)], 1e-3) << k;
}

TEST(TextureDescriptor, RefusesImagesOfDifferentSizes) {
  EXPECT_THROW(texture_descriptor(reference_image(64, 100), reference_image(32, 100)), Error);
  TextureDescriptorSpec odd;
  odd.size = 100;
  EXPECT_THROW(texture_descriptor(reference_image(64, 100), reference_image(64, 100), odd), Error);
}

// Issue 11 point 7: the image is reduced to spec.size before anything else, so the descriptor of a
// large frame equals that of the frame reduced first (the blur of the self-reference included) and
// its cost no longer grows with the blur's reach over millions of pixels.
TEST(TextureDescriptor, WorksAtItsOwnResolutionWhateverTheImageSize) {
  const cv::Mat large = reference_image(2048, 120) + noise(2048, 6, 5);
  cv::Mat reduced;
  cv::resize(large, reduced, {256, 256}, 0, 0, cv::INTER_AREA);
  const auto a = texture_descriptor_self_referenced(large), b = texture_descriptor_self_referenced(reduced);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-3 * (1 + std::abs(b[i]))) << i;
  // With a reference, reducing first changes nothing either (area averaging is linear).
  const cv::Mat reference = reference_image(2048, 120);
  cv::Mat reference_reduced;
  cv::resize(reference, reference_reduced, {256, 256}, 0, 0, cv::INTER_AREA);
  const auto c = texture_descriptor(large, reference), d = texture_descriptor(reduced, reference_reduced);
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(c[i], d[i], 1e-3 * (1 + std::abs(d[i]))) << i;
}

TEST(TextureDescriptor, SpecsItCannotComputeAreNamed) {
  EXPECT_EQ(spec_problem(kSpec), "");
  for (const auto& [spec, says] : {std::pair{TextureDescriptorSpec{100, 24, 6, 4, 3}, "size"}, std::pair{TextureDescriptorSpec{256, 0, 6, 4, 3}, "radial_bins"},
                                   std::pair{TextureDescriptorSpec{256, 24, 6, 9, 3}, "octaves"}, std::pair{TextureDescriptorSpec{16, 24, 6, 4, 3}, "gradient_scales"},
                                   std::pair{TextureDescriptorSpec{1 << 20, 24, 6, 4, 3}, "size"}})
    EXPECT_NE(spec_problem(spec).find(says), std::string::npos) << spec_problem(spec);
}

}  // namespace
}  // namespace haptex::predict
