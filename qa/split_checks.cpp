// split.*: a split manifest on its own (schema, sections, sets, presses) and against the dataset
// file it was made from (hashes, materials, window counts, force-speed coverage).
#include "qa/split_checks.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "core/error.hpp"
#include "core/h5/link_rule.hpp"
#include "core/json/schema.hpp"
#include "core/sha256.hpp"
#include "dataset/layout.hpp"
#include "dataset/window.hpp"
#include "qa/catalog.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"
#include "split/coverage.hpp"
#include "split/sections.hpp"

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

MaterialSections section_sets(const SplitMaterial& m, std::int64_t sections) {
  std::vector<int> set_of(std::size_t(std::max<std::int64_t>(sections, 0)), -1);
  for (int s = 0; s < 3; ++s)
    for (auto section : m.sections[std::size_t(s)]) {
      if (section < 0 || section >= sections)
        return {std::nullopt, "section " + std::to_string(section) + " in " + kSetNames[std::size_t(s)] +
                                  " is outside 0.." + std::to_string(sections - 1)};
      int& owner = set_of[std::size_t(section)];
      if (owner >= 0 && owner != s)
        return {std::nullopt, "section " + std::to_string(section) + " is in both " + kSetNames[std::size_t(owner)] +
                                  " and " + kSetNames[std::size_t(s)]};
      owner = s;
    }
  return {set_of, ""};
}

// A window's force-speed point, where haptex split places it (dataset::action_point).
cv::Point2f window_point(const WindowTable& t, std::size_t w) {
  const dataset::ActionPoint p = dataset::action_point(std::span(t.action).subspan(w * t.action_width, t.action_width));
  return {p.speed, p.force};
}

// Actions of this haptex's shape (dataset.windows reports any other).
bool has_actions(const WindowTable& t) { return !t.action.empty() && t.action_width == dataset::kActionValues; }

// judge(i) for every material whose windows were recounted; a skip for the others (for all of
// them without a window table).
void for_each_recounted(const SplitManifest& m, const SplitDataset& d, const std::vector<Recount>& recount,
                        CheckTally& tally, const std::function<void(std::size_t)>& judge) {
  if (!d.table) return tally.skip(d.table_problem);
  for (std::size_t i = 0; i < m.materials.size(); ++i)
    if (recount[i].usable) judge(i);
    else tally.skip(m.materials[i].id + ": invalid sections or not in the dataset");
}

// judge(i, s, coverage) for the val and test sets (s = 1, 2) of every material whose coverage was
// recomputed; a skip for the others.
void for_each_coverage(const SplitManifest& m, const SplitDataset& d, const std::vector<Recount>& recount,
                       CheckTally& tally, const std::function<void(std::size_t, std::size_t, double)>& judge) {
  for_each_recounted(m, d, recount, tally, [&](std::size_t i) {
    if (!has_actions(*d.table)) return tally.skip("/windows/action is unreadable");
    for (std::size_t s = 1; s < 3; ++s)
      if (const auto coverage = recount[i].coverage[s]) judge(i, s, *coverage);
      else tally.skip(m.materials[i].id + ": no " + kSetNames[s] + " windows");
  });
}

std::string coverage_where(std::size_t i, std::size_t s) { return pointer(i, std::string("coverage/") + kSetNames[s]); }

// Why a material's presses are not at least 3 train, exactly 1 val and 1 test, each in one set;
// empty when they are. 3 + 1 + 1 (docs/split.md); haptex split gives training any presses beyond five.
std::string press_sets_problem(const SplitMaterial& mat) {
  const std::array<std::size_t, 3> wanted = {3, 1, 1};
  std::set<std::int64_t> all;
  for (std::size_t s = 0; s < 3; ++s) {
    const std::size_t n = mat.presses[s].size();
    if (s == 0 ? n < wanted[s] : n != wanted[s])
      return std::to_string(n) + " " + kSetNames[s] + " presses " + list_text(mat.presses[s]) + ", expected " +
             (s == 0 ? "at least " : "") + std::to_string(wanted[s]);
    for (auto j : mat.presses[s])
      if (!all.insert(j).second) return "press " + std::to_string(j) + " is in two sets";
  }
  return "";
}

