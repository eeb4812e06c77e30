#include "qa/press_data.hpp"

#include <algorithm>
#include <cstring>

#include <opencv2/imgproc.hpp>

#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/press_images.hpp"
#include "qa/recording_data.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

double laplacian_variance(const cv::Mat& bgr) {
  cv::Mat grey, lap;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Laplacian(grey, lap, CV_64F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(lap, mean, stddev);
  return stddev[0] * stddev[0];
}

double saturated_share(const cv::Mat& bgr) {
  std::vector<cv::Mat> channels;
  cv::split(bgr, channels);
  const cv::Mat brightest = cv::max(cv::max(channels[0], channels[1]), channels[2]);
  return double(cv::countNonZero(brightest >= kSaturatedLevel)) / double(bgr.total());
}

// The images of dataset `name` as BGR; none when it is missing or does not read (the layout checks
// report its form; a damaged image is reported by the press's other checks as missing).
std::vector<cv::Mat> read_images(const h5::Group& press, const std::string& name) {
  if (!press.has_dataset(name)) return {};
  try {
    return dataset::read_press_images(press, name, false);  // the sizes are compared below, with the attributes
  } catch (const Error&) {
    return {};
  }
}

std::optional<cv::Mat> read_single(const h5::Group& press, const std::string& name) {
  std::vector<cv::Mat> images = read_images(press, name);
  if (images.size() != 1) return std::nullopt;
  return images.front();
}

// layout.* reports a missing or mistyped attribute; source_damage skips the press then.
void read_source_frames_unreadable(const h5::Group& g, Press& p) {
  try {
    if (!g.has_attr(layout::kSourceFramesUnreadable)) {
      p.source_frames_problem = p.path + ": no source_frames_unreadable attribute";
      return;
    }
    p.source_frames_unreadable = g.attr_int(layout::kSourceFramesUnreadable);
  } catch (const Error&) {
    p.source_frames_problem = p.path + "/@source_frames_unreadable is not an integer";
  }
}

Press summarize_press(const h5::Group& g, std::string path, std::string material) {
  Press p;
  p.path = std::move(path);
  p.material = std::move(material);
  p.trigger = g.try_attr<double>(layout::kTrigger);
  p.pixel_threshold = g.try_attr<double>(layout::kPixelThreshold);
  // Images in an order qa cannot read are not judged: gelsight.channel_order reports the press.
  try {
    for (const char* image : {layout::kReference, layout::kPeak, layout::kFrames}) dataset::read_channel_order(g, image);
  } catch (const Error& e) {
    p.channel_order_problem = e.what();
    read_source_frames_unreadable(g, p);
    return p;
  }
  const std::optional<cv::Mat> reference = read_single(g, layout::kReference), peak = read_single(g, layout::kPeak);
  const std::vector<cv::Mat> frames = read_images(g, layout::kFrames);
  std::vector<cv::Size> sizes;
  if (reference) {
    p.has_reference = true;
    p.reference_size = reference->size();
    p.reference_scoring = capture::scoring_image(*reference);
    p.reference_sharpness = laplacian_variance(*reference);
    sizes.push_back(p.reference_size);
  }
  std::vector<const cv::Mat*> images;
  if (peak) {
    p.has_peak = true;
    p.peak_size = peak->size();
    sizes.push_back(p.peak_size);
    images.push_back(&*peak);
    p.images.push_back({p.path + "/peak", p.peak_size, 0, 0});
    if (reference && p.pixel_threshold && reference->size() == peak->size())
      p.peak_score = capture::contact_score(capture::scoring_image(*peak), p.reference_scoring, float(*p.pixel_threshold));
  }
  if (!frames.empty()) {
    p.frames_size = frames.front().size();
    sizes.push_back(p.frames_size);
  }
  for (std::size_t i = 0; i < frames.size(); ++i) {
    images.push_back(&frames[i]);
    p.images.push_back({p.path + "/frames[" + std::to_string(i) + "]", frames[i].size(), 0, 0});
  }
  // Encoded images carry their size inside; the press's attributes state it for the layout.
  const std::optional<double> width = g.try_attr<double>(layout::kWidth), height = g.try_attr<double>(layout::kHeight);
  const auto pixels = [](double v) { return v >= 0 && v < 1e6 ? int(v) : -1; };  // NaN or absurd: no size
  if (!sizes.empty() && width && height) sizes.push_back(cv::Size(pixels(*width), pixels(*height)));
  p.sizes_agree = !sizes.empty() && std::all_of(sizes.begin(), sizes.end(), [&](cv::Size s) { return s == sizes.front(); });
  parallel_for(images.size(), [&](std::size_t i) {
    p.images[i].sharpness = laplacian_variance(*images[i]);
    p.images[i].saturated = saturated_share(*images[i]);
  });
  read_source_frames_unreadable(g, p);
  return p;
}


}  // namespace

std::vector<std::string> press_paths(const h5::Group& root) {
  std::vector<std::string> paths;
  if (!root.has_group(layout::kMaterials)) return paths;
  const h5::Group materials = root.open_group(layout::kMaterials);
  for (const auto& id : materials.children()) {
    if (!materials.has_group(id) || !materials.open_group(id).has_group(layout::kPresses)) continue;
    const h5::Group presses = materials.open_group(id).open_group(layout::kPresses);
    for (const auto& j : presses.children())
      if (presses.has_group(j)) paths.push_back(dataset::press_path(id, j));
  }
  return paths;
}

GelsightPresses read_presses(const h5::Group& root) {
  GelsightPresses file;
  if (!root.has_group(layout::kMaterials)) return file;
  const h5::Group materials = root.open_group(layout::kMaterials);
  for (const auto& id : materials.children())
    if (materials.has_group(id)) file.per_material[id] = 0;
  for (const std::string& path : press_paths(root)) {
    const std::string material = dataset::material_of(path);
    file.presses.push_back(summarize_press(root.open_group(path.substr(1)), path, material));
    ++file.per_material[material];
  }
  return file;
}

}  // namespace haptex::qa
