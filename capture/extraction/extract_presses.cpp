#include "capture/extraction/extract_presses.hpp"

#include <filesystem>
#include <fstream>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "capture/extraction/capture_inputs.hpp"
#include "capture/extraction/contact_sheet.hpp"
#include "capture/extraction/gelsight_writer.hpp"
#include "capture/scoring/contact_score.hpp"
#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/partial_directory.hpp"
#include "core/sha256.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

// One contact sheet into the sheets folder being built.
void write_sheet(const PartialDirectory& sheets, const std::string& name, const std::vector<std::uint8_t>& png) {
  std::ofstream out(fs::path(sheets.path()) / name, std::ios::binary);
  out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  if (!out) throw failure(sheets.path() + "/" + name + ": cannot write the contact sheet");
}

cv::Mat load_reference(const std::string& path) {
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty())
    throw input_error(path, "", "cannot read the reference image", "Give a PNG or JPEG no-contact frame of the sensor");
  return image;
}

// Three significant digits: thresholds and scores as a person reads them.
std::string figure(double v) { return text::format("%.3g", v); }

SourceDetection detection_of(const std::string& path, const SourceScores& scores, int presses) {
  const ContactReference& c = *scores.contact;
  SourceDetection d{path, scores.reference_note, presses, c.noise(), c.pixel_threshold(), c.level(), c.trigger(), c.release()};
  for (std::size_t i = 0; i < scores.scores.size(); ++i)
    if (std::isfinite(scores.scores[i]) && (d.highest_frame < 0 || scores.scores[i] > d.highest_score)) {
      d.highest_score = scores.scores[i];
      d.highest_frame = std::int64_t(i);
    }
  return d;
}

std::string relative_to_output(const std::string& file, const std::string& output) {
  const fs::path base = fs::absolute(output).parent_path();
  return fs::absolute(file).lexically_relative(base).string();
}

class Extraction {
 public:
  Extraction(const std::string& output, const ExtractOptions& options)
      : output_(output), options_(options), settings_(options.settings), writer_(output, options.overwrite, options.provenance) {
    if (options.reference_path) {
      settings_.reference_image = load_reference(*options.reference_path);
      settings_.reference_image_path = *options.reference_path;
    }
    if (options.sheets)
      sheets_ = std::make_unique<PartialDirectory>(options.sheets_dir.empty() ? default_sheets_dir(output) : options.sheets_dir,
                                                   FolderOptions{options.overwrite, "contact sheet folder", "--sheets", "haptex capture extract"});
  }

  void add(const CaptureInput& input) {
    const auto source = input.kind == CaptureInput::Kind::press_file       ? open_press_file(input.path)
                        : input.kind == CaptureInput::Kind::image_sequence ? open_image_sequence(input.path)
                                                                           : open_video(input.path);
    const std::string material = input.material.empty() ? source->material() : input.material;
    text::require_utf8(material, input.path, "the material name (--material, the folder's name or the press file's)");
    const SourceScores scores = score_source(*source, settings_);
    result_.frames_scored += std::int64_t(scores.scores.size());
    result_.frames_unreadable += scores.unreadable_frames + source->frames_missing();
    const SegmenterSettings segmenter = scores.contact->segmenter(settings_.segmenter);
    const auto plans = plan_presses(scores.scores, segmenter, settings_.frames_per_press, settings_.margin_frames);
    if (plans.empty()) result_.sources_without_press.push_back(input.path);
    result_.detections.push_back(detection_of(input.path, scores, int(plans.size())));
    const std::string sha = plans.empty() ? "" : source->sha256();
    read_press_frames(*source, plans, [&](const PressPlan& plan, std::vector<cv::Mat> frames, const cv::Mat& peak) {
      write_press(material, *source, scores, sha, plan, std::move(frames), peak);
    });
  }

  ExtractResult finish() {
    if (result_.presses.empty()) throw NoPressFound(no_press_message(), result_);
    writer_.commit();
    if (sheets_) {
      sheets_->commit();
      result_.sheets_dir = sheets_->final_path();
    }
    return result_;
  }

  void count_source() { ++result_.sources; }

 private:
  std::string no_press_message() const {
    std::string m = "no press found in " + std::to_string(result_.sources) + " input(s); nothing was written.";
    constexpr std::size_t kShown = 5;
    for (std::size_t i = 0; i < std::min(kShown, result_.detections.size()); ++i)
      m += "\n  " + result_.detections[i].source + ": " + describe(result_.detections[i]);
    if (result_.detections.size() > kShown) m += "\n  ... and " + std::to_string(result_.detections.size() - kShown) + " more";
    return m + "\nIf the sensor was pressed, give a lower --trigger (above the no-contact level), or a no-contact "
               "image with --reference";
  }

