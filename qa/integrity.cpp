#include "qa/integrity.hpp"

#include "core/error.hpp"
#include "dataset/format.hpp"
#include "qa/checkers.hpp"
#include "qa/gelsight_checks.hpp"
#include "qa/recording_checks.hpp"

namespace haptex::qa {
namespace {

std::vector<CheckResult> recording_integrity(const h5::Group& root) {
  CheckTally nan{"signal.nan", "recordings"}, rate{"signal.sample_rate", "recordings"}, stated{"filter.stated", "recordings"},
      duplicate{"recordings.duplicate", "recordings"};
  SeenHashes hashes;
  for (const auto& path : recording_paths(root)) {
    const LoadedRecording r = load_recording(root, path);
    check_signal_nan(r, nan);
    check_signal_sample_rate(r, rate);
    check_filter_stated(r, stated);
    check_recordings_duplicate(r, duplicate, hashes);  // a recording twice would leak between train and test
  }
  return {nan.result(), rate.result(), stated.result(), duplicate.result()};
}

void append(std::vector<CheckResult>& out, std::vector<CheckResult> more) {
  for (auto& r : more) out.push_back(std::move(r));
}

}  // namespace

std::vector<CheckResult> check_integrity(const h5::Group& root, dataset::Kind kind) {
  std::vector<CheckResult> results = check_layout(root, kind);
  if (kind != dataset::Kind::gelsight) append(results, recording_integrity(root));
  if (kind != dataset::Kind::recordings) {
    results.push_back(check_gelsight_duplicate(root));  // one press twice would leak between train and test
    results.push_back(check_gelsight_channel_order(root));
    results.push_back(check_gelsight_frame_numbers(root));
    results.push_back(check_gelsight_images(root));
  }
  if (kind == dataset::Kind::dataset) append(results, check_dataset(root));
  return results;
}

namespace {

void require_passed(const h5::Group& root, const std::vector<CheckResult>& results) {
  for (const CheckResult& r : results)
    if (r.status == Status::fail)
      throw input_error(root.file(), "", r.message + " (qa check " + r.id + ")",
                        r.hint + "; `haptex qa " + root.file() + "` lists every finding");
}

}  // namespace

void require_integrity(const h5::Group& root, dataset::Kind kind) { require_passed(root, check_integrity(root, kind)); }

void require_sound_layout(const h5::Group& root, dataset::Kind kind) { require_passed(root, check_layout(root, kind)); }

void require_sound_dataset(const std::string& dataset_path) {
  const h5::File file = dataset::open_checked(dataset_path, dataset::Kind::dataset);
  require_sound_layout(file.root(), dataset::Kind::dataset);
  require_passed(file.root(), check_dataset(file.root()));
}

}  // namespace haptex::qa
