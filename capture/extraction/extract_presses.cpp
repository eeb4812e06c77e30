#include "capture/extraction/extract_presses.hpp"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include <opencv2/imgproc.hpp>

#include "capture/extraction/capture_inputs.hpp"
#include "capture/extraction/contact_sheet.hpp"
#include "capture/extraction/gel_image.hpp"
#include "dataset/gelsight_file.hpp"
#include "capture/extraction/score_chart.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/storage/video_file.hpp"
#include "core/durable_file.hpp"
#include "core/output_is_input.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/naming.hpp"
#include "core/parallel.hpp"
#include "core/partial_directory.hpp"
#include "core/sha256.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "core/output_set.hpp"
#include "core/owned_folder.hpp"
#include "dataset/decode_image.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

constexpr const char* kExtractCommand = "haptex capture extract";

// Folders an earlier extraction wrote, which --force retires with the file they describe.
bool extraction_folder(const std::string& dir) { return is_haptex_folder(dir, kExtractCommand); }

// The contact sheets an earlier gelsight file at `output` names, by folder: each sheet's file name and
// its SHA-256 as written. Empty when there is no such file or it cannot be read.
using RecordedSheets = std::map<std::string, std::map<std::string, std::string>>;

RecordedSheets recorded_sheets(const std::string& output) {
  RecordedSheets recorded;
  try {
    std::error_code ec;
    if (!fs::is_regular_file(output, ec)) return recorded;
    const h5::Group materials = h5::File::open(output).root().open_group(dataset::layout::kMaterials);
    for (const std::string& material : materials.children()) {
      const h5::Group presses = materials.open_group(material).open_group(dataset::layout::kPresses);
      for (const std::string& j : presses.children()) {
        const h5::Group press = presses.open_group(j);
        const auto sheet = press.try_attr<std::string>(dataset::layout::kContactSheet);
        const auto sha256 = press.try_attr<std::string>(dataset::layout::kContactSheetSha256);
        if (!sheet || !sha256) continue;
        const fs::path path = resolved_beside(*sheet, output);
        recorded[path.parent_path().string()][path.filename().string()] = *sha256;
      }
    }
  } catch (const Error&) {
    return {};
  }
  return recorded;
}

// Whether `folder` holds, beside its haptex-files.json, exactly the `sheets` an earlier extraction wrote
// there, each still the bytes it wrote (review 27, F2: `--sheets shx` was kept beside the file that
// replaced the one it described).
bool holds_just(const std::string& folder, const std::map<std::string, std::string>& sheets) {
  if (!extraction_folder(folder)) return false;
  std::size_t files = 0;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == kFileListName) continue;
    const auto recorded = sheets.find(name);
    if (recorded == sheets.end() || !entry.is_regular_file(ec) || sha256_file(entry.path().string()) != recorded->second) return false;
    ++files;
  }
  return !ec && files == sheets.size();
}

// A folder at a default name goes with the file --force replaces only while that file is there and the
// folder's list names it back (`owner`); contact sheets also only while they are the ones that file
// recorded (`recorded`, read from it before it is replaced). Review 33, F1: the folders of a file moved
// away, or of another file renamed into its place, went.
bool companion_of(const std::string& dir, const std::string& output, bool output_there) {
  return output_there && extraction_folder(dir) && same_output_path(folder_owner(dir), output);
}

bool sheets_of(const std::string& dir, const std::string& output, bool output_there, const RecordedSheets& recorded) {
  if (!companion_of(dir, output, output_there)) return false;
  for (const auto& [folder, sheets] : recorded)
    if (same_output_path(folder, dir)) return holds_just(dir, sheets);
  return false;
}


// One PNG (a contact sheet, a score chart) into a folder being built.
void write_png(const PartialDirectory& folder, const std::string& name, const std::vector<std::uint8_t>& png) {
  folder.fill([&](const std::string& dir) {
    write_whole_file((fs::path(dir) / name).string(), {reinterpret_cast<const char*>(png.data()), png.size()});
  });
}