bool has_press(const h5::Group& root, const std::string& material, const std::string& press) {
  using namespace dataset::layout;
  const std::string path = std::string(kMaterials) + "/" + material;
  return root.has_group(kMaterials) && root.open_group(kMaterials).has_group(material) && root.open_group(path).has_group(kPresses) &&
         root.open_group(path + "/" + kPresses).has_group(press);
}

// The first of a material's presses (in order of number) the dataset lacks; empty when it has them all.
std::string missing_press(const SplitMaterial& mat, const h5::Group& root) {
  std::set<std::int64_t> all;
  for (const auto& set : mat.presses) all.insert(set.begin(), set.end());
  for (auto j : all)
    if (!has_press(root, mat.id, std::to_string(j)))
      return "press " + std::to_string(j) + " is not in the dataset (/materials/" + mat.id + "/presses/" +
             std::to_string(j) + ")";
  return "";
}

}  // namespace

SplitDataset open_split_dataset(const SplitManifest& m, const std::string& manifest_path,
                                const std::optional<std::string>& dataset_path) {
  SplitDataset d;
  d.path = dataset_path;
  if (!dataset_path) {
    d.missing = "the dataset file " + m.dataset_path + " was not found; give it: haptex qa DATASET --split " + manifest_path;
    d.table_problem = d.missing;
    return d;
  }
  d.file = h5::File::open(*dataset_path);
  h5::require_link_rule(d.file->root());  // its window table is looked up by name (core/h5/link_rule.hpp)
  d.table = load_window_table(d.file->root(), d.table_problem);
  if (!d.table) d.table_problem = "the dataset's window table is unreadable: " + d.table_problem;
  else d.materials.insert(d.table->materials.begin(), d.table->materials.end());
  return d;
}

std::vector<MaterialSections> material_sections(const SplitManifest& m) {
  std::vector<MaterialSections> out;
  for (const auto& mat : m.materials) out.push_back(section_sets(mat, m.sections));
  return out;
}

std::vector<Recount> recount_windows(const SplitManifest& m, const std::vector<MaterialSections>& sections,
                                     const SplitDataset& d) {
  std::vector<Recount> recount(m.materials.size());
  if (!d.table) return recount;
  const WindowTable& t = *d.table;
  const h5::Group root = d.file->root();
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < m.materials.size(); ++i) index_of.emplace(m.materials[i].id, i);
  std::vector<std::array<std::vector<cv::Point2f>, 3>> points(m.materials.size());  // (speed, force)
  std::map<std::pair<std::int32_t, std::int32_t>, std::optional<std::int64_t>> samples_cache;
  const bool actions = has_actions(t);
  for (std::size_t w = 0; w < t.size(); ++w) {
    if (t.material[w] < 0 || std::size_t(t.material[w]) >= t.materials.size()) continue;
    const auto it = index_of.find(t.materials[std::size_t(t.material[w])]);
    if (it == index_of.end() || !sections[it->second].set_of) continue;
    auto& samples = samples_cache[{t.material[w], t.recording[w]}];
    if (!samples) samples = recording_samples(root, it->first, t.recording[w]).value_or(-1);
    Recount& r = recount[it->second];
    const int section = split::section_of(t.first_sample(w), t.end_sample(w), *samples, std::size_t(m.sections));
    if (section < 0) {
      ++r.crossing;
      continue;
    }
    const int set = (*sections[it->second].set_of)[std::size_t(section)];
    if (set < 0) continue;
    ++r.windows[std::size_t(set)];
    if (actions) points[it->second][std::size_t(set)].push_back(window_point(t, w));
  }
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    Recount& r = recount[i];
    r.usable = sections[i].set_of && d.materials.count(m.materials[i].id);
    for (std::size_t s = 1; s < 3 && r.usable; ++s)
      if (!points[i][s].empty()) r.coverage[s] = split::hull_coverage(points[i][0], points[i][s]);
  }
  return recount;
}

CheckResult check_split_schema(const SplitManifestDocument& doc) {
  CheckTally tally("split.schema", "manifests");
  try {
    split::validate_split_manifest(doc);
    tally.pass();
  } catch (const Error& e) {
    std::string message = e.what();
    if (message.rfind(doc.path + ": ", 0) == 0) message = message.substr(doc.path.size() + 2);
    tally.fail("#", message);
  }
  return tally.result();
}

