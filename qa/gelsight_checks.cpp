// gelsight.*: the no-contact reference, the peak's contact score, saturation, blur, image size,
// press count and source damage of every press of a gelsight or dataset file.
#include "qa/gelsight_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include <opencv2/imgproc.hpp>

#include "capture/contact_score.hpp"
#include "capture/image_datasets.hpp"
#include "capture/scoring_image.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {
namespace {

std::string size_text(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

ImageSize key_of(cv::Size s) { return {s.width, s.height}; }

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

// layout.* reports a missing or mistyped attribute; source_damage skips the press then.
void read_source_frames_unreadable(const h5::Group& g, Press& p) {
  try {
    if (!g.has_attr("source_frames_unreadable")) {
      p.source_frames_problem = p.path + ": no source_frames_unreadable attribute";
      return;
    }
    p.source_frames_unreadable = g.attr_int("source_frames_unreadable");
  } catch (const Error&) {
    p.source_frames_problem = p.path + "/@source_frames_unreadable is not an integer";
  }
}

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
  read_source_frames_unreadable(g, p);
  return p;
}

cv::Size press_size(const Press& p) {
  return p.has_reference ? p.reference_size : p.has_peak ? p.peak_size : p.frames_size;
}

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

// The reference and peak checks scale their thresholds by the press's own trigger.
bool has_thresholds(const Press& p) { return p.trigger && p.pixel_threshold && *p.trigger > 0; }

// The peak and every frame of each press through `judge`; a press with neither is skipped.
void for_each_image(const std::vector<Press>& presses, CheckTally& tally,
                    const std::function<void(const Press::Image&)>& judge) {
  for (const auto& p : presses) {
    if (p.images.empty()) tally.skip(p.path + ": no readable peak or frames");
    for (const auto& image : p.images) judge(image);
  }
}

// gelsight.resolution for one material.
void judge_resolution(const std::vector<Press>& presses, const std::string& id, CheckTally& tally) {
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
  if (!mixed_inside.empty()) return tally.fail(mixed_inside, "reference, peak and frames differ in size");
  if (by_size.empty()) return tally.skip("/materials/" + id + ": no readable press images");
  if (by_size.size() == 1) return tally.pass();
  std::string sizes;
  for (const auto& [s, n] : by_size) sizes += (sizes.empty() ? "" : ", ") + s + " (" + std::to_string(n) + ")";
  tally.fail("/materials/" + id + "/presses", "presses of several sizes: " + sizes);
}

}  // namespace

GelsightPresses read_presses(const h5::Group& root) {
  GelsightPresses file;
  if (!root.has_group("materials")) return file;
  const h5::Group materials = root.open_group("materials");
  for (const auto& id : materials.children()) {
    if (!materials.has_group(id)) continue;
    const h5::Group material = materials.open_group(id);
    std::size_t& count = file.per_material[id];
    if (!material.has_group("presses")) continue;
    const h5::Group group = material.open_group("presses");
    for (const auto& j : group.children()) {
      if (!group.has_group(j)) continue;
      file.presses.push_back(summarize_press(group.open_group(j), "/materials/" + id + "/presses/" + j, id));
      ++count;
    }
  }
  return file;
}

NoContactBaselines no_contact_baselines(const std::vector<Press>& presses) {
  std::map<ImageSize, std::vector<const cv::Mat*>> references;
  std::map<ImageSize, std::vector<double>> sharpness;
  for (const auto& p : presses)
    if (p.has_reference) {
      references[key_of(p.reference_size)].push_back(&p.reference_scoring);
      sharpness[key_of(p.reference_size)].push_back(p.reference_sharpness);
    }
  NoContactBaselines baselines;
  for (const auto& [size, images] : references)
    if (images.size() >= kMinReferencesForMedian) baselines.reference[size] = median_image(images);
  for (const auto& [size, values] : sharpness) baselines.sharpness[size] = median(values);
  return baselines;
}

// No contact: the reference scored against the median reference of its size.
CheckResult check_gelsight_reference(const std::vector<Press>& presses, const NoContactBaselines& baselines) {
  CheckTally tally("gelsight.reference", "references");
  double worst = 0;
  for (const auto& p : presses) {
    if (!p.has_reference) {
      tally.skip(p.path + ": no readable reference");
      continue;
    }
    if (!has_thresholds(p)) {
      tally.skip(p.path + ": no positive trigger and pixel_threshold attributes");
      continue;
    }
    const auto median_reference = baselines.reference.find(key_of(p.reference_size));
    if (median_reference == baselines.reference.end()) {
      tally.skip(p.path + ": fewer than " + std::to_string(kMinReferencesForMedian) + " references of its size to compare with");
      continue;
    }
    const double score = capture::contact_score(p.reference_scoring, median_reference->second, float(*p.pixel_threshold));
    worst = std::max(worst, score / *p.trigger);
    if (score > *p.trigger)
      tally.fail(p.path + "/reference", "scores " + number(score) + " against the median reference, above the press's "
                                        "contact trigger " + number(*p.trigger) + ": it shows contact");
    else tally.pass();
  }
  tally.set_pass_message("scores at most " + number(worst) + " x their contact trigger");
  return tally.result();
}