// A source's chart name: its file's (or folder's) name as an id, ASCII and at most 100 characters, so
// any file name gives a valid one ("Cork take 1.avi" -> "cork_take_1_avi").
std::string chart_stem(const std::string& source) {
  fs::path p = fs::path(source).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  const std::string id = material_id(p.filename().string()).substr(0, 100);
  return id.empty() ? "source" : id;
}

// Three significant digits: thresholds and scores as a person reads them.
std::string figure(double v) { return text::format("%.3g", v); }

cv::Mat load_reference(const std::string& path) {
  cv::Mat image = dataset::read_image_file(path);
  if (image.empty())
    throw input_error(path, "", "cannot read the reference image", "Give a PNG or JPEG no-contact frame of the sensor");
  require_gel_image(image, path, "", "Give a no-contact frame of the sensor, as it recorded it, with its light on");
  return image;
}

SourceDetection detection_of(const std::string& path, const SourceScores& scores, int presses) {
  const ContactReference& c = *scores.contact;
  SourceDetection d{path,      scores.reference_note, reference_kind_name(scores.reference_kind), presses, c.noise(),
                    c.pixel_threshold(), c.level(), c.spread(), c.trigger(), c.release(), 0, -1, {}};
  for (std::size_t i = 0; i < scores.scores.size(); ++i)
    if (std::isfinite(scores.scores[i]) && (d.highest_frame < 0 || scores.scores[i] > d.highest_score)) {
      d.highest_score = scores.scores[i];
      d.highest_frame = std::int64_t(i);
    }
  return d;
}

// The source's scores, thresholds, reference frames and presses, for a chart.
ScoreChart chart_of(const SourceScores& scores, const std::vector<PressPlan>& plans, const SourceDetection& d) {
  ScoreChart c;
  c.scores = scores.scores;
  c.level = d.level, c.trigger = d.trigger, c.release = d.release;
  c.reference_first = scores.reference_first, c.reference_last = scores.reference_last;
  for (const auto& p : plans) c.presses.push_back({p.contact.first, p.contact.last, p.contact.peak});
  c.caption = "reference: " + std::string(reference_kind_name(scores.reference_kind)) + "  no-contact level " +
              figure(d.level) + "  jitter " + figure(d.jitter) + "  trigger " + figure(d.trigger) + "  release " +
              figure(d.release);
  if (d.jitter > 0) c.caption += "  signal-to-noise " + figure(d.signal_to_noise());
  return c;
}

// Whether this run writes contact sheets where an earlier run's default ones are (OUTPUT_sheets): with
// --force, sheets elsewhere or none leave those describing a file now replaced, so they go too (review 9, F6).
bool sheets_at_default_place(const std::string& output, const ExtractOptions& options) {
  return options.sheets && (options.sheets_dir.empty() ||
                            fs::path(options.sheets_dir).lexically_normal() == fs::path(default_sheets_dir(output)).lexically_normal());
}

class Extraction {
 public:
  Extraction(const std::string& output, const ExtractOptions& options, std::vector<std::string> inputs)
      : output_(output), options_(options), settings_(options.settings), writer_(output, options.overwrite, options.provenance),
        inputs_(std::move(inputs)) {
    if (options.reference_path) {
      settings_.reference_image = load_reference(*options.reference_path);
      settings_.reference_image_path = *options.reference_path;
    }
    if (options.sheets)
      sheets_ = std::make_unique<PartialDirectory>(options.sheets_dir.empty() ? default_sheets_dir(output) : options.sheets_dir,
                                                   FolderOptions{options.overwrite, "contact sheet folder", "--sheets", kExtractCommand});
    if (options.explain)
      explain_ = std::make_unique<PartialDirectory>(default_explain_dir(output),
                                                    FolderOptions{options.overwrite, "explain folder", "-o (the folder is named after it)",
                                                                  kExtractCommand});
    for (PartialDirectory* folder : {sheets_.get(), explain_.get()})
      if (folder) folder->belongs_to(output);
  }

  // One source opened, its frames scored and its presses planned: what write() reads the kept frames
  // of and stores. Touches nothing of the Extraction but its settings, so videos and image sequences
  // can be analysed on several threads.
  struct Analysed {
    const CaptureInput* input = nullptr;
    std::unique_ptr<FrameSource> source;
    std::string material, sha;
    SourceScores scores;
    std::vector<PressPlan> plans;
    int left_out = 0;  // presses with frames that do not decode around their peak
  };

