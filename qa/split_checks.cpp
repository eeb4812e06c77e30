// split.*: a split manifest on its own (schema, sections, sets, presses) and against the dataset
// file it was made from (hashes, materials, window counts, force-speed coverage).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/sha256.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"
#include "split/coverage.hpp"
#include "split/sections.hpp"
#include "qa/window_table.hpp"

namespace haptex::qa {
namespace {

std::string list_text(const std::vector<std::int64_t>& v) {
  std::string text;
  for (auto x : v) text += (text.empty() ? "" : ", ") + std::to_string(x);
  return "[" + text + "]";
}

std::string pointer(std::size_t material, const std::string& rest) {
  return "#/materials/" + std::to_string(material) + (rest.empty() ? "" : "/" + rest);
}

std::optional<std::string> string_attr(const h5::Group& root, const char* name) {
  if (!root.has_attr(name)) return std::nullopt;
  try {
    return root.attr_string(name);
  } catch (const Error&) {
    return std::nullopt;
  }
}

// Which set each section of a material belongs to (-1: none); nullopt when the sections are invalid.
std::optional<std::vector<int>> section_sets(const SplitMaterial& m, std::int64_t sections, std::string& problem) {
  std::vector<int> set_of(std::size_t(std::max<std::int64_t>(sections, 0)), -1);
  for (int s = 0; s < 3; ++s)
    for (auto section : m.sections[std::size_t(s)]) {
      if (section < 0 || section >= sections) {
        problem = "section " + std::to_string(section) + " in " + kSetNames[std::size_t(s)] + " is outside 0.." +
                  std::to_string(sections - 1);
        return std::nullopt;
      }
      int& owner = set_of[std::size_t(section)];
      if (owner >= 0 && owner != s) {
        problem = "section " + std::to_string(section) + " is in both " + kSetNames[std::size_t(owner)] + " and " +
                  kSetNames[std::size_t(s)];
        return std::nullopt;
      }
      owner = s;
    }
  return set_of;
}

struct Recount {
  std::array<std::int64_t, 3> windows{};
  std::int64_t crossing = 0;
  std::array<std::vector<cv::Point2f>, 3> points;  // (speed, force)
};

// A window's force-speed point, as haptex split places it: the mean of its action samples.
cv::Point2f window_point(const WindowTable& t, std::size_t w) {
  const std::size_t a = std::size_t(t.action_samples);
  const float* action = &t.action[w * t.action_width];
  float force = 0, speed = 0;
  for (std::size_t k = 0; k < a; ++k) {
    force += action[k] / float(a);
    speed += action[a + k] / float(a);
  }
  return {speed, force};
}

}  // namespace

std::vector<CheckResult> check_split(const SplitManifestDocument& doc, const std::optional<std::string>& dataset_path) {
  CheckTally schema("split.schema", "manifests"), hashes("split.hashes", "hashes"), materials("split.materials", "materials"),
      sections("split.sections", "materials"), sets("split.sets", "materials"), crossing("split.crossing", "materials"),
      coverage("split.coverage", "val/test sets"), recorded("split.coverage_recorded", "coverage figures"),
      presses("split.presses", "materials");
  auto results = [&] {
    return std::vector<CheckResult>{schema.result(),   hashes.result(),   materials.result(),
                                    sections.result(), sets.result(),     crossing.result(),
                                    coverage.result(), recorded.result(), presses.result()};
  };
  try {
    json::validate(doc.json, "split.schema.json", doc.path);
    schema.pass();
  } catch (const Error& e) {
    std::string message = e.what();
    if (message.rfind(doc.path + ": ", 0) == 0) message = message.substr(doc.path.size() + 2);
    schema.fail("#", message);
    for (CheckTally* t : {&hashes, &materials, &sections, &sets, &crossing, &coverage, &recorded, &presses})
      t->skip("the manifest does not follow split.schema.json");
    return results();
  }
  const SplitManifest m = split::parse_split_manifest(doc.json);

  // The dataset file, when at hand.
  std::optional<h5::File> file;
  std::string no_dataset = "the dataset file " + m.dataset_path + " was not found; give it: haptex qa DATASET --split " + doc.path;
  if (dataset_path) {
    file = h5::File::open(*dataset_path);
    no_dataset.clear();
  }
  std::optional<WindowTable> table;
  std::string table_problem;
  if (file) {
    table = load_window_table(file->root(), table_problem);
    if (!table) table_problem = "the dataset's window table is unreadable: " + table_problem;
  } else {
    table_problem = no_dataset;
  }

  // Hashes.
  if (!file) {
    hashes.skip(no_dataset);
  } else {
    const std::string actual = sha256_file(*dataset_path);
    if (actual != m.dataset_sha256)
      hashes.fail("#/dataset/sha256", "the manifest names " + m.dataset_sha256.substr(0, 12) + "..., but " + *dataset_path +
                                          " hashes to " + actual.substr(0, 12) + "...");
    else hashes.pass();
    const h5::Group root = file->root();
    for (const auto& [attr, expected, where] :
         {std::tuple{"recordings_sha256", m.recordings_sha256, "#/dataset/recordings_sha256"},
          std::tuple{"gelsight_sha256", m.gelsight_sha256, "#/dataset/gelsight_sha256"}}) {
      const auto stored = string_attr(root, attr);
      if (!stored) hashes.skip(std::string("the dataset has no ") + attr + " attribute");
      else if (*stored != expected)
        hashes.fail(where, "the manifest names " + expected.substr(0, 12) + "..., the dataset's /@" + attr + " is " +
                               stored->substr(0, 12) + "...");
      else hashes.pass();
    }
  }

  // Per material, from the manifest alone: sections, sets, presses.
  std::vector<std::optional<std::vector<int>>> set_of(m.materials.size());
  std::set<std::string> ids;
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const SplitMaterial& mat = m.materials[i];
    std::string problem;
    set_of[i] = section_sets(mat, m.sections, problem);
    if (set_of[i]) sections.pass();
    else sections.fail(pointer(i, "sections"), mat.id + ": " + problem);

    std::string missing;
    for (std::size_t s = 0; s < 3; ++s)
      if (mat.sections[s].empty() || mat.windows[s] <= 0)
        missing += (missing.empty() ? "" : ", ") + std::string(kSetNames[s]) + " (" +
                   std::to_string(mat.sections[s].size()) + " sections, " + std::to_string(mat.windows[s]) + " windows)";
    if (missing.empty()) sets.pass();
    else sets.fail(pointer(i, ""), mat.id + ": nothing in " + missing);

    std::string press_problem;
    // 3 train, 1 val, 1 test (DESIGN.md section 6); haptex split gives training any presses beyond five.
    const std::array<std::size_t, 3> wanted = {3, 1, 1};
    std::set<std::int64_t> all;
    for (std::size_t s = 0; s < 3 && press_problem.empty(); ++s) {
      const std::size_t n = mat.presses[s].size();
      if (s == 0 ? n < wanted[s] : n != wanted[s])
        press_problem = std::to_string(n) + " " + kSetNames[s] + " presses " + list_text(mat.presses[s]) + ", expected " +
                        (s == 0 ? "at least " : "") + std::to_string(wanted[s]);
      for (auto j : mat.presses[s])
        if (!all.insert(j).second && press_problem.empty())
          press_problem = "press " + std::to_string(j) + " is in two sets";
    }
    if (press_problem.empty() && file) {
      const h5::Group root = file->root();
      for (auto j : all) {
        const std::string path = "materials/" + mat.id + "/presses/" + std::to_string(j);
        if (!root.has_group("materials") || !root.open_group("materials").has_group(mat.id) ||
            !root.open_group("materials/" + mat.id).has_group("presses") ||
            !root.open_group("materials/" + mat.id + "/presses").has_group(std::to_string(j))) {
          press_problem = "press " + std::to_string(j) + " is not in the dataset (/" + path + ")";
          break;
        }
      }
    }
    if (press_problem.empty()) presses.pass();
    else presses.fail(pointer(i, "presses"), mat.id + ": " + press_problem);

    if (!ids.insert(mat.id).second) materials.fail(pointer(i, "id"), mat.id + " is listed twice");
  }

