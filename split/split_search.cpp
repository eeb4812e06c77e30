#include "split/split_search.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random_seeds.hpp"
#include "core/text/format.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/window.hpp"
#include "split/coverage.hpp"
#include "split/sections.hpp"

namespace haptex::split {
namespace {

constexpr std::size_t kPresses = 5;  // 3 train, 1 val, 1 test (docs/split.md)

Sets random_sets(std::size_t count, std::size_t val, std::size_t test, std::mt19937_64& rng) {
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  Sets s;
  s.val.assign(order.begin(), order.begin() + std::ptrdiff_t(val));
  s.test.assign(order.begin() + std::ptrdiff_t(val), order.begin() + std::ptrdiff_t(val + test));
  s.train.assign(order.begin() + std::ptrdiff_t(val + test), order.end());
  for (auto* v : {&s.train, &s.val, &s.test}) std::sort(v->begin(), v->end());
  return s;
}

// Counts and coverage of one assignment.
MaterialSplit evaluate(const MaterialWindows& m, const std::vector<int>& section, const Sets& sets) {
  MaterialSplit r;
  r.sections = sets;
  std::vector<cv::Point2f> points[3];
  for (std::size_t i = 0; i < section.size(); ++i) {
    const int set = section[i] < 0 ? -1 : set_of_section(sets, section[i]);
    if (set < 0) {
      ++r.crossing_windows;
      continue;
    }
    points[set].emplace_back(m.speed[i], m.force[i]);
  }
  r.train_windows = points[0].size();
  r.val_windows = points[1].size();
  r.test_windows = points[2].size();
  r.val_coverage = hull_coverage(points[0], points[1]);
  r.test_coverage = hull_coverage(points[0], points[2]);
  return r;
}

MaterialSplit best_split(const MaterialWindows& m, const SplitOptions& o) {
  const std::vector<int> section = window_sections(m, o.sections);
  MaterialSplit best;
  for (int attempt = 0; attempt < o.tries; ++attempt) {
    std::mt19937_64 rng(derive_seed(o.seed, name_seed(m.id), std::uint64_t(attempt)));
    MaterialSplit candidate = evaluate(m, section, random_sets(o.sections, o.val, o.test, rng));
    if (attempt == 0 || candidate.worst() > best.worst()) best = candidate;
    if (best.worst() >= 1.0) break;
  }
  std::mt19937_64 press_rng(derive_seed(o.seed, name_seed(m.id), 0x9e55));
  best.presses = random_sets(m.presses, 1, 1, press_rng);
  best.id = m.id;
  best.name = m.name;
  best.recordings = m.recording_samples.size();
  return best;
}

std::string format_fraction(double x) {
  return text::format("%.3f", x);
}

}  // namespace

std::vector<int> window_sections(const MaterialWindows& m, std::size_t sections) {
  std::vector<int> out(m.start.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::int64_t n = m.recording_samples.at(std::size_t(m.recording[i]));
    out[i] = section_of(dataset::window_first_sample(m.start[i]), dataset::window_end_sample(m.start[i]), n, sections);
  }
  return out;
}

int set_of_section(const Sets& s, int section) {
  if (std::binary_search(s.train.begin(), s.train.end(), section)) return 0;
  if (std::binary_search(s.val.begin(), s.val.end(), section)) return 1;
  if (std::binary_search(s.test.begin(), s.test.end(), section)) return 2;
  return -1;
}

std::vector<MaterialSplit> search_split(const std::vector<MaterialWindows>& materials, const SplitOptions& o,
                                        const std::string& dataset_path) {
  if (o.val < 1 || o.test < 1 || o.val + o.test + 1 > o.sections)
    throw input_error("--val/--test/--sections", "", "need at least one section each for val and test and one for training",
                      "For example --sections 25 --val 3 --test 3");
  if (o.tries < 1) throw input_error("--tries", "", "must be at least 1", "Pass --tries 200");
  for (const auto& m : materials)
    if (m.presses < kPresses)
      throw input_error(dataset_path, dataset::presses_path(m.id),
                        "material '" + m.name + "' has " + std::to_string(m.presses) + " presses; the split needs 5 (3 train, 1 val, 1 test)",
                        "Capture more presses of this material, then run capture extract and align again");
  std::vector<MaterialSplit> result(materials.size());
  parallel_for(materials.size(), [&](std::size_t i) { result[i] = best_split(materials[i], o); });
  std::string below;
  for (const auto& r : result)
    if (r.worst() < o.min_coverage)
      below += (below.empty() ? "" : ", ") + r.id + " (val " + format_fraction(r.val_coverage) + ", test " +
               format_fraction(r.test_coverage) + ")";
  if (!below.empty())
    throw failure("force-speed coverage stays under " + format_fraction(o.min_coverage) + " for: " + below +
                  ". Try more --tries, another --seed, more --sections, or record strokes that cover these materials' "
                  "force and speed range more evenly; --min-coverage lowers the bar (and the split's value)");
  return result;
}

}  // namespace haptex::split
