// gelsight.*: the no-contact reference, the peak's contact score, saturation, blur, image size and
// press count of every press (/materials/{material}/presses/{j}) of a gelsight or dataset file.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "capture/extraction/contact_score.hpp"
#include "capture/extraction/scoring_image.hpp"
#include "capture/recording/image_datasets.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {
namespace {

std::string size_text(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

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

// N x H x W x 3 uint8 (RGB) -> N BGR images; empty when the dataset has another form.
std::vector<cv::Mat> read_stack(const h5::Group& press, const std::string& name) {
  if (!press.has_dataset(name)) return {};
  const h5::Dataset d = press.open_dataset(name);
  const h5::Shape shape = d.shape();
  if (shape.size() != 4 || shape[3] != 3 || d.dtype() != "uint8" || shape[0] == 0) return {};
  const std::vector<std::uint8_t> rgb = d.read<std::uint8_t>();
  const std::size_t frame_bytes = shape[1] * shape[2] * 3;
  std::vector<cv::Mat> frames;
  for (std::size_t i = 0; i < shape[0]; ++i) {
    cv::Mat image(static_cast<int>(shape[1]), static_cast<int>(shape[2]), CV_8UC3);
    std::memcpy(image.data, rgb.data() + i * frame_bytes, frame_bytes);
    cv::cvtColor(image, image, cv::COLOR_RGB2BGR);
    frames.push_back(image);
  }
  return frames;
}

std::optional<cv::Mat> read_single(const h5::Group& press, const std::string& name) {
  if (!press.has_dataset(name)) return std::nullopt;
  try {
    return capture::read_image(press.open_dataset(name));
  } catch (const Error&) {
    return std::nullopt;
  }
}

std::optional<double> number_attr(const h5::Group& g, const char* name) {
  if (!g.has_attr(name)) return std::nullopt;
  try {
    return g.attr_double(name);
  } catch (const Error&) {
    return std::nullopt;
  }
}

// What the checks need of one press, measured as it is read: its images are not kept, so a file of
// thousands of full-size frames is checked in the memory of one press.
struct Press {
  std::string path, material;
  std::optional<double> trigger, pixel_threshold;
  bool has_reference = false, has_peak = false;
  cv::Size reference_size, peak_size, frames_size;
  bool sizes_agree = false;
  cv::Mat reference_scoring;            // CV_32F scoring image of the reference
  double reference_sharpness = 0;       // variance of its Laplacian
  std::optional<double> peak_score;     // the peak against the reference, recomputed
  struct Image {
    std::string where;
    cv::Size size;
    double sharpness = 0, saturated = 0;
  };
  std::vector<Image> images;            // the peak and every frame
};

Press summarize_press(const h5::Group& g, std::string path, std::string material) {
  Press p;
  p.path = std::move(path);
  p.material = std::move(material);
  p.trigger = number_attr(g, "trigger");
  p.pixel_threshold = number_attr(g, "pixel_threshold");
  const std::optional<cv::Mat> reference = read_single(g, "reference"), peak = read_single(g, "peak");
  const std::vector<cv::Mat> frames = read_stack(g, "frames");
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
  p.sizes_agree = !sizes.empty() && std::all_of(sizes.begin(), sizes.end(), [&](cv::Size s) { return s == sizes.front(); });
  parallel_for(images.size(), [&](std::size_t i) {
    p.images[i].sharpness = laplacian_variance(*images[i]);
    p.images[i].saturated = saturated_share(*images[i]);
  });
  return p;
}

cv::Size press_size(const Press& p) {
  return p.has_reference ? p.reference_size : p.has_peak ? p.peak_size : p.frames_size;
}

std::pair<int, int> key_of(cv::Size s) { return {s.width, s.height}; }

// Per-pixel median of scoring images of one size.
cv::Mat median_image(const std::vector<const cv::Mat*>& images) {
  cv::Mat out(images.front()->size(), CV_32F);
  std::vector<float> values(images.size());
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      for (std::size_t i = 0; i < images.size(); ++i) values[i] = images[i]->at<float>(y, x);
      std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
      out.at<float>(y, x) = values[values.size() / 2];
    }
  return out;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// capture extract records how many frames of the press's source did not decode; layout.* reports a
// missing or mistyped attribute.
void check_source_damage(const h5::Group& press, const std::string& path, CheckTally& damage) {
  std::int64_t unreadable = 0;
  try {
    if (!press.has_attr("source_frames_unreadable")) return damage.skip(path + ": no source_frames_unreadable attribute");
    unreadable = press.attr_int("source_frames_unreadable");
  } catch (const Error&) {
    return damage.skip(path + "/@source_frames_unreadable is not an integer");
  }
  if (unreadable > 0)
    damage.fail(path, "its source had " + std::to_string(unreadable) + " frames that did not decode or never arrived (none is kept)");
  else damage.pass();
}

}  // namespace

std::vector<CheckResult> check_gelsight(const h5::Group& root) {
  CheckTally reference("gelsight.reference", "references"), peak_score("gelsight.peak_score", "presses"),
      saturation("gelsight.saturation", "frames"), blur("gelsight.blur", "frames"),
      resolution("gelsight.resolution", "materials"), press_count("gelsight.press_count", "materials"),
      damage("gelsight.source_damage", "presses");

  std::vector<Press> presses;
  std::map<std::string, std::size_t> per_material;  // presses per material id
  if (root.has_group("materials")) {
    const h5::Group materials = root.open_group("materials");
    for (const auto& id : materials.children()) {
      if (!materials.has_group(id)) continue;
      const h5::Group material = materials.open_group(id);
      per_material[id] = 0;
      if (!material.has_group("presses")) continue;
      const h5::Group group = material.open_group("presses");
      for (const auto& j : group.children()) {
        if (!group.has_group(j)) continue;
        presses.push_back(summarize_press(group.open_group(j), "/materials/" + id + "/presses/" + j, id));
        ++per_material[id];
        check_source_damage(group.open_group(j), presses.back().path, damage);
      }
    }
  }

  // Press count and resolution, per material.
  for (const auto& [id, count] : per_material) {
    if (count < kPressesPerMaterial)
      press_count.fail("/materials/" + id + "/presses", std::to_string(count) + " presses, at least " +
                                                            std::to_string(kPressesPerMaterial) + " needed (3 train, 1 val, 1 test)");
    else press_count.pass();
    std::map<std::string, std::size_t> by_size;  // "WxH" -> presses
    std::string mixed_inside;
    for (const auto& p : presses) {
      if (p.material != id) continue;
      if (!p.sizes_agree && (p.has_reference || p.has_peak || p.frames_size.width > 0)) {
        if (mixed_inside.empty()) mixed_inside = p.path;
        continue;
      }
      if (p.sizes_agree) ++by_size[size_text(press_size(p))];
    }
    if (!mixed_inside.empty()) resolution.fail(mixed_inside, "reference, peak and frames differ in size");
    else if (by_size.size() > 1) {
      std::string sizes;
      for (const auto& [s, n] : by_size) sizes += (sizes.empty() ? "" : ", ") + s + " (" + std::to_string(n) + ")";
      resolution.fail("/materials/" + id + "/presses", "presses of several sizes: " + sizes);
    } else if (by_size.empty()) resolution.skip("/materials/" + id + ": no readable press images");
    else resolution.pass();
  }

  // Baselines per image size (one sensor mode): the median no-contact reference and its sharpness.
  std::map<std::pair<int, int>, std::vector<const cv::Mat*>> references;
  std::map<std::pair<int, int>, std::vector<double>> sharpness;
  for (const auto& p : presses)
    if (p.has_reference) {
      references[key_of(p.reference_size)].push_back(&p.reference_scoring);
      sharpness[key_of(p.reference_size)].push_back(p.reference_sharpness);
    }
  std::map<std::pair<int, int>, cv::Mat> median_reference;
  for (const auto& [key, images] : references)
    if (images.size() >= kMinReferencesForMedian) median_reference[key] = median_image(images);
  std::map<std::pair<int, int>, double> median_sharpness;
  for (const auto& [key, values] : sharpness) median_sharpness[key] = median(values);

  double worst_reference = 0, worst_peak = INFINITY, worst_saturation = 0, worst_blur = INFINITY;
  for (const auto& p : presses) {
    const bool thresholds = p.trigger && p.pixel_threshold && *p.trigger > 0;
    // Reference: no contact against the median reference of its size.
    if (!p.has_reference) reference.skip(p.path + ": no readable reference");
    else if (!thresholds) reference.skip(p.path + ": no positive trigger and pixel_threshold attributes");
    else {
      const auto it = median_reference.find(key_of(p.reference_size));
      if (it == median_reference.end())
        reference.skip(p.path + ": fewer than " + std::to_string(kMinReferencesForMedian) + " references of its size to compare with");
      else {
        const double score = capture::contact_score(p.reference_scoring, it->second, float(*p.pixel_threshold));
        worst_reference = std::max(worst_reference, score / *p.trigger);
        if (score > *p.trigger)
          reference.fail(p.path + "/reference", "scores " + number(score) + " against the median reference, above the press's "
                                                "contact trigger " + number(*p.trigger) + ": it shows contact");
        else reference.pass();
      }
    }
    // Peak score, recomputed from the stored frames.
    if (!p.peak_score) peak_score.skip(p.path + ": no readable reference and peak of one size, or no pixel_threshold");
    else if (!thresholds) peak_score.skip(p.path + ": no positive trigger attribute");
    else {
      worst_peak = std::min(worst_peak, *p.peak_score / *p.trigger);
      if (*p.peak_score < kPeakOverTrigger * *p.trigger)
        peak_score.fail(p.path + "/peak", "scores " + number(*p.peak_score) + " against the reference, under " +
                                              number(kPeakOverTrigger) + " x the contact trigger " + number(*p.trigger));
      else peak_score.pass();
    }
    // Saturation and blur of the peak and its frames.
    if (p.images.empty()) {
      saturation.skip(p.path + ": no readable peak or frames");
      blur.skip(p.path + ": no readable peak or frames");
    }
    for (const auto& image : p.images) {
      worst_saturation = std::max(worst_saturation, image.saturated);
      if (image.saturated > kSaturatedMaxShare)
        saturation.fail(image.where, number(100 * image.saturated) + "% of the pixels saturated (at most " +
                                         number(100 * kSaturatedMaxShare) + "%)");
      else saturation.pass();
      const auto baseline = median_sharpness.find(key_of(image.size));
      if (baseline == median_sharpness.end() || baseline->second <= 0) {
        blur.skip(image.where + ": no textured reference of its size");
        continue;
      }
      worst_blur = std::min(worst_blur, image.sharpness / baseline->second);
      if (image.sharpness < kBlurMinRatio * baseline->second)
        blur.fail(image.where, "variance of the Laplacian " + number(image.sharpness) + ", under " + number(kBlurMinRatio) +
                                   " x the no-contact references' " + number(baseline->second) + ": blurred");
      else blur.pass();
    }
  }
  reference.set_pass_message("scores at most " + number(worst_reference) + " x their contact trigger");
  peak_score.set_pass_message("peaks score at least " + number(worst_peak) + " x their contact trigger");
  saturation.set_pass_message("at most " + number(100 * worst_saturation) + "% of a frame's pixels saturated");
  blur.set_pass_message("Laplacian variance at least " + number(worst_blur) + " x the references'");
  return {reference.result(), peak_score.result(), saturation.result(), blur.result(), resolution.result(),
          press_count.result(), damage.result()};
}

}  // namespace haptex::qa