CheckResult check_gelsight_peak_score(const std::vector<Press>& presses) {
  CheckTally tally("gelsight.peak_score", "presses");
  double worst = INFINITY;
  for (const auto& p : presses) {
    if (!p.peak_score) tally.skip(p.path + ": no readable reference and peak of one size, or no pixel_threshold");
    else if (!has_thresholds(p)) tally.skip(p.path + ": no positive trigger attribute");
    else {
      worst = std::min(worst, *p.peak_score / *p.trigger);
      if (*p.peak_score < kPeakOverTrigger * *p.trigger)
        tally.fail(p.path + "/peak", "scores " + number(*p.peak_score) + " against the reference, under " +
                                         number(kPeakOverTrigger) + " x the contact trigger " + number(*p.trigger));
      else tally.pass();
    }
  }
  tally.set_pass_message("peaks score at least " + number(worst) + " x their contact trigger");
  return tally.result();
}

CheckResult check_gelsight_saturation(const std::vector<Press>& presses) {
  CheckTally tally("gelsight.saturation", "frames");
  double worst = 0;
  for_each_image(presses, tally, [&](const Press::Image& image) {
    worst = std::max(worst, image.saturated);
    if (image.saturated > kSaturatedMaxShare)
      tally.fail(image.where, number(100 * image.saturated) + "% of the pixels saturated (at most " +
                                  number(100 * kSaturatedMaxShare) + "%)");
    else tally.pass();
  });
  tally.set_pass_message("at most " + number(100 * worst) + "% of a frame's pixels saturated");
  return tally.result();
}

// Against the no-contact references of the same size: contact only adds edges.
CheckResult check_gelsight_blur(const std::vector<Press>& presses, const NoContactBaselines& baselines) {
  CheckTally tally("gelsight.blur", "frames");
  double worst = INFINITY;
  for_each_image(presses, tally, [&](const Press::Image& image) {
    const auto baseline = baselines.sharpness.find(key_of(image.size));
    if (baseline == baselines.sharpness.end() || baseline->second <= 0)
      return tally.skip(image.where + ": no textured reference of its size");
    worst = std::min(worst, image.sharpness / baseline->second);
    if (image.sharpness < kBlurMinRatio * baseline->second)
      tally.fail(image.where, "variance of the Laplacian " + number(image.sharpness) + ", under " + number(kBlurMinRatio) +
                                  " x the no-contact references' " + number(baseline->second) + ": blurred");
    else tally.pass();
  });
  tally.set_pass_message("Laplacian variance at least " + number(worst) + " x the references'");
  return tally.result();
}

CheckResult check_gelsight_resolution(const GelsightPresses& file) {
  CheckTally tally("gelsight.resolution", "materials");
  for (const auto& material : file.per_material) judge_resolution(file.presses, material.first, tally);
  return tally.result();
}

CheckResult check_gelsight_press_count(const std::map<std::string, std::size_t>& per_material) {
  CheckTally tally("gelsight.press_count", "materials");
  for (const auto& [id, count] : per_material)
    if (count < kPressesPerMaterial)
      tally.fail("/materials/" + id + "/presses", std::to_string(count) + " presses, at least " +
                                                      std::to_string(kPressesPerMaterial) + " needed (3 train, 1 val, 1 test)");
    else tally.pass();
  return tally.result();
}

CheckResult check_gelsight_source_damage(const std::vector<Press>& presses) {
  CheckTally tally("gelsight.source_damage", "presses");
  for (const auto& p : presses)
    if (!p.source_frames_problem.empty()) tally.skip(p.source_frames_problem);
    else if (p.source_frames_unreadable > 0)
      tally.fail(p.path, "its source had " + std::to_string(p.source_frames_unreadable) +
                             " frames that did not decode or never arrived (none is kept)");
    else tally.pass();
  return tally.result();
}

std::vector<CheckResult> check_gelsight(const h5::Group& root) {
  const GelsightPresses file = read_presses(root);
  const NoContactBaselines baselines = no_contact_baselines(file.presses);
  return {check_gelsight_reference(file.presses, baselines),
          check_gelsight_peak_score(file.presses),
          check_gelsight_saturation(file.presses),
          check_gelsight_blur(file.presses, baselines),
          check_gelsight_resolution(file),
          check_gelsight_press_count(file.per_material),
          check_gelsight_source_damage(file.presses)};
}

}  // namespace haptex::qa