  Analysed analyse(const CaptureInput& input) const {
    Analysed a;
    a.input = &input;
    a.source = input.kind == CaptureInput::Kind::press_file       ? open_press_file(input.path)
               : input.kind == CaptureInput::Kind::image_sequence ? open_image_sequence(input.path)
                                                                  : open_video(input.path);
    a.material = input.material.empty() ? a.source->material() : input.material;
    text::require_utf8(a.material, input.path, "the material name (--material, the folder's name or the press file's)");
    a.scores = score_source(*a.source, settings_);
    require_trigger_over_level(input.path, *a.scores.contact);
    require_a_decoded_frame(input.path, a.scores);
    a.plans = plan_presses(a.scores.scores, a.scores.contact->segmenter(settings_.segmenter), settings_.frames_per_press,
                           settings_.margin_frames, a.scores.end_level, &a.left_out);
    a.sha = a.plans.empty() ? "" : a.source->sha256();
    return a;
  }

  // Review 6: --trigger 0.3 under a level of 0.48 made every frame contact and wrote presses whose
  // peak lay outside their own contact, which qa, merge and align then refused as damaged.
  void require_trigger_over_level(const std::string& path, const ContactReference& contact) const {
    if (!settings_.trigger || contact.trigger() > contact.level()) return;
    throw input_error(path, "--trigger", figure(*settings_.trigger) + " is not above this source's no-contact level, " + figure(contact.level()) +
                                             ": its no-contact frames would count as contact",
                      "Give a --trigger above " + figure(contact.level()) + ", or leave it out (the footage sets one)");
  }

  // Review 5: a press file whose every JPEG stated 60000x60000 was "no press found" (exit 1, "give a
  // lower --trigger"); a source of which no frame decodes is damaged input.
  static void require_a_decoded_frame(const std::string& path, const SourceScores& scores) {
    if (scores.unreadable_frames == 0 || std::any_of(scores.scores.begin(), scores.scores.end(), [](float s) { return std::isfinite(s); }))
      return;
    throw input_error(path, "", "no frame of it decodes (" + std::to_string(scores.unreadable_frames) +
                                    " frames damaged, or of another size than the file states)",
                      "Copy the file again from the machine that recorded it");
  }

  // The kept frames are read and stored a press at a time, so memory holds about one press.
  void write(Analysed& a) {
    result_.frames_scored += std::int64_t(a.scores.scores.size());
    result_.frames_unreadable += a.scores.unreadable_frames + a.source->frames_missing();
    if (a.plans.empty()) result_.sources_without_press.push_back(a.input->path);
    result_.detections.push_back(detection_of(a.input->path, a.scores, int(a.plans.size())));
    result_.detections.back().presses_left_out = a.left_out;
    if (explain_) explain(a);
    if (!a.plans.empty()) require_new_source(a);
    read_press_frames(*a.source, a.plans, [&](const PressPlan& plan, PressFrames frames) {
      write_press(a.material, *a.source, a.scores, a.sha, plan, std::move(frames));
    });
    a.source.reset();
    ++result_.sources;
  }

