// Issue 11 point 4: one validation of a split manifest against its dataset (the split.* checks of
// haptex qa) runs in split before it writes, and in train and evaluate before they read: a leaky,
// out-of-range or empty split is exit code 2 naming the material and the sections.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/pipeline_fixture.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

struct SplitDamage {
  std::string name;
  std::function<void(nlohmann::json& material)> edit;
  std::string says;
};

TEST(LeakySplit, TrainAndEvaluateRefuseAHandEditedManifest) {
  const std::vector<SplitDamage> damages = {
      {"a section in two sets", [](nlohmann::json& m) { m["sections"]["test"].push_back(m["sections"]["train"][0]); }, "is in both train and test"},
      {"test sections = training sections", [](nlohmann::json& m) { m["sections"]["test"] = m["sections"]["train"]; }, "is in both train and test"},
      {"a section out of range", [](nlohmann::json& m) { m["sections"]["val"].push_back(99999); }, "section 99999 in val is outside"},
      {"an empty test set", [](nlohmann::json& m) { m["sections"]["test"] = nlohmann::json::array(); }, "nothing in test"},
  };
  const SmallPipeline& p = small_pipeline();
  const std::string id = read_json(p.split)["materials"][1]["id"];
  for (const SplitDamage& damage : damages) {
    SCOPED_TRACE(damage.name);
    const TempDir dir;
    nlohmann::json manifest = read_json(p.split);
    damage.edit(manifest["materials"][1]);
    write_json(dir.file("split.json"), manifest);
    const CommandResult train = run_haptex(quick_train_args(p.dataset, dir.file("split.json"), dir.file("m.h5")));
    expect_refusal(train, {dir.file("split.json"), id, damage.says});
    EXPECT_FALSE(fs::exists(dir.file("m.h5")));
    const CommandResult evaluate =
        run_haptex({"evaluate", p.dataset, "--split", dir.file("split.json"), "--model", quick_model(), "-o", dir.file("report")});
    expect_refusal(evaluate, {dir.file("split.json"), id, damage.says});
    EXPECT_FALSE(fs::exists(dir.file("report")));
    EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
  }
}

TEST(LeakySplit, SplitRefusesSectionsSoShortEveryWindowCrossesOne) {
  const TempDir dir;
  const CommandResult r = run_haptex({"split", small_pipeline().dataset, "-o", dir.file("split.json"), "--sections", "10000", "--no-plots"});
  expect_refusal(r, {small_pipeline().dataset, "nothing in train", "Nothing was written"});
  EXPECT_FALSE(fs::exists(dir.file("split.json")));
}