  void write_press(const std::string& material, const FrameSource& source, const SourceScores& scores,
                   const std::string& sha, const PressPlan& plan, std::vector<cv::Mat> frames, const cv::Mat& peak) {
    const ContactReference& contact = *scores.contact;
    GelsightPress p;
    p.source_file = source.path();
    p.source_sha256 = sha;
    p.press_in_source = plan.press_in_source;
    p.frame_start = plan.range_first;
    p.frame_end = plan.range_last;
    p.contact_first = plan.contact.first;
    p.contact_last = plan.contact.last;
    p.peak_index = plan.contact.peak;
    p.peak_score = plan.contact.peak_score;
    p.frame_indices = plan.frame_indices;
    p.frames = std::move(frames);
    p.peak = peak;
    p.reference = scores.reference;
    p.contrast.assign(scores.scores.begin() + plan.range_first, scores.scores.begin() + plan.range_last + 1);
    p.fps = source.fps();
    p.reference_note = scores.reference_note;
    p.noise = contact.noise();
    p.pixel_threshold = contact.pixel_threshold();
    p.level = contact.level();
    p.trigger = contact.trigger();
    p.release = contact.release();
    p.source_frames_unreadable = scores.unreadable_frames + source.frames_missing();
    const std::string id = material_id(material);
    std::string sheet_name;
    if (sheets_) {
      sheet_name = id + "_press_" + std::to_string(next_press_number(id)) + ".png";
      p.contact_sheet = relative_to_output((fs::path(sheets_->final_path()) / sheet_name).string(), output_);
    }
    const int j = writer_.add_press(material, p);
    if (sheets_) write_sheet(*sheets_, sheet_name, contact_sheet_png(sheet_input(material, j, source, scores, plan, peak, result_.detections.back())));
    result_.presses.push_back({material, id, source.path(), j, plan.press_in_source, p.frame_start, p.frame_end,
                               p.contact_first, p.contact_last, p.peak_index, p.peak_score, p.contact_sheet});
  }

  int next_press_number(const std::string& id) const {
    int n = 0;
    for (const auto& p : result_.presses) n += p.material_id == id;
    return n;
  }

  static ContactSheetInput sheet_input(const std::string& material, int j, const FrameSource& source,
                                       const SourceScores& scores, const PressPlan& plan, const cv::Mat& peak,
                                       const SourceDetection& detection) {
    ContactSheetInput in;
    in.title = material + "  press " + std::to_string(j) + "  " + fs::path(source.path()).filename().string() +
               "  frames " + std::to_string(plan.range_first) + "-" + std::to_string(plan.range_last) + ", contact " +
               std::to_string(plan.contact.first) + "-" + std::to_string(plan.contact.last);
    in.reference = scores.reference;
    in.peak = peak;
    in.scores = scores.scores;
    in.range_first = plan.range_first;
    in.range_last = plan.range_last;
    in.contact_first = plan.contact.first;
    in.contact_last = plan.contact.last;
    in.peak_index = plan.contact.peak;
    in.kept = plan.frame_indices;
    in.trigger = scores.contact->trigger();
    in.release = scores.contact->release();
    in.level = scores.contact->level();
    in.detection = "no-contact level " + figure(detection.level) + "  trigger " + figure(detection.trigger) + "  release " +
                   figure(detection.release) + "  pixel threshold " + figure(detection.pixel_threshold) + "  noise " +
                   figure(detection.noise);
    if (detection.level > 0) in.detection += "  signal-to-noise " + figure(detection.signal_to_noise());
    return in;
  }

  std::string output_;
  const ExtractOptions& options_;
  ExtractSettings settings_;
  GelsightWriter writer_;
  std::unique_ptr<PartialDirectory> sheets_;
  ExtractResult result_;
};

}  // namespace

float SourceDetection::signal_to_noise() const {
  return level > 0 ? highest_score / level : std::numeric_limits<float>::infinity();
}

std::string describe(const SourceDetection& d) {
  std::string s = d.highest_frame < 0 ? "no frame decoded" : "highest score " + figure(d.highest_score) + " (frame " +
                                                                 std::to_string(d.highest_frame) + ")";
  s += ", trigger " + figure(d.trigger) + " over a no-contact level of " + figure(d.level);
  if (d.level > 0) s += " (signal-to-noise " + figure(d.signal_to_noise()) + ", a press needs " + figure(d.trigger / d.level) + ")";
  return s + "; per-pixel threshold " + figure(d.pixel_threshold) + " grey levels, noise " + figure(d.noise);
}

std::string default_sheets_dir(const std::string& output) {
  fs::path p(output);
  return (p.parent_path() / (p.stem().string() + "_sheets")).string();
}

ExtractResult extract_presses(const std::vector<std::string>& inputs, const std::string& output,
                              const ExtractOptions& options, const Progress& progress) {
  require_reference_frames(options.settings.reference_frames);
  check_output_path(output, options.overwrite);
  const std::vector<CaptureInput> expanded = expand_capture_inputs(inputs, options.material);
  Extraction extraction(output, options);
  for (std::size_t i = 0; i < expanded.size(); ++i) {
    if (progress) progress(i, expanded.size(), expanded[i].path);
    extraction.add(expanded[i]);
    extraction.count_source();
  }
  if (progress) progress(expanded.size(), expanded.size(), "");
  return extraction.finish();
}

}  // namespace haptex::capture