  ExtractResult finish() {
    if (result_.presses.empty()) {
      // The charts say why no press was found, but not in place of the charts of an earlier file at -o,
      // which stays, and which they describe (review 22, F2).
      std::error_code ec;
      if (explain_ && !fs::exists(fs::symlink_status(output_, ec))) commit_explain();
      throw NoPressFound(no_press_message(), result_);
    }
    // The file and its folders appear together or not at all (a full disk while writing any of them, a
    // folder appearing at a folder's name). --force without sheets or --explain: folders an earlier
    // extraction wrote for the file replaced describe it, so they go too; anything else there stays.
    std::error_code ec;
    const bool output_there = fs::is_regular_file(output_, ec);
    const RecordedSheets earlier_record = recorded_sheets(output_);
    EarlierOutput earlier_sheets(default_sheets_dir(output_), [&](const std::string& dir) { return sheets_of(dir, output_, output_there, earlier_record); });
    EarlierOutput earlier_explain(default_explain_dir(output_), [&](const std::string& dir) { return companion_of(dir, output_, output_there); });
    const bool retire = options_.overwrite;
    std::vector<StagedOutput*> outputs{&writer_.output(), explain_.get(), sheets_.get(),
                                       retire && !sheets_at_default_place(output_, options_) ? &earlier_sheets : nullptr,
                                       !explain_ && retire ? &earlier_explain : nullptr};
    // Sheets the earlier file names under a name of their own (--sheets) go too, when the new run does
    // not write there, they are still those the earlier file names, and their haptex-files.json names
    // this file as theirs: not a copy's original, nor a merged file's shard (checked again as they go).
    std::vector<std::unique_ptr<EarlierOutput>> recorded;
    if (retire)
      for (const auto& [folder, sheets] : earlier_record) {
        if (same_output_path(folder, default_sheets_dir(output_)) || (sheets_ && same_output_path(folder, sheets_->final_path())) ||
            holds_an_input(folder))
          continue;
        recorded.push_back(std::make_unique<EarlierOutput>(folder, [this, sheets](const std::string& dir) {
          return holds_just(dir, sheets) && same_output_path(folder_owner(dir), output_);
        }));
        outputs.push_back(recorded.back().get());
      }
    commit_together(outputs);
    if (explain_) result_.explain_dir = explain_->final_path();
    if (sheets_) result_.sheets_dir = sheets_->final_path();
    return result_;
  }

 private:
  void commit_explain() {
    if (!explain_) return;
    explain_->commit();
    result_.explain_dir = explain_->final_path();
  }

  // One chart per source, named after the source (chart_stem; numbered _2, _3 ... when two sources give
  // the same name); its path goes into the source's detection.
  void explain(const Analysed& a) {
    const std::string stem = chart_stem(a.input->path);
    std::string name = stem + ".png";
    for (int k = 2; !explain_names_.insert(name).second; ++k) name = stem + "_" + std::to_string(k) + ".png";
    SourceDetection& d = result_.detections.back();
    d.chart = (fs::path(explain_->final_path()) / name).string();
    write_png(*explain_, name, score_chart_png(a.input->path + ": " + std::to_string(a.plans.size()) + " press(es)",
                                               chart_of(a.scores, a.plans, d)));
  }

  // Review 6: a video given twice (or once more through a linked folder, or copied) gave the same
  // presses twice, which split put in train and val; and folders "Woven 1" and "woven-1" (the second
  // holding sandpaper) were poured into one material. Both are refused, naming the two sources.
  void require_new_source(const Analysed& a) {
    const std::string& path = a.input->path;
    if (const auto [at, added] = source_by_sha_.emplace(a.sha, path); !added)
      throw input_error(path, "", "is the same file as " + at->second + " (SHA-256 " + a.sha.substr(0, 12) +
                                      "...): given twice, through a link, or copied, its presses would be taken twice and could land in "
                                      "both the training and the test set",
                        "Give each video once");
    const auto [at, added] = spelling_.emplace(material_id(a.material), std::make_pair(a.material, path));
    if (!added && at->second.first != a.material)
      throw input_error(path, "", "its material '" + text::printable(a.material) + "' and '" + text::printable(at->second.first) + "' (of " +
                                      text::printable(at->second.second) +
                                      ") make one material id, " + at->first,
                        "Name the two folders (or --material) alike if they hold one material, or with different letters or digits if not");
  }

  std::string no_press_message() const {
    std::string m = "no press found in " + std::to_string(result_.sources) + " input(s); no gelsight file was written.";
    constexpr std::size_t kShown = 5;
    for (std::size_t i = 0; i < std::min(kShown, result_.detections.size()); ++i)
      m += "\n  " + text::printable(result_.detections[i].source) + ": " + describe(result_.detections[i]);  // a newline in a name is its own
    if (result_.detections.size() > kShown) m += "\n  ... and " + std::to_string(result_.detections.size() - kShown) + " more";
    if (!result_.explain_dir.empty()) m += "\nEach source's score over time: " + text::printable(result_.explain_dir);
    else if (explain_)
      m += "\nThe score charts were not written: " + text::printable(explain_->final_path()) +
           " belongs to " + text::printable(output_) + ", which stays (give another -o to see them)";
    return m + "\nIf the sensor was pressed, give a lower --trigger (above the no-contact level), or a no-contact "
               "image with --reference";
  }

