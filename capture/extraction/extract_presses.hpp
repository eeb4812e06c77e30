#pragma once
// `haptex capture extract`: press files and videos -> the gelsight file, plus one contact sheet PNG
// per press. Nothing is written under the final names unless every input was read: the gelsight file
// goes through NAME.partial and the sheets through a DIR.partial folder renamed at the end.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "capture/extraction/peak_frames.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"

namespace haptex::capture {

struct ExtractOptions {
  ExtractSettings settings;
  std::optional<std::string> material;        // names every input's material
  std::optional<std::string> reference_path;  // a no-contact image replacing the leading frames
  bool overwrite = false;
  bool sheets = true;
  std::string sheets_dir;  // default: <output without extension>_sheets beside the output
  // --explain: one chart per source of its score over time with the reference, the thresholds and the
  // presses (score_chart.hpp), in <output without extension>_explain/<the source's name as an id>.png,
  // written even when no source holds a press.
  bool explain = false;
  std::string provenance;
  // Image sequences analysed at once (0: one per core, at most 4); the output is the same for any count.
  unsigned threads = 0;
};

struct ExtractedPressSummary {
  std::string material, material_id, source;
  int press = 0, press_in_source = 0;
  std::int64_t frame_start = 0, frame_end = 0, contact_first = 0, contact_last = 0, peak_index = 0;
  float peak_score = 0;
  std::string contact_sheet;
};

// What a source's presses were judged by, so a user sees why one was or was not found.
struct SourceDetection {
  std::string source, reference;  // reference: where the no-contact reference came from
  std::string reference_kind;     // reference_kind_name: start, end, least contact, image, press file
  int presses = 0;
  float noise = 0, pixel_threshold = 0, level = 0, jitter = 0, trigger = 0, release = 0;
  float highest_score = 0;  // the source's strongest frame
  std::int64_t highest_frame = -1;
  std::string chart;  // its --explain chart, or empty
  // Presses found but left out: no run of frames_per_press decoded frames holds their peak.
  int presses_left_out = 0;
  // The strongest frame's excess over the no-contact level in units of the score's jitter: the
  // score's signal-to-noise. A press needs (trigger - level) / jitter, 5 or more by default. Infinite
  // when the jitter is 0 (a given image, copied frames).
  float signal_to_noise() const;
};
// One line: the strongest frame, the trigger, the level and the signal-to-noise.
std::string describe(const SourceDetection& d);

struct ExtractResult {
  std::vector<ExtractedPressSummary> presses;
  std::vector<SourceDetection> detections;  // one per source, in input order
  std::vector<std::string> sources_without_press;
  std::size_t sources = 0;
  std::int64_t frames_scored = 0;
  // Frames that did not decode (damaged, or announced by a video cut short): never a peak or kept.
  std::int64_t frames_unreadable = 0;
  std::string sheets_dir;  // empty without sheets
  std::string explain_dir;  // empty without --explain
};

// No input held a press, and nothing was written: what each source was judged by comes with the error.
class NoPressFound : public Error {
 public:
  NoPressFound(const std::string& message, ExtractResult result)
      : Error(Kind::failed, message), result_(std::move(result)) {}
  const ExtractResult& result() const { return result_; }

 private:
  ExtractResult result_;
};

// Throws haptex::Error: bad_input for unreadable inputs or outputs; NoPressFound (failed) when no input
// holds a press.
ExtractResult extract_presses(const std::vector<std::string>& inputs, const std::string& output,
                              const ExtractOptions& options, const Progress& progress = {});

std::string default_sheets_dir(const std::string& output);
std::string default_explain_dir(const std::string& output);

}  // namespace haptex::capture
