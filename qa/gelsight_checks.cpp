// gelsight.*: the no-contact reference, the peak's contact score, saturation, blur, image size and
// press count of every press (/materials/{material}/presses/{j}) of a gelsight or dataset file.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "capture/contact_score.hpp"
#include "capture/image_datasets.hpp"
#include "capture/scoring_image.hpp"
#include "core/error.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {
namespace {

std::string number(double value, int precision = 3) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

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

struct Press {
  std::string path, material;
  std::optional<cv::Mat> reference, peak;
  std::vector<cv::Mat> frames;
  std::optional<double> trigger, pixel_threshold;
};

bool same_sizes(const Press& p, cv::Size& size) {
  std::vector<cv::Size> sizes;
  if (p.reference) sizes.push_back(p.reference->size());
  if (p.peak) sizes.push_back(p.peak->size());
  if (!p.frames.empty()) sizes.push_back(p.frames.front().size());
  if (sizes.empty()) return false;
  size = sizes.front();
  return std::all_of(sizes.begin(), sizes.end(), [&](cv::Size s) { return s == size; });
}

// Per-pixel median of scoring images of one size.
cv::Mat median_image(const std::vector<cv::Mat>& images) {
  cv::Mat out(images.front().size(), CV_32F);
  std::vector<float> values(images.size());
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      for (std::size_t i = 0; i < images.size(); ++i) values[i] = images[i].at<float>(y, x);
      std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
      out.at<float>(y, x) = values[values.size() / 2];
    }
  return out;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

std::vector<CheckResult> check_gelsight(const h5::Group& root) {
  CheckTally reference("gelsight.reference", "references"), peak_score("gelsight.peak_score", "presses"),
      saturation("gelsight.saturation", "frames"), blur("gelsight.blur", "frames"),
      resolution("gelsight.resolution", "materials"), press_count("gelsight.press_count", "materials");

  std::vector<Press> presses;
  std::map<std::string, std::size_t> per_material;  // presses per material id, in file order
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
        const h5::Group g = group.open_group(j);
        Press p{"/materials/" + id + "/presses/" + j, id, read_single(g, "reference"), read_single(g, "peak"),
                read_stack(g, "frames"), number_attr(g, "trigger"), number_attr(g, "pixel_threshold")};
        presses.push_back(std::move(p));
        ++per_material[id];
      }
    }
  }

  // Press count and resolution, per material.
  for (const auto& [id, count] : per_material) {
    if (count < kPressesPerMaterial)
      press_count.fail("/materials/" + id + "/presses", std::to_string(count) + " presses, at least " +
                                                            std::to_string(kPressesPerMaterial) + " needed (3 train, 1 val, 1 test)");
    else press_count.pass();
    std::map<std::string, std::vector<std::string>> by_size;  // "WxH" -> presses
    bool mixed_inside = false;
    std::string mixed_where;
    for (const auto& p : presses) {
      if (p.material != id) continue;
      cv::Size size;
      if (!same_sizes(p, size)) {
        if (size.width > 0 && !mixed_inside) mixed_inside = true, mixed_where = p.path;
        if (size.width == 0) continue;
      }
      by_size[size_text(size)].push_back(p.path);
    }
    if (mixed_inside) resolution.fail(mixed_where, "reference, peak and frames differ in size");
    else if (by_size.size() > 1) {
      std::string sizes;
      for (const auto& [s, paths] : by_size) sizes += (sizes.empty() ? "" : ", ") + s + " (" + std::to_string(paths.size()) + ")";
      resolution.fail("/materials/" + id + "/presses", "presses of several sizes: " + sizes);
    } else if (by_size.empty()) resolution.skip("/materials/" + id + ": no readable press images");
    else resolution.pass();
  }

  // Baselines per image size: the median no-contact reference and its Laplacian variance.
  std::map<std::pair<int, int>, std::vector<cv::Mat>> references;
  std::map<std::pair<int, int>, std::vector<double>> reference_sharpness;
  for (const auto& p : presses)
    if (p.reference) {
      const std::pair key{p.reference->cols, p.reference->rows};
      references[key].push_back(capture::scoring_image(*p.reference));
      reference_sharpness[key].push_back(laplacian_variance(*p.reference));
    }
  std::map<std::pair<int, int>, cv::Mat> median_reference;
  for (const auto& [key, images] : references)
    if (images.size() >= kMinReferencesForMedian) median_reference[key] = median_image(images);

  double worst_reference = 0, worst_peak = INFINITY, worst_saturation = 0, worst_blur = INFINITY;
  for (const auto& p : presses) {
    const bool thresholds = p.trigger && p.pixel_threshold;
    // Reference: no contact against the median reference of its size.
    if (!p.reference) reference.skip(p.path + ": no readable reference");
    else if (!thresholds) reference.skip(p.path + ": no trigger/pixel_threshold attributes");
    else {
      const auto it = median_reference.find({p.reference->cols, p.reference->rows});
      if (it == median_reference.end())
        reference.skip(p.path + ": fewer than " + std::to_string(kMinReferencesForMedian) + " references of its size to compare with");
      else {
        const double score = capture::contact_score(capture::scoring_image(*p.reference), it->second, float(*p.pixel_threshold));
        worst_reference = std::max(worst_reference, score / *p.trigger);
        if (score > *p.trigger)
          reference.fail(p.path + "/reference", "scores " + number(score) + " against the median reference, above the press's "
                                                "contact trigger " + number(*p.trigger) + ": it shows contact");
        else reference.pass();
      }
    }
    // Peak score, recomputed from the stored frames.
    if (!p.reference || !p.peak) peak_score.skip(p.path + ": no readable reference or peak");
    else if (!thresholds) peak_score.skip(p.path + ": no trigger/pixel_threshold attributes");
    else if (p.reference->size() != p.peak->size()) peak_score.skip(p.path + ": reference and peak differ in size");
    else {
      const double score = capture::contact_score(capture::scoring_image(*p.peak), capture::scoring_image(*p.reference),
                                                  float(*p.pixel_threshold));
      worst_peak = std::min(worst_peak, score / *p.trigger);
      if (score < kPeakOverTrigger * *p.trigger)
        peak_score.fail(p.path + "/peak", "scores " + number(score) + " against the reference, under " +
                                              number(kPeakOverTrigger) + " x the contact trigger " + number(*p.trigger));
      else peak_score.pass();
    }
    // Saturation and blur of the peak and its frames.
    std::vector<std::pair<std::string, const cv::Mat*>> images;
    if (p.peak) images.emplace_back(p.path + "/peak", &*p.peak);
    for (std::size_t i = 0; i < p.frames.size(); ++i)
      images.emplace_back(p.path + "/frames[" + std::to_string(i) + "]", &p.frames[i]);
    if (images.empty()) {
      saturation.skip(p.path + ": no readable peak or frames");
      blur.skip(p.path + ": no readable peak or frames");
    }
    for (const auto& [where, image] : images) {
      const double share = saturated_share(*image);
      worst_saturation = std::max(worst_saturation, share);
      if (share > kSaturatedMaxShare)
        saturation.fail(where, number(100 * share) + "% of the pixels saturated (at most " + number(100 * kSaturatedMaxShare) + "%)");
      else saturation.pass();
      const auto sharp = reference_sharpness.find({image->cols, image->rows});
      if (sharp == reference_sharpness.end()) {
        blur.skip(where + ": no reference of its size");
        continue;
      }
      const double baseline = median(sharp->second), v = laplacian_variance(*image);
      worst_blur = std::min(worst_blur, v / baseline);
      if (v < kBlurMinRatio * baseline)
        blur.fail(where, "variance of the Laplacian " + number(v) + ", under " + number(kBlurMinRatio) +
                             " x the no-contact references' " + number(baseline) + ": blurred");
      else blur.pass();
    }
  }
  reference.set_pass_message("scores at most " + number(worst_reference) + " x their contact trigger");
  peak_score.set_pass_message("peaks score at least " + number(worst_peak) + " x their contact trigger");
  saturation.set_pass_message("at most " + number(100 * worst_saturation) + "% of a frame's pixels saturated");
  blur.set_pass_message("Laplacian variance at least " + number(worst_blur) + " x the references'");
  return {reference.result(), peak_score.result(), saturation.result(), blur.result(), resolution.result(),
          press_count.result()};
}

}  // namespace haptex::qa