CheckResult check_split_hashes(const SplitManifest& m, const SplitDataset& d) {
  CheckTally tally("split.hashes", "hashes");
  if (!d.file) {
    tally.skip(d.missing);
    return tally.result();
  }
  const std::string actual = sha256_file(*d.path);
  if (actual != m.dataset_sha256)
    tally.fail("#/dataset/sha256", "the manifest names " + m.dataset_sha256.substr(0, 12) + "..., but " + *d.path +
                                       " hashes to " + actual.substr(0, 12) + "...");
  else tally.pass();
  const h5::Group root = d.file->root();
  for (const auto& [attr, expected, where] :
       {std::tuple{"recordings_sha256", m.recordings_sha256, "#/dataset/recordings_sha256"},
        std::tuple{"gelsight_sha256", m.gelsight_sha256, "#/dataset/gelsight_sha256"}}) {
    const auto stored = root.try_attr<std::string>(attr);
    if (!stored) tally.skip(std::string("the dataset has no ") + attr + " attribute");
    else if (*stored != expected)
      tally.fail(where, "the manifest names " + expected.substr(0, 12) + "..., the dataset's /@" + attr + " is " +
                            stored->substr(0, 12) + "...");
    else tally.pass();
  }
  return tally.result();
}

CheckResult check_split_materials(const SplitManifest& m, const SplitDataset& d) {
  CheckTally tally("split.materials", "materials");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < m.materials.size(); ++i)
    if (!ids.insert(m.materials[i].id).second) tally.fail(pointer(i, "id"), m.materials[i].id + " is listed twice");
  if (!d.table) {
    tally.skip(d.table_problem);
    return tally.result();
  }
  for (const auto& id : d.materials)
    if (!ids.count(id)) tally.fail("#/materials", id + " has windows in the dataset but is not in the manifest");
  const h5::Group root = d.file->root();
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const SplitMaterial& mat = m.materials[i];
    if (!d.materials.count(mat.id)) {
      tally.fail(pointer(i, "id"), mat.id + " is not in the dataset's window table");
      continue;
    }
    std::int64_t recordings = 0;
    const std::string path = std::string(dataset::layout::kMaterials) + "/" + mat.id + "/" + dataset::layout::kRecordings;
    if (root.has_group(path)) recordings = std::int64_t(root.open_group(path).children().size());
    if (recordings != mat.recordings)
      tally.fail(pointer(i, "recordings"), mat.id + ": the manifest counts " + std::to_string(mat.recordings) +
                                               " recordings, the dataset has " + std::to_string(recordings));
    else tally.pass();
  }
  return tally.result();
}

CheckResult check_split_sections(const SplitManifest& m, const std::vector<MaterialSections>& sections) {
  CheckTally tally("split.sections", "materials");
  for (std::size_t i = 0; i < m.materials.size(); ++i)
    if (sections[i].set_of) tally.pass();
    else tally.fail(pointer(i, "sections"), m.materials[i].id + ": " + sections[i].problem);
  return tally.result();
}

CheckResult check_split_sets(const SplitManifest& m) {
  CheckTally tally("split.sets", "materials");
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const SplitMaterial& mat = m.materials[i];
    std::string missing;
    for (std::size_t s = 0; s < 3; ++s)
      if (mat.sections[s].empty() || mat.windows[s] <= 0)
        missing += (missing.empty() ? "" : ", ") + std::string(kSetNames[s]) + " (" +
                   std::to_string(mat.sections[s].size()) + " sections, " + std::to_string(mat.windows[s]) + " windows)";
    if (missing.empty()) tally.pass();
    else tally.fail(pointer(i, ""), mat.id + ": nothing in " + missing);
  }
  return tally.result();
}