  void write_press(const std::string& material, const FrameSource& source, const SourceScores& scores,
                   const std::string& sha, const PressPlan& plan, PressFrames frames) {
    const ContactReference& contact = *scores.contact;
    dataset::GelsightPress p;
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
    p.frames = std::move(frames.frames);
    p.peak = frames.peak;
    p.frames_encoded = std::move(frames.frames_encoded);
    p.peak_encoded = std::move(frames.peak_encoded);
    const cv::Mat& peak = p.peak;
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
    // The sheet is made first: the file records its SHA-256 (layout::kContactSheetSha256).
    const int number = next_press_number(id);
    const std::string sheet_name = id + "_press_" + std::to_string(number) + ".png";
    std::vector<std::uint8_t> sheet;
    if (sheets_) {
      sheet = contact_sheet_png(sheet_input(material, number, source, scores, plan, peak, result_.detections.back()));
      p.contact_sheet = relative_to_folder_of((fs::path(sheets_->final_path()) / sheet_name).string(), output_);
      p.contact_sheet_sha256 = sha256_hex({reinterpret_cast<const char*>(sheet.data()), sheet.size()});
    }
    const int j = writer_.add_press(material, p);
    if (j != number) throw failure("internal: press " + std::to_string(j) + " of " + id + " was numbered " + std::to_string(number));
    if (sheets_) write_png(*sheets_, sheet_name, sheet);
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
    in.peak_index = plan.contact.peak;
    in.chart = chart_of(scores, {plan}, detection);
    in.chart.range_first = plan.range_first;
    in.chart.range_last = plan.range_last;
    in.chart.kept = plan.frame_indices;
    return in;
  }

  std::string output_;
  const ExtractOptions& options_;
  ExtractSettings settings_;
  dataset::GelsightWriter writer_;
  std::unique_ptr<PartialDirectory> sheets_, explain_;
  std::vector<std::string> inputs_;  // every file read, those found in input folders included

  // Whether `folder` is, or holds, one of the inputs: never retired, though the earlier file names it.
  bool holds_an_input(const std::string& folder) const {
    for (const std::string& input : inputs_)
      for (fs::path at = fs::absolute(input); at.has_relative_path(); at = at.parent_path())
        if (same_output_path(at.string(), folder)) return true;
    return false;
  }
  std::set<std::string> explain_names_;
  std::map<std::string, std::string> source_by_sha_;                      // SHA-256 -> the source first with it
  std::map<std::string, std::pair<std::string, std::string>> spelling_;  // material id -> (name, the source first with it)
  ExtractResult result_;
};

}  // namespace

float SourceDetection::signal_to_noise() const {
  return jitter > 0 ? (highest_score - level) / jitter : std::numeric_limits<float>::infinity();
}

std::string describe(const SourceDetection& d) {
  std::string s = d.highest_frame < 0 ? "no frame decoded" : "highest score " + figure(d.highest_score) + " (frame " +
                                                                 std::to_string(d.highest_frame) + ")";
  s += ", trigger " + figure(d.trigger) + " over a no-contact level of " + figure(d.level) + " (jitter " + figure(d.jitter);
  if (d.jitter > 0) s += "; signal-to-noise " + figure(d.signal_to_noise()) + ", a press needs " + figure((d.trigger - d.level) / d.jitter);
  s += "); reference: " + d.reference;
  if (d.pixel_threshold > 0) s += "; per-pixel threshold " + figure(d.pixel_threshold) + " grey levels";
  if (d.presses_left_out > 0)
    s += "; " + std::to_string(d.presses_left_out) + " press(es) left out: frames around the peak do not decode, so no whole run of frames holds it";
  return s;
}

