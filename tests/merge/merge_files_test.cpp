// merge_files on small hand-made shards: what is copied, how windows are renumbered, what the
// merged file records of its inputs, and what is refused before anything is written.
#include "core/temporary_name.hpp"
#include "merge/merge_files.hpp"

#include <gtest/gtest.h>

#include <cctype>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/sha256.hpp"
#include "dataset/layout.hpp"
#include "dataset/window_table.hpp"
#include "tests/support/bad_input.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::merge {
namespace {

namespace fs = std::filesystem;
using dataset::Kind;
using test::TempDir;

std::string upper(std::string id) {
  for (char& c : id) c = char(std::toupper(static_cast<unsigned char>(c)));
  return id;
}

struct Material {
  std::string id;
  int recordings = 1;
};

// A shard of `kind` with these materials, each holding its recordings (a dataset of its id's length)
// and, for a dataset, one window per recording whose action holds the material's first letter.
std::string shard(const TempDir& dir, const std::string& name, Kind kind, const std::vector<Material>& materials,
                  std::size_t stride = 100) {
  const std::string path = dir.file(name);
  h5::AtomicFile out(path, false);
  h5::Group root = out.root();
  dataset::stamp(root, kind, "haptex test " + name);
  if (kind == Kind::recordings) root.set_attr(dataset::layout::kFieldMap, "map of " + name);
  if (kind == Kind::dataset)
    for (const char* a : {dataset::layout::kRecordingsFile, dataset::layout::kRecordingsSha256, dataset::layout::kGelsightFile,
                          dataset::layout::kGelsightSha256})
      root.set_attr(a, std::string(a) + " of " + name);
  dataset::WindowTable windows;
  windows.stride = stride;
  h5::Group all = root.create_group(dataset::layout::kMaterials);
  for (const Material& m : materials) {
    h5::Group g = all.create_group(m.id);
    g.set_attr(dataset::layout::kName, upper(m.id));  // a name whose id is the group's (qa's layout.required)
    for (int k = 0; k < m.recordings; ++k) {
      g.require_group(dataset::layout::kRecordings).create_group(std::to_string(k))
          .write<float>(dataset::layout::kAccel, std::vector<float>(m.id.size() + std::size_t(k), float(k)));
      windows.material.push_back(std::int32_t(windows.materials.size()));
      windows.recording.push_back(k);
      windows.start.push_back(0);
      windows.action.insert(windows.action.end(), dataset::kActionValues, float(m.id[0]));
      windows.target.insert(windows.target.end(), dataset::kTargetBins, float(k));
    }
    windows.materials.push_back(m.id);
  }
  if (kind == Kind::dataset) dataset::write_window_table(root, windows);
  out.commit();
  return path;
}

MergeOptions options(const std::vector<std::string>& shards, const std::string& output) {
  MergeOptions o;
  o.shards = shards;
  o.output = output;
  o.provenance = "haptex merge (test)";
  o.check_integrity = false;  // skeleton shards: these tests are about the joining rules
  return o;
}

// The refusal's message, after checking that nothing was written.
std::string refusal(const MergeOptions& o) {
  const std::string message = test::bad_input_message([&] { merge_files(o); });
  EXPECT_FALSE(fs::exists(o.output)) << "nothing is written";
  EXPECT_TRUE(temporaries_of(o.output).empty());
  return message;
}

TEST(MergeFiles, CopiesEveryMaterialAndRecordsEachShard) {
  const TempDir dir;
  const std::string a = shard(dir, "a.h5", Kind::gelsight, {{"wood"}, {"cork"}}), b = shard(dir, "b.h5", Kind::gelsight, {{"brick"}});
  const MergeResult r = merge_files(options({a, b}, dir.file("m.h5")));
  EXPECT_EQ(r.kind, Kind::gelsight);
  const h5::File merged = h5::File::open(dir.file("m.h5"));
  const h5::Group root = merged.root();
  EXPECT_EQ(root.attr_string("haptex_format"), "gelsight/2");
  EXPECT_EQ(root.attr_string("source"), "haptex merge (test)");
  const h5::Group materials = root.open_group("materials");
  EXPECT_EQ(materials.children(), (std::vector<std::string>{"brick", "cork", "wood"}));
  EXPECT_EQ(materials.open_group("wood").attr_string("name"), "WOOD");
  EXPECT_EQ(materials.open_group("wood").open_group("recordings").open_group("0").open_dataset(dataset::layout::kAccel).read<float>().size(), 4u);

  const h5::Group first = root.open_group("shards").open_group("0");
  EXPECT_EQ(first.attr_string("file"), a);
  EXPECT_EQ(first.attr_string("sha256"), sha256_file(a));
  EXPECT_EQ(first.attr_string("materials"), "cork wood");
  EXPECT_EQ(first.attr_string("left_out"), "");
  EXPECT_EQ(first.attr_string("source"), "haptex test a.h5");
  EXPECT_EQ(first.attr_string("haptex_format"), "gelsight/2");
  EXPECT_EQ(root.open_group("shards").open_group("1").attr_string("materials"), "brick");
}

TEST(MergeFiles, RenumbersTheWindowsSoEachPointsAtItsMaterial) {
  const TempDir dir;
  const std::string a = shard(dir, "a.h5", Kind::dataset, {{"wood", 1}, {"cork", 2}}), b = shard(dir, "b.h5", Kind::dataset, {{"brick", 2}});
  const MergeResult r = merge_files(options({a, b}, dir.file("m.h5")));
  EXPECT_EQ(r.windows, 5u);
  const h5::File merged = h5::File::open(dir.file("m.h5"));
  const dataset::WindowTable t = dataset::read_window_table(merged);
  EXPECT_EQ(t.materials, (std::vector<std::string>{"brick", "cork", "wood"}));
  EXPECT_EQ(t.material, (std::vector<std::int32_t>{0, 0, 1, 1, 2}));
  EXPECT_EQ(t.recording, (std::vector<std::int32_t>{0, 1, 0, 1, 0}));
  for (std::size_t w = 0; w < t.size(); ++w) {
    EXPECT_EQ(t.action_of(w)[0], float(t.materials[std::size_t(t.material[w])][0])) << "window " << w << " kept its own action";
    EXPECT_EQ(t.target_of(w)[99], float(t.recording[w]));
  }
  const h5::Group root = merged.root();
  EXPECT_EQ(root.attr_string("recordings_file"), "recordings_file of a.h5\nrecordings_file of b.h5");
  EXPECT_EQ(root.attr_string("recordings_sha256"),
            sha256_hex(std::string_view("recordings_sha256 of a.h5\nrecordings_sha256 of b.h5\n")));
  EXPECT_EQ(root.open_group("shards").open_group("1").attr_string("gelsight_sha256"), "gelsight_sha256 of b.h5");
}

TEST(MergeFiles, KeepFirstLeavesOutLaterCopiesAndTheirWindows) {
  const TempDir dir;
  const std::string a = shard(dir, "a.h5", Kind::dataset, {{"cork", 1}}), b = shard(dir, "b.h5", Kind::dataset, {{"cork", 2}, {"felt", 1}});
  MergeOptions o = options({a, b}, dir.file("m.h5"));
  EXPECT_NE(refusal(o).find("material 'cork' is also in " + a), std::string::npos);
  o.keep_first = true;
  const MergeResult r = merge_files(o);
  EXPECT_EQ(r.windows, 2u) << "cork's one window from a.h5, felt's from b.h5";
  const h5::Group root = h5::File::open(dir.file("m.h5")).root();
  EXPECT_EQ(root.open_group("shards").open_group("1").attr_string("left_out"), "cork");
  EXPECT_EQ(root.open_group("materials").open_group("cork").open_group("recordings").children().size(), 1u);
}

TEST(MergeFiles, AMergeOfMergesKeepsEveryInput) {
  const TempDir dir;
  const std::string a = shard(dir, "a.h5", Kind::recordings, {{"cork"}}), b = shard(dir, "b.h5", Kind::recordings, {{"felt"}});
  const std::string c = shard(dir, "c.h5", Kind::recordings, {{"glass"}});
  merge_files(options({a, b}, dir.file("ab.h5")));
  merge_files(options({dir.file("ab.h5"), c}, dir.file("abc.h5")));
  const h5::Group root = h5::File::open(dir.file("abc.h5")).root();
  EXPECT_EQ(root.open_group("materials").children(), (std::vector<std::string>{"cork", "felt", "glass"}));
  EXPECT_EQ(root.attr_string("field_map"), "map of a.h5\nmap of b.h5\nmap of c.h5");
  EXPECT_EQ(root.open_group("shards").open_group("0").open_group("shards").open_group("1").attr_string("file"), b);
}

TEST(MergeFiles, RefusesShardsThatCannotBeJoinedNamingTheFile) {
  const TempDir dir;
  const std::string out = dir.file("m.h5");
  const std::string r = shard(dir, "r.h5", Kind::recordings, {{"cork"}}), g = shard(dir, "g.h5", Kind::gelsight, {{"felt"}});
  const std::string mixed = refusal(options({r, g}, out));
  EXPECT_NE(mixed.find(g + ": /@haptex_format: is gelsight/2, but " + r + " is recordings/1"), std::string::npos) << mixed;

  const std::string empty = refusal(options({r, shard(dir, "e.h5", Kind::recordings, {})}, out));
  EXPECT_NE(empty.find("e.h5: /materials: holds no material"), std::string::npos) << empty;

  const std::string model = refusal(options({r, shard(dir, "model.h5", Kind::model, {{"cork"}})}, out));
  EXPECT_NE(model.find("is 'model/3': haptex merge joins recordings/1, gelsight/2 or dataset/4"), std::string::npos) << model;

  fs::create_symlink(r, dir.file("link.h5"));
  const std::string twice = refusal(options({r, dir.file("link.h5")}, out));
  EXPECT_NE(twice.find("is the same file as " + r), std::string::npos) << twice;

  const std::string extra = shard(dir, "x.h5", Kind::recordings, {{"felt"}});
  h5::File::open(extra, true).root().set_attr("notes", "mine");
  const std::string unknown = refusal(options({r, extra}, out));
  EXPECT_NE(unknown.find("x.h5: /@notes: is not an attribute haptex writes"), std::string::npos) << unknown;
}

TEST(MergeFiles, RefusesDatasetsWhoseWindowsCannotBeJoined) {
  const TempDir dir;
  const std::string out = dir.file("m.h5");
  const std::string a = shard(dir, "a.h5", Kind::dataset, {{"cork"}}), b = shard(dir, "b.h5", Kind::dataset, {{"felt"}}, 50);
  const std::string stride = refusal(options({a, b}, out));
  EXPECT_NE(stride.find("b.h5: /windows/@stride: is 50, but " + a + "'s is 100"), std::string::npos) << stride;

  const std::string lost = shard(dir, "lost.h5", Kind::dataset, {{"felt", 2}});
  {
    h5::File f = h5::File::open(lost, true);
    H5Ldelete(f.root().id(), "materials/felt/recordings/1", H5P_DEFAULT);
  }
  const std::string missing = refusal(options({a, lost}, out));
  // More windows than the recordings left can hold: refused before the table is read (review 12, F4).
  EXPECT_NE(missing.find("lost.h5: /windows/start: has 2 rows, more than the 1 windows its recordings hold"), std::string::npos) << missing;
}

// With the integrity checks on (the default), a skeleton shard is refused by qa's layout check,
// naming the shard and the check.
TEST(MergeFiles, RefusesAShardThatFailsQasIntegrityChecks) {
  const TempDir dir;
  const std::string a = shard(dir, "a.h5", Kind::gelsight, {{"cork"}});
  MergeOptions o = options({a}, dir.file("m.h5"));
  o.check_integrity = true;
  const std::string message = refusal(o);
  EXPECT_NE(message.find(a + ": /materials/cork/presses: missing"), std::string::npos) << message;
  EXPECT_NE(message.find("(qa check layout.required)"), std::string::npos) << message;
}

TEST(MergeFiles, ForceReplacesOnlyAFileHaptexWrote) {
  const TempDir dir;
  const std::string a = shard(dir, "a.h5", Kind::gelsight, {{"cork"}}), b = shard(dir, "b.h5", Kind::gelsight, {{"felt"}});
  std::ofstream(dir.file("notes.h5")) << "my notes";
  MergeOptions o = options({a, b}, dir.file("notes.h5"));
  o.overwrite = true;
  EXPECT_NE(test::bad_input_message([&] { merge_files(o); }).find("--force replaces only a file haptex wrote"), std::string::npos);
  std::ifstream in(dir.file("notes.h5"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "my notes");

  o.output = dir.file("m.h5");
  merge_files(o);
  EXPECT_NO_THROW(merge_files(o)) << "its own output is replaced";
}

}  // namespace
}  // namespace haptex::merge
