// recordings.duplicate: the same source file converted twice, or the same samples under two names.
#include <algorithm>

#include "core/sha256.hpp"
#include "qa/checkers.hpp"

namespace haptex::qa {
namespace {

const std::string* find_hash(const std::vector<std::pair<std::string, std::string>>& seen, const std::string& hash) {
  for (const auto& [h, path] : seen)
    if (h == hash) return &path;
  return nullptr;
}

}  // namespace

DuplicateCheck::DuplicateCheck() : tally_("recordings.duplicate", "recordings") {}

void DuplicateCheck::add(const LoadedRecording& r) {
  const Signal& accel = r.signals.at("accel_xyz").ok() ? r.signals.at("accel_xyz") : r.signals.at("accel");
  if (!r.source_sha256 && !accel.ok()) {
    tally_.skip(r.path + ": neither source_sha256 nor acceleration to compare");
    return;
  }
  std::string problem;
  if (r.source_sha256 && !r.source_sha256->empty()) {
    if (const std::string* first = find_hash(source_hashes_, *r.source_sha256))
      problem = "the same source file (SHA-256 " + r.source_sha256->substr(0, 12) + "...) as " + *first;
    else source_hashes_.emplace_back(*r.source_sha256, r.path);
  }
  if (accel.ok()) {
    Sha256 hash;
    hash.update(std::span(reinterpret_cast<const std::uint8_t*>(accel.values.data()), accel.values.size() * sizeof(double)));
    const std::string data_hash = hash.hex_digest();
    if (const std::string* first = find_hash(data_hashes_, data_hash)) {
      if (problem.empty()) problem = "the same acceleration samples as " + *first;
    } else {
      data_hashes_.emplace_back(data_hash, r.path);
    }
  }
  if (problem.empty()) tally_.pass();
  else tally_.fail(r.path, problem);
}

std::vector<CheckResult> DuplicateCheck::results() const { return {tally_.result()}; }

}  // namespace haptex::qa