namespace {

std::string beside_output(const std::string& output, const std::string& suffix) {
  fs::path p(output);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

}  // namespace

std::string default_sheets_dir(const std::string& output) { return beside_output(output, "_sheets"); }
std::string default_explain_dir(const std::string& output) { return beside_output(output, "_explain"); }

ExtractResult extract_presses(const std::vector<std::string>& inputs, const std::string& output,
                              const ExtractOptions& options, const Progress& progress) {
  require_reference_frames(options.settings.reference_frames);
  check_output_path(output, options.overwrite);
  const std::vector<CaptureInput> expanded = expand_capture_inputs(inputs, options.material);
  // The files found inside input folders are inputs too: a recorded press is never the output
  // (issue 32, review 2: `extract sess -o sess/press_0.h5 --force` replaced the take's press).
  std::vector<std::string> found;
  for (const CaptureInput& c : expanded) found.push_back(c.path);
  refuse_output_among_inputs(output, found);
  if (options.sheets) refuse_output_among_inputs(options.sheets_dir.empty() ? default_sheets_dir(output) : options.sheets_dir, found);
  if (options.explain) refuse_output_among_inputs(default_explain_dir(output), found);
  std::error_code ec;
  const bool output_there = fs::is_regular_file(output, ec);
  if (options.overwrite && !sheets_at_default_place(output, options)) {
    const RecordedSheets recorded = recorded_sheets(output);
    EarlierOutput::require_retirable(default_sheets_dir(output),
                                     [&](const std::string& dir) { return sheets_of(dir, output, output_there, recorded); },
                                     "the contact sheet folder", "Move your files out of it (or the folder away), or write sheets again");
  }
  if (options.overwrite && !options.explain)
    EarlierOutput::require_retirable(default_explain_dir(output), [&](const std::string& dir) { return companion_of(dir, output, output_there); },
                                     "the score chart folder", "Move your files out of it (or the folder away), or add --explain");
  Extraction extraction(output, options, found);
  // Videos and image sequences are analysed a few at a time on as many threads, the next few while
  // the last are written, and written in their order, so the output is the same whatever the cores.
  // Press files go one at a time (HDF5 runs one call at a time even in its thread-safe build; their
  // frames are scored on every core instead). A video keeps up to 128 MiB of frames until written, and
  // two chunks may be alive: 1 GiB at most on 4 threads (docs/capture.md).
  constexpr unsigned kThreads = 4;
  prepare_video_environment();
  const bool no_press_file = std::none_of(expanded.begin(), expanded.end(),
                                          [](const CaptureInput& c) { return c.kind == CaptureInput::Kind::press_file; });
  const unsigned threads = options.threads ? options.threads : std::min(kThreads, available_cores());
  const std::size_t chunk = no_press_file ? threads : 1;
  struct Chunk {
    std::vector<Extraction::Analysed> analysed;
    std::vector<std::exception_ptr> failed;  // rethrown in the sources' order, as one at a time would
  };
  const auto analyse = [&](std::size_t first) {
    const std::size_t count = std::min(chunk, expanded.size() - first);
    Chunk c{std::vector<Extraction::Analysed>(count), std::vector<std::exception_ptr>(count)};
    parallel_for(count, [&](std::size_t k) {
      try {
        c.analysed[k] = extraction.analyse(expanded[first + k]);
      } catch (...) {
        c.failed[k] = std::current_exception();
      }
    }, unsigned(count));
    return c;
  };
  const auto launch = chunk > 1 ? std::launch::async : std::launch::deferred;
  std::future<Chunk> next = std::async(launch, analyse, std::size_t{0});
  for (std::size_t first = 0; first < expanded.size(); first += chunk) {
    Chunk current = next.get();
    const bool failed = std::any_of(current.failed.begin(), current.failed.end(), [](const auto& e) { return bool(e); });
    if (!failed && first + chunk < expanded.size()) next = std::async(launch, analyse, first + chunk);
    for (std::size_t k = 0; k < current.analysed.size(); ++k) {
      if (progress) progress(first + k, expanded.size(), expanded[first + k].path);
      if (current.failed[k]) std::rethrow_exception(current.failed[k]);
      extraction.write(current.analysed[k]);
    }
  }
  if (progress) progress(expanded.size(), expanded.size(), "");
  return extraction.finish();
}

}  // namespace haptex::capture
