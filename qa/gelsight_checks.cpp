// gelsight.*: the no-contact reference, the peak's contact score, saturation, blur, image size,
// press count, source damage, channel order and whole images of every press of a gelsight or dataset file.
#include "qa/gelsight_checks.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "capture/scoring/contact_score.hpp"
#include "core/error.hpp"
#include "core/h5/structure_probe.hpp"
#include "core/sha256.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/press_images.hpp"
#include "dataset/vlen_bytes.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {
namespace {

std::string size_text(cv::Size s) { return std::to_string(s.width) + "x" + std::to_string(s.height); }

ImageSize key_of(cv::Size s) { return {s.width, s.height}; }

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
  if (!mixed_inside.empty()) return tally.fail(mixed_inside, "reference, peak, frames and the press's width and height differ in size");
  if (by_size.empty()) return tally.skip(dataset::material_path(id) + ": no readable press images");
  if (by_size.size() == 1) return tally.pass();
  std::string sizes;
  for (const auto& [s, n] : by_size) sizes += (sizes.empty() ? "" : ", ") + s + " (" + std::to_string(n) + ")";
  tally.fail(dataset::presses_path(id), "presses of several sizes: " + sizes);
}

}  // namespace

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
    if (baseline == baselines.sharpness.end()) return tally.skip(image.where + ": no reference of its size");
    if (baseline->second < kBlurMinReferenceSharpness)
      return tally.skip(image.where + ": the references of its size are too smooth to judge focus against (Laplacian variance " +
                        number(baseline->second) + ", under " + number(kBlurMinReferenceSharpness) + ")");
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
      tally.fail(dataset::presses_path(id), std::to_string(count) + " presses, at least " +
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

namespace {

// One check judging each press of the file alone: `problem_of` says what is wrong with it ("" when nothing).
CheckResult per_press(const h5::Group& root, std::string_view id, const std::function<std::string(const h5::Group&)>& problem_of) {
  CheckTally tally(id, "presses");
  for (const std::string& path : press_paths(root)) {
    const std::string problem = problem_of(root.open_group(path.substr(1)));
    if (problem.empty()) tally.pass();
    else tally.fail(path, problem);
  }
  return tally.result();
}

// The message of the first haptex::Error `step` throws for one of a press's image datasets.
std::string first_image_error(const h5::Group& press, const std::function<void(const char* name)>& step) {
  for (const char* name : {dataset::layout::kReference, dataset::layout::kPeak, dataset::layout::kFrames}) {
    if (!press.has_dataset(name)) continue;  // a missing dataset is layout.required's
    try {
      step(name);
    } catch (const Error& e) {
      return e.what();
    }
  }
  return "";
}

}  // namespace

namespace {

// The SHA-256 of a press's stored peak image, "" when it cannot be read (gelsight.images says why).
std::string peak_bytes_sha(const h5::Group& press) {
  try {
    const std::vector<std::uint8_t> bytes = dataset::read_vlen_bytes(press.open_dataset(dataset::layout::kPeak), 0);
    return sha256_hex(std::span(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  } catch (const Error&) {
    return "";
  }
}

}  // namespace

CheckResult check_gelsight_duplicate(const h5::Group& root) {
  CheckTally tally("gelsight.duplicate", "presses");
  std::map<std::pair<std::string, std::int64_t>, std::string> first;  // (source SHA-256, press in it) -> press path
  std::map<std::string, std::string> first_peak;                      // peak image's SHA-256 -> press path
  for (const std::string& path : press_paths(root)) {
    const h5::Group press = root.open_group(path.substr(1));
    const auto sha = press.try_attr<std::string>(dataset::layout::kSourceSha256);
    const auto number = press.try_attr<std::int64_t>(dataset::layout::kPressInSource);
    // Review 8: a copy of a video with other bytes (4 bytes appended, remuxed) has another SHA-256 but
    // the same frames; no two presses of a sensor give one peak image byte for byte (its noise differs).
    const std::string peak = peak_bytes_sha(press);
    if (!sha || sha->empty() || !number) {
      tally.skip(path + ": no source_sha256 or press_in_source to compare");
      continue;
    }
    const auto [at, added] = first.emplace(std::make_pair(*sha, *number), path);
    const auto [same_peak, new_peak] = peak.empty() ? std::make_pair(first_peak.end(), true) : first_peak.emplace(peak, path);
    if (!added)
      tally.fail(path, "is press " + std::to_string(*number) + " of the same source file (SHA-256 " + sha->substr(0, 12) + "...) as " + at->second);
    else if (!new_peak)
      tally.fail(path, "has the peak image of " + same_peak->second + " byte for byte: the same footage twice (a copy of its video)");
    else
      tally.pass();
  }
  return tally.result();
}

CheckResult check_gelsight_channel_order(const h5::Group& root) {
  return per_press(root, "gelsight.channel_order", [](const h5::Group& press) {
    return first_image_error(press, [&](const char* name) { dataset::read_channel_order(press, name); });
  });
}

namespace {

// What is wrong with a press's frame numbers (schemas/hdf5-layout.md, "Frame numbers"): "" when they
// agree, or when one is missing or mistyped (layout.required and layout.dtype report those).
std::string frame_number_problem(const h5::Group& press) {
  namespace layout = dataset::layout;
  const auto start = press.try_attr<std::int64_t>(layout::kFrameStart), end = press.try_attr<std::int64_t>(layout::kFrameEnd),
             first = press.try_attr<std::int64_t>(layout::kContactFirst), last = press.try_attr<std::int64_t>(layout::kContactLast);
  if (!start || !end || !first || !last || !press.has_dataset(layout::kPeakIndex) || !press.has_dataset(layout::kFrameIndices) ||
      !press.has_dataset(layout::kContrast))
    return "";
  std::int64_t peak = 0;
  std::vector<std::int64_t> indices;
  std::size_t scores = 0;
  try {
    const std::vector<std::int64_t> peak_value = press.open_dataset(layout::kPeakIndex).read<std::int64_t>();
    if (peak_value.size() != 1) return "";
    peak = peak_value.front();
    indices = press.open_dataset(layout::kFrameIndices).read<std::int64_t>();
    scores = press.open_dataset(layout::kContrast).elements();
  } catch (const Error&) {
    return "";  // not integers, or not readable: the layout checks say which
  }
  const auto n = [](std::int64_t v) { return std::to_string(v); };
  if (!(0 <= *start && *start <= *first && *first <= peak && peak <= *last && *last <= *end))
    return "frame_start " + n(*start) + ", contact_first " + n(*first) + ", peak_index " + n(peak) + ", contact_last " + n(*last) +
           " and frame_end " + n(*end) + " are not in that order, from 0";
  if (std::uint64_t(*end - *start) + 1 != scores)
    return "contrast holds " + std::to_string(scores) + " scores, but frames " + n(*start) + " to " + n(*end) + " are " +
           std::to_string(std::uint64_t(*end - *start) + 1);
  for (std::size_t i = 0; i < indices.size(); ++i)
    if (indices[i] < *start || indices[i] > *end || (i > 0 && indices[i] != indices[i - 1] + 1))
      return "frame_indices[" + std::to_string(i) + "] is " + n(indices[i]) + ": the frames are not consecutive within frames " +
             n(*start) + " to " + n(*end);
  if (indices.empty() || peak < indices.front() || peak > indices.back())
    return "peak_index " + n(peak) + " is not among frame_indices";
  return "";
}

}  // namespace

CheckResult check_gelsight_frame_numbers(const h5::Group& root) { return per_press(root, "gelsight.frame_numbers", frame_number_problem); }

CheckResult check_gelsight_images(const h5::Group& root) {
  return per_press(root, "gelsight.images", [](const h5::Group& press) {
    return first_image_error(press, [&](const char* name) { dataset::require_whole_press_images(press, name); });
  });
}

std::vector<CheckResult> check_gelsight(const h5::Group& root) {
  // Every image is read below, and a press's finding is its own: damage HDF5 cannot read safely is the
  // file's refusal (core/h5/structure_probe.hpp), made before the first.
  h5::probe_values(root.id(), root.file());
  const GelsightPresses file = read_presses(root);
  const NoContactBaselines baselines = no_contact_baselines(file.presses);
  return {check_gelsight_reference(file.presses, baselines),
          check_gelsight_peak_score(file.presses),
          check_gelsight_saturation(file.presses),
          check_gelsight_blur(file.presses, baselines),
          check_gelsight_resolution(file),
          check_gelsight_press_count(file.per_material),
          check_gelsight_source_damage(file.presses),
          check_gelsight_duplicate(root),
          check_gelsight_channel_order(root),
          check_gelsight_frame_numbers(root),
          check_gelsight_images(root)};
}

}  // namespace haptex::qa