  // Against the dataset: materials, window counts and coverage.
  if (!table) {
    for (CheckTally* t : {&materials, &crossing, &coverage, &recorded}) t->skip(table_problem);
    return results();
  }
  const h5::Group root = file->root();
  const WindowTable& t = *table;
  std::set<std::string> in_dataset(t.materials.begin(), t.materials.end());
  for (const auto& id : in_dataset)
    if (!ids.count(id)) materials.fail("#/materials", id + " has windows in the dataset but is not in the manifest");
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const SplitMaterial& mat = m.materials[i];
    index_of.emplace(mat.id, i);
    if (!in_dataset.count(mat.id)) {
      materials.fail(pointer(i, "id"), mat.id + " is not in the dataset's window table");
      continue;
    }
    std::int64_t recordings = 0;
    if (root.has_group("materials/" + mat.id + "/recordings"))
      recordings = std::int64_t(root.open_group("materials/" + mat.id + "/recordings").children().size());
    if (recordings != mat.recordings)
      materials.fail(pointer(i, "recordings"), mat.id + ": the manifest counts " + std::to_string(mat.recordings) +
                                                   " recordings, the dataset has " + std::to_string(recordings));
    else materials.pass();
  }

  // Recount the windows of each material from the table and its recordings' lengths.
  std::vector<Recount> recount(m.materials.size());
  std::map<std::pair<std::int32_t, std::int32_t>, std::optional<std::int64_t>> samples_cache;
  const bool have_actions = !t.action.empty() && t.action_width == 2 * std::size_t(t.action_samples);
  for (std::size_t w = 0; w < t.size(); ++w) {
    if (t.material[w] < 0 || std::size_t(t.material[w]) >= t.materials.size()) continue;
    const auto it = index_of.find(t.materials[std::size_t(t.material[w])]);
    if (it == index_of.end() || !set_of[it->second]) continue;
    auto& samples = samples_cache[{t.material[w], t.recording[w]}];
    if (!samples) samples = recording_samples(root, it->first, t.recording[w]).value_or(-1);
    Recount& r = recount[it->second];
    const int section = split::section_of(t.first_sample(w), t.end_sample(w), *samples, std::size_t(m.sections));
    if (section < 0) {
      ++r.crossing;
      continue;
    }
    const int set = (*set_of[it->second])[std::size_t(section)];
    if (set < 0) continue;
    ++r.windows[std::size_t(set)];
    if (have_actions) r.points[std::size_t(set)].push_back(window_point(t, w));
  }

  double worst_recorded = 1.0;
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const SplitMaterial& mat = m.materials[i];
    worst_recorded = std::min({worst_recorded, mat.coverage_val, mat.coverage_test});
    if (!set_of[i] || !in_dataset.count(mat.id)) {
      for (CheckTally* tally : {&crossing, &coverage, &recorded})
        tally->skip(mat.id + ": invalid sections or not in the dataset");
      continue;
    }
    const Recount& r = recount[i];
    if (r.windows != mat.windows || r.crossing != mat.crossing)
      crossing.fail(pointer(i, "windows"),
                    mat.id + ": the manifest counts " + std::to_string(mat.windows[0]) + "/" + std::to_string(mat.windows[1]) +
                        "/" + std::to_string(mat.windows[2]) + " train/val/test windows and " + std::to_string(mat.crossing) +
                        " crossing; inside the sections lie " + std::to_string(r.windows[0]) + "/" +
                        std::to_string(r.windows[1]) + "/" + std::to_string(r.windows[2]) + ", and " +
                        std::to_string(r.crossing) + " cross a boundary");
    else crossing.pass();

    if (!have_actions) {
      coverage.skip("/windows/action is unreadable");
      recorded.skip("/windows/action is unreadable");
      continue;
    }
    for (std::size_t s = 1; s < 3; ++s) {
      const double stored = s == 1 ? mat.coverage_val : mat.coverage_test;
      const std::string where = pointer(i, std::string("coverage/") + kSetNames[s]);
      if (r.points[s].empty()) {
        coverage.skip(mat.id + ": no " + kSetNames[s] + " windows");
        recorded.skip(mat.id + ": no " + kSetNames[s] + " windows");
        continue;
      }
      const double actual = split::hull_coverage(r.points[0], r.points[s]);
      if (actual < m.min_coverage)
        coverage.fail(where, mat.id + ": " + number(100 * actual) + "% of the " + kSetNames[s] +
                                 " windows lie inside the training force-speed hull, under min_coverage " +
                                 number(100 * m.min_coverage) + "%");
      else coverage.pass();
      if (std::abs(actual - stored) > kCoverageRecordedTolerance)
        recorded.fail(where, mat.id + ": the manifest records " + number(stored) + ", recomputed " + number(actual));
      else recorded.pass();
    }
  }
  if (!m.materials.empty() && std::abs(worst_recorded - m.worst_coverage) > 1e-9)
    recorded.fail("#/worst_coverage", "is " + number(m.worst_coverage) + ", the lowest coverage the manifest lists is " +
                                          number(worst_recorded));
  return results();
}

}  // namespace haptex::qa
