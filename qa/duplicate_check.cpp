// recordings.duplicate: the same source file converted twice, or the same samples under two names.
#include <span>

#include "core/sha256.hpp"
#include "dataset/layout.hpp"
#include "qa/recording_checks.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

using Hashes = std::vector<std::pair<std::string, std::string>>;

const std::string* find_hash(const Hashes& seen, const std::string& hash) {
  for (const auto& [h, path] : seen)
    if (h == hash) return &path;
  return nullptr;
}

// The recording that first had `hash`, or nullptr after remembering `path` as that recording.
const std::string* first_with(Hashes& seen, const std::string& hash, const std::string& path) {
  if (const std::string* first = find_hash(seen, hash)) return first;
  seen.emplace_back(hash, path);
  return nullptr;
}

std::string data_hash(const Signal& s) {
  Sha256 hash;
  hash.update(std::span(reinterpret_cast<const std::uint8_t*>(s.values.data()), s.values.size() * sizeof(double)));
  return hash.hex_digest();
}

}  // namespace

void check_recordings_duplicate(const LoadedRecording& r, CheckTally& tally, SeenHashes& seen) {
  const Signal& accel = r.signals.at(layout::kAccelXyz).ok() ? r.signals.at(layout::kAccelXyz) : r.signals.at(layout::kAccel);
  if (!r.source_sha256 && !accel.ok()) return tally.skip(r.path + ": neither source_sha256 nor acceleration to compare");
  std::string problem;
  if (r.source_sha256 && !r.source_sha256->empty())
    if (const std::string* first = first_with(seen.source, *r.source_sha256, r.path))
      problem = "the same source file (SHA-256 " + r.source_sha256->substr(0, 12) + "...) as " + *first;
  if (accel.ok())
    if (const std::string* first = first_with(seen.data, data_hash(accel), r.path); first && problem.empty())
      problem = "the same acceleration samples as " + *first;
  if (problem.empty()) tally.pass();
  else tally.fail(r.path, problem);
}

}  // namespace haptex::qa
