#include "synth/photo_press.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdlib>
#include <random>

#include "core/error.hpp"
#include "dataset/decode_image.hpp"
#include "synth/gelsight_camera.hpp"
#include "synth/gelsight_renderer.hpp"
#include "core/random_seeds.hpp"

namespace haptex::synth {
namespace {

int uniform_int(std::mt19937_64& engine, int lo, int hi) {  // [lo, hi], portable
  return lo + int(engine() % std::uint64_t(hi - lo + 1));
}

bool far_from_all(const cv::Point& corner, const std::vector<cv::Rect>& crops, int separation) {
  return std::all_of(crops.begin(), crops.end(), [&](const cv::Rect& c) {
    return std::max(std::abs(c.x - corner.x), std::abs(c.y - corner.y)) >= separation;
  });
}

// A GelSight shows a surface's micro-relief at high contrast even where a photograph of it is nearly
// uniform (plain paper): a crop whose grey variation is under this many levels is stretched to it
// about its mean, so every press shows its contact.
constexpr double kMinReliefContrast = 8.0;

// A GelSight's camera is exposed for the lit gel: a photograph's blacks and whites land inside
// its range, not clipped (a white fleece would otherwise saturate the sensor).
cv::Mat in_gel_range(const cv::Mat& crop) { return crop * 0.8 + cv::Scalar::all(24); }

cv::Mat with_relief_contrast(const cv::Mat& crop) {
  cv::Mat grey;
  cv::cvtColor(crop, grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, deviation;
  cv::meanStdDev(grey, mean, deviation);
  if (deviation[0] >= kMinReliefContrast) return crop;
  const double gain = kMinReliefContrast / std::max(deviation[0], 0.5);
  const cv::Scalar colour_mean = cv::mean(crop);
  cv::Mat stretched = (crop - colour_mean) * gain + colour_mean;
  return stretched;
}

// The light reaching the camera at contact weight w: the flat gel fading into the photograph.
cv::Mat blend(const cv::Mat& flat, const cv::Mat& crop, double weight) {
  cv::Mat radiance;
  cv::addWeighted(flat, 1 - weight, crop, weight, 0, radiance);
  return radiance;
}

}  // namespace

std::vector<cv::Rect> photo_crops(cv::Size image, std::uint64_t seed, const PhotoPressOptions& options) {
  if (image.width < options.width || image.height < options.height || options.width < 8 || options.height < 8)
    throw failure("photo_crops: a " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                  " image cannot hold " + std::to_string(options.width) + " x " + std::to_string(options.height) +
                  " crops");
  std::mt19937_64 engine(seed);
  std::vector<cv::Rect> crops;
  int separation = options.min_separation_px, misses = 0;
  while (int(crops.size()) < options.presses) {
    const cv::Point corner(uniform_int(engine, 0, image.width - options.width),
                           uniform_int(engine, 0, image.height - options.height));
    // Well apart when the photograph has room; otherwise halve the distance, down to merely distinct
    // (and to anything at all only when no distinct place is left).
    if (far_from_all(corner, crops, separation)) {
      crops.emplace_back(corner.x, corner.y, options.width, options.height);
      continue;
    }
    if (++misses % 200 == 0) separation /= 2;
  }
  return crops;
}

std::vector<PressSidecar> write_photo_presses(const std::string& image_path, const std::string& out_directory,
                                              const std::string& material, std::uint64_t seed,
                                              const std::string& source, const PhotoPressOptions& options) {
  // The press-image reader predict --image uses: a header over 64 megapixels and a photograph that does
  // not decode whole are refused, not handed to OpenCV (review 23, F2).
  const cv::Mat photo = dataset::read_image_file(image_path);
  if (photo.empty())
    throw input_error(image_path, "", "cannot read the texture photograph: it does not decode whole (cut short, damaged or CMYK?)",
                      "Give a readable RGB JPEG or PNG image");
  if (photo.cols < options.width || photo.rows < options.height)
    throw input_error(image_path, "", "the photograph is " + std::to_string(photo.cols) + " x " +
                      std::to_string(photo.rows) + ", smaller than one " + std::to_string(options.width) + " x " +
                      std::to_string(options.height) + " press", "Use the full-size HaTT image (1024 x 1024)");
  const GelSightCamera camera({options.width, options.height, options.noise_grey, 0.0});  // evenly lit
  const cv::Mat flat(options.height, options.width, CV_32FC3, cv::Scalar(flat_gel_colour()));
  const std::vector<cv::Rect> crops = photo_crops(photo.size(), derive_seed(seed, 0xc409), options);

  std::vector<PressSidecar> sidecars;
  for (int j = 0; j < options.presses; ++j) {
    const cv::Rect& rect = crops[std::size_t(j)];
    cv::Mat crop;
    photo(rect).convertTo(crop, CV_32FC3);
    crop = with_relief_contrast(in_gel_range(crop));
    const PressTimeline timeline = make_press_timeline(derive_seed(seed, 0x9407, std::uint64_t(j)), options.timeline);
    const std::uint64_t noise_seed = derive_seed(seed, 0x4015e, std::uint64_t(j));
    PressVideoWriter writer(out_directory, j, timeline.fps);
    for (int f = 0; f < timeline.frames(); ++f) {
      const double weight = timeline.depth_mm[std::size_t(f)] / timeline.peak_depth_mm();
      writer.add(camera.expose(blend(flat, crop, weight), timeline.exposure_gain[std::size_t(f)],
                               derive_seed(noise_seed, std::uint64_t(f))));
    }
    PressSidecar sidecar;
    sidecar.material = material;
    sidecar.press = j;
    sidecar.fps = timeline.fps;
    sidecar.peak_frame = timeline.peak_frame;
    sidecar.contact_first = timeline.contact_first;
    sidecar.contact_last = timeline.contact_last;
    sidecar.peak_depth_mm = timeline.peak_depth_mm();
    sidecar.crop_px = std::array<int, 4>{rect.x, rect.y, rect.width, rect.height};
    sidecar.source = source;
    sidecars.push_back(writer.finish(sidecar));
  }
  return sidecars;
}

}  // namespace haptex::synth
