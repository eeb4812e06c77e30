#include "capture/scoring/scoring_image.hpp"

#include "core/image_header.hpp"
#include "dataset/decode_image.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif
#include <opencv2/imgproc.hpp>

namespace haptex::capture {
namespace {

constexpr int kMinimumWidth = 160;

cv::Mat to_float(const cv::Mat& grey) {
  cv::Mat out;
  grey.convertTo(out, CV_32F);
  return out;
}

#ifdef __SSE2__
// [a0 + a1, a2 + a3, b0 + b1, b2 + b3] of two vectors of four 32-bit sums.
__m128i add_pairs(__m128i a, __m128i b) {
  const __m128 fa = _mm_castsi128_ps(a), fb = _mm_castsi128_ps(b);
  return _mm_add_epi32(_mm_castps_si128(_mm_shuffle_ps(fa, fb, _MM_SHUFFLE(2, 0, 2, 0))),
                       _mm_castps_si128(_mm_shuffle_ps(fa, fb, _MM_SHUFFLE(3, 1, 3, 1))));
}

// Eight 16-bit column sums (up to 8 x 255: madd's signed arithmetic is safe) added in pairs: four 32-bit.
__m128i pair_sums(const std::uint16_t* p) {
  return _mm_madd_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), _mm_set1_epi16(1));
}
#endif

// out[i] = scale x (column sums r i .. r i + r - 1), r = 2, 4 or 8: four outputs at a time in SSE2
// (every x86-64 has it), the rest one by one.
void block_sums(const std::uint16_t* c, int r, float scale, float* out, int n) {
  int i = 0;
#ifdef __SSE2__
  for (; i + 4 <= n; i += 4) {
    const std::uint16_t* p = c + r * i;
    const __m128i s = r == 2   ? pair_sums(p)
                      : r == 4 ? add_pairs(pair_sums(p), pair_sums(p + 8))
                               : add_pairs(add_pairs(pair_sums(p), pair_sums(p + 8)), add_pairs(pair_sums(p + 16), pair_sums(p + 24)));
    _mm_storeu_ps(out + i, _mm_mul_ps(_mm_cvtepi32_ps(s), _mm_set1_ps(scale)));
  }
#endif
  for (; i < n; ++i) {
    unsigned sum = 0;
    for (int x = 0; x < r; ++x) sum += c[r * i + x];
    out[i] = float(sum) * scale;
  }
}

// The r x r block means of a grey image whose sides are multiples of r: the rows of a block added
// up first (a vectorised pass over whole rows), then each block's columns. OpenCV's INTER_AREA gives
// the same means rounded to whole grey levels, in twice the time (bench_capture's BM_ScoringImage).
cv::Mat block_means(const cv::Mat& grey, int r) {
  cv::Mat out(grey.rows / r, grey.cols / r, CV_32F);
  thread_local std::vector<std::uint16_t> columns;  // a sum of r rows: at most 8 x 255
  columns.resize(std::size_t(grey.cols));
  std::uint16_t* c = columns.data();
  const float scale = 1.0f / float(r * r);
  for (int j = 0; j < out.rows; ++j) {
    std::fill(columns.begin(), columns.end(), std::uint16_t{0});
    for (int y = 0; y < r; ++y) {
      const std::uint8_t* p = grey.ptr<std::uint8_t>(r * j + y);
#pragma omp simd
      for (int i = 0; i < grey.cols; ++i) c[i] = std::uint16_t(c[i] + p[i]);
    }
    block_sums(c, r, scale, out.ptr<float>(j), out.cols);
  }
  return out;
}

}  // namespace

int jpeg_reduction(cv::Size frame) {
  const int f = std::max(1, int(std::lround(double(frame.width) / kMinimumWidth)));
  return f >= 8 ? 8 : f >= 4 ? 4 : f >= 2 ? 2 : 1;
}

cv::Size scoring_size(cv::Size frame) {
  // DCT scaling rounds up: 3280 / 8 -> 410.
  const int r = jpeg_reduction(frame);
  return {(frame.width + r - 1) / r, (frame.height + r - 1) / r};
}

cv::Mat scoring_image(const cv::Mat& frame) {
  cv::Mat grey = frame;
  if (frame.channels() != 1) cv::cvtColor(frame, grey, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  const cv::Size size = scoring_size(frame.size());
  if (grey.size() == size) return to_float(grey);
  const int r = jpeg_reduction(frame.size());
  if (grey.cols == size.width * r && grey.rows == size.height * r) return block_means(grey, r);
  cv::Mat reduced;  // sides that are no multiple of r: the last blocks are partial
  cv::resize(grey, reduced, size, 0, 0, cv::INTER_AREA);
  return to_float(reduced);
}

cv::Mat scoring_image_from_jpeg(std::span<const std::uint8_t> jpeg, cv::Size frame) {
  // A frame whose header states another size is not the camera's: refused before libjpeg sizes its buffers by it.
  const std::optional<ImageSize> stated = image_header_size(jpeg);
  if (!stated || cv::Size(int(stated->width), int(stated->height)) != frame) return {};
  const cv::Mat grey = dataset::decode_jpeg(jpeg, dataset::DecodedColour::grey, jpeg_reduction(frame));
  if (grey.empty() || grey.size() != scoring_size(frame)) return {};
  return to_float(grey);
}

cv::Mat scoring_image_from_yuyv(std::span<const std::uint8_t> yuyv, cv::Size frame) {
  if (yuyv.size() != std::size_t(frame.width) * frame.height * 2) return {};
  const cv::Mat packed(frame.height, frame.width, CV_8UC2, const_cast<std::uint8_t*>(yuyv.data()));
  cv::Mat luma, grey;
  cv::extractChannel(packed, luma, 0);
  // UVC sends luma in video range (16..235). Stretched to 0..255 it is the grey level of the decoded
  // frame, which press files store (PNG) and extraction scores: live and offline scores and thresholds
  // share one scale.
  luma.convertTo(grey, CV_8U, 255.0 / 219, -16 * 255.0 / 219);
  return scoring_image(grey);
}

}  // namespace haptex::capture