TEST(LeakySplit, SplitRefusesAMaterialWithOneHalfSecondRecording) {
  PipelineFiles files;
  make_pipeline_dataset(files, {0.5});
  const CommandResult r = run_haptex({"split", files.dataset, "-o", files.dir.file("split.json"), "--no-plots"});
  EXPECT_EQ(r.exit_code, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("nothing in"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(files.dir.file("split.json")));
}

// Review 6: capture extract took a video given twice (or once more through a linked folder) as more
// presses, which split put in train and val, and poured folders "Woven 1" and "woven-1" into one
// material; qa called both files clean.
TEST(LeakySplit, ExtractRefusesAVideoTwiceAndTwoSpellingsOfOneMaterial) {
  const TempDir dir;
  ASSERT_EQ(run_haptex({"synth", "materials", "-n", "2", "--presses", "2", "--recordings", "1", "--seconds", "0.5", "--size", "64x48",
                        "-o", dir.file("s")}).exit_code, 0);
  const std::string woven = dir.file("s/gelsight/Polished 1"), video = woven + "/press_0.avi";
  fs::create_directories(dir.file("linked"));
  fs::create_directory_symlink(woven, dir.file("linked/Polished 1 link"));
  fs::copy(woven, dir.file("linked/Polished 1"));
  fs::create_directories(dir.file("spelled"));
  fs::copy(dir.file("s/gelsight/Sandpaper 1"), dir.file("spelled/polished-1"));
  fs::copy(woven, dir.file("spelled/Polished 1"));
  // Review 13, C6: a folder name's newline was printed raw in the message (the file's was escaped).
  fs::create_directories(dir.file("newline"));
  fs::copy(dir.file("s/gelsight/Sandpaper 1"), dir.file("newline/Polished 1\n"));
  fs::copy(woven, dir.file("newline/Polished 1"));
  // Review 8: a copy with 4 bytes appended has its own SHA-256 and the same frames. Extraction takes
  // it (identical noiseless test videos are common); qa's gelsight.duplicate compares peak images.
  const std::string appended = dir.file("appended.avi");
  fs::copy_file(video, appended);
  std::ofstream(appended, std::ios::app) << "JUNK";
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
      {{video, video}, {"is the same file as", video, "Give each video once"}},
      {{woven, video}, {"is the same file as", "Give each video once"}},
      {{dir.file("linked")}, {"is the same file as", "Polished 1 link"}},
      {{dir.file("spelled")}, {"make one material id, polished_1", "'polished-1'", "'Polished 1'"}},
      {{dir.file("newline")}, {"make one material id, polished_1", "'Polished 1\\x0a'"}},
  };
  for (const auto& [inputs, says] : cases) {
    SCOPED_TRACE(says.front() + " " + inputs.front());
    std::vector<std::string> args{"capture", "extract"};
    args.insert(args.end(), inputs.begin(), inputs.end());
    for (const char* more : {"--no-sheets", "-o"}) args.push_back(more);
    args.push_back(dir.file("g.h5"));
    expect_refusal(run_haptex(args), says);
    EXPECT_FALSE(fs::exists(dir.file("g.h5")));
  }
  ASSERT_EQ(run_haptex({"capture", "extract", video, appended, "--material", "Polished 1", "--no-sheets", "-o", dir.file("a.h5")}).exit_code, 0);
  const CommandResult appended_qa = run_haptex({"qa", dir.file("a.h5")});
  EXPECT_NE(appended_qa.out.find("has the peak image of /materials/polished_1/presses/0"), std::string::npos) << appended_qa.out;

  // A press copied within a file (as a merge of two extractions of one video would): qa's gelsight.duplicate.
  const std::string copied = copy_into(dir, small_pipeline().gelsight, "g.h5");
  {
    Edit edit(copied);
    const std::string presses = "materials/" + material_ids(copied).front() + "/presses";
    const std::size_t count = edit.group(presses).children().size();
    ASSERT_GE(H5Ocopy(edit.root().id(), (presses + "/0").c_str(), edit.root().id(), (presses + "/" + std::to_string(count)).c_str(),
                      H5P_DEFAULT, H5P_DEFAULT), 0);
  }
  const CommandResult qa = run_haptex({"qa", copied});
  EXPECT_EQ(qa.exit_code, 1);
  EXPECT_NE(qa.out.find("gelsight.duplicate"), std::string::npos) << qa.out;
  EXPECT_NE(qa.out.find("of the same source file"), std::string::npos) << qa.out;
  // The copy from a video with other bytes: another source SHA-256, the same peak image (review 8).
  {
    Edit edit(copied);
    const std::string presses = "materials/" + material_ids(copied).front() + "/presses";
    const std::size_t last = edit.group(presses).children().size() - 1;
    edit.group(presses + "/" + std::to_string(last)).set_attr("source_sha256", std::string(64, 'a'));
  }
  const CommandResult copy = run_haptex({"qa", copied});
  EXPECT_EQ(copy.exit_code, 1);
  EXPECT_NE(copy.out.find("has the peak image of"), std::string::npos) << copy.out;
  // Review 8: align still built a dataset of it, and merge took it as a shard. Both now refuse it, as
  // they do a recording given twice.
  const std::string recordings = copy_into(dir, small_pipeline().recordings, "r.h5");
  expect_refusal(run_haptex({"align", "--recordings", recordings, "--gelsight", copied, "-o", dir.file("d.h5")}),
                 {"gelsight.duplicate", "has the peak image of"});
  expect_refusal(run_haptex({"merge", copied, dir.file("a.h5"), "-o", dir.file("m.h5")}), {"gelsight.duplicate"});
  {
    Edit edit(recordings);
    const std::string material = "materials/" + material_ids(recordings).front() + "/recordings";
    const std::size_t count = edit.group(material).children().size();
    ASSERT_GE(H5Ocopy(edit.root().id(), (material + "/0").c_str(), edit.root().id(), (material + "/" + std::to_string(count)).c_str(),
                      H5P_DEFAULT, H5P_DEFAULT), 0);
  }
  expect_refusal(run_haptex({"align", "--recordings", recordings, "--gelsight", small_pipeline().gelsight, "-o", dir.file("d.h5")}),
                 {"recordings.duplicate", "the same source file"});
  EXPECT_FALSE(fs::exists(dir.file("d.h5")));
  EXPECT_FALSE(fs::exists(dir.file("m.h5")));
}

}  // namespace
}  // namespace haptex::test