CheckResult check_split_crossing(const SplitManifest& m, const SplitDataset& d, const std::vector<Recount>& recount) {
  CheckTally tally("split.crossing", "materials");
  for_each_recounted(m, d, recount, tally, [&](std::size_t i) {
    const SplitMaterial& mat = m.materials[i];
    const Recount& r = recount[i];
    if (r.windows == mat.windows && r.crossing == mat.crossing) return tally.pass();
    tally.fail(pointer(i, "windows"),
               mat.id + ": the manifest counts " + std::to_string(mat.windows[0]) + "/" + std::to_string(mat.windows[1]) +
                   "/" + std::to_string(mat.windows[2]) + " train/val/test windows and " + std::to_string(mat.crossing) +
                   " crossing; inside the sections lie " + std::to_string(r.windows[0]) + "/" +
                   std::to_string(r.windows[1]) + "/" + std::to_string(r.windows[2]) + ", and " +
                   std::to_string(r.crossing) + " cross a boundary");
  });
  return tally.result();
}

CheckResult check_split_coverage(const SplitManifest& m, const SplitDataset& d, const std::vector<Recount>& recount) {
  CheckTally tally("split.coverage", "val/test sets");
  for_each_coverage(m, d, recount, tally, [&](std::size_t i, std::size_t s, double coverage) {
    if (coverage < m.min_coverage)
      tally.fail(coverage_where(i, s), m.materials[i].id + ": " + number(100 * coverage) + "% of the " + kSetNames[s] +
                                           " windows lie inside the training force-speed hull, under min_coverage " +
                                           number(100 * m.min_coverage) + "%");
    else tally.pass();
  });
  return tally.result();
}

CheckResult check_split_coverage_recorded(const SplitManifest& m, const SplitDataset& d,
                                          const std::vector<Recount>& recount) {
  CheckTally tally("split.coverage_recorded", "coverage figures");
  for_each_coverage(m, d, recount, tally, [&](std::size_t i, std::size_t s, double coverage) {
    const double stored = s == 1 ? m.materials[i].coverage_val : m.materials[i].coverage_test;
    if (std::abs(coverage - stored) > kCoverageRecordedTolerance)
      tally.fail(coverage_where(i, s), m.materials[i].id + ": the manifest records " + number(stored) + ", recomputed " +
                                           number(coverage));
    else tally.pass();
  });
  if (!d.table || m.materials.empty()) return tally.result();
  double lowest = 1.0;
  for (const auto& mat : m.materials) lowest = std::min({lowest, mat.coverage_val, mat.coverage_test});
  if (std::abs(lowest - m.worst_coverage) > 1e-9)
    tally.fail("#/worst_coverage", "is " + number(m.worst_coverage) + ", the lowest coverage the manifest lists is " +
                                       number(lowest));
  return tally.result();
}

CheckResult check_split_presses(const SplitManifest& m, const SplitDataset& d) {
  CheckTally tally("split.presses", "materials");
  for (std::size_t i = 0; i < m.materials.size(); ++i) {
    const SplitMaterial& mat = m.materials[i];
    std::string problem = press_sets_problem(mat);
    if (problem.empty() && d.file) problem = missing_press(mat, d.file->root());
    if (problem.empty()) tally.pass();
    else tally.fail(pointer(i, "presses"), mat.id + ": " + problem);
  }
  return tally.result();
}

std::vector<CheckResult> check_split(const SplitManifestDocument& doc, const std::optional<std::string>& dataset_path) {
  CheckResult schema = check_split_schema(doc);
  if (schema.status == Status::fail) {
    std::vector<CheckResult> out{std::move(schema)};
    for (const CheckInfo& c : all_checks())
      if (c.id.starts_with("split.") && c.id != "split.schema")
        out.push_back(make_result(c.id, Status::skip, "the manifest does not follow split.schema.json"));
    return out;
  }
  const SplitManifest m = split::parse_split_manifest(doc.json);
  const SplitDataset dataset = open_split_dataset(m, doc.path, dataset_path);
  const std::vector<MaterialSections> sections = material_sections(m);
  const std::vector<Recount> recount = recount_windows(m, sections, dataset);
  return {std::move(schema),
          check_split_hashes(m, dataset),
          check_split_materials(m, dataset),
          check_split_sections(m, sections),
          check_split_sets(m),
          check_split_crossing(m, dataset, recount),
          check_split_coverage(m, dataset, recount),
          check_split_coverage_recorded(m, dataset, recount),
          check_split_presses(m, dataset)};
}

}  // namespace haptex::qa
