// Review 12, F4: split, windows, train and evaluate took a dataset's /windows table as it was, where
// qa (and view) refuse it: targets that are not the recordings' spectra trained the model, a window
// twice was scored twice, and 6 MB declaring 10 million rows cost 5 GB. Each now runs qa's window
// table checks, and every reader refuses more rows than the recordings hold before reading them.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/sha256.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

// A copy of the small pipeline's dataset edited by `edit`, and its split manifest pointing at it, as a
// split made before the edit would (the table, not the manifest, is what is damaged).
struct Damaged {
  std::string dataset, split;
};

Damaged damaged(const TempDir& dir, const std::function<void(Edit&)>& edit) {
  Damaged d{dir.file("d.h5"), dir.file("split.json")};
  fs::copy_file(small_pipeline().dataset, d.dataset, fs::copy_options::overwrite_existing);
  {
    Edit e(d.dataset);
    edit(e);
  }
  nlohmann::json manifest = read_json(small_pipeline().split);
  manifest["dataset"]["sha256"] = sha256_file(d.dataset);
  write_json(d.split, manifest);
  return d;
}

void expect_every_reader_refuses(const TempDir& dir, const Damaged& d, const std::vector<std::string>& mentions) {
  std::vector<std::string> with_file = mentions;
  with_file.insert(with_file.begin(), d.dataset);
  expect_refusal(run_haptex({"split", d.dataset, "-o", dir.file("s2.json"), "--no-plots"}), with_file);
  expect_refusal(run_haptex({"windows", d.dataset, "--split", d.split, "-o", dir.file("w.h5")}), with_file);
  expect_refusal(run_haptex(quick_train_args(d.dataset, d.split, dir.file("m.h5"))), with_file);
  expect_refusal(run_haptex({"evaluate", d.dataset, "--split", d.split, "--model", quick_model(), "-o", dir.file("r")}), with_file);
  const CommandResult qa = run_haptex({"qa", d.dataset});
  EXPECT_EQ(qa.exit_code, 1) << "qa finds the same";
  EXPECT_NE(qa.out.find(mentions.back()), std::string::npos) << qa.out;
  for (const char* out : {"s2.json", "w.h5", "m.h5", "r"}) EXPECT_FALSE(fs::exists(dir.file(out))) << out;
}

TEST(WindowTable, TargetsThatAreNotTheRecordingsSpectraAreRefused) {
  const TempDir dir;
  const Damaged d = damaged(dir, [](Edit& e) {
    e.change_floats("windows/target", [](std::vector<float>& t) {
      for (std::size_t k = 1000; k < 1100; ++k) t[k] *= 3;  // row 10
    });
  });
  expect_every_reader_refuses(dir, d, {"/windows[10]", "dataset.cache"});
}

TEST(WindowTable, MoreRowsThanTheRecordingsHoldAreRefusedBeforeTheyAreRead) {
  const TempDir dir;
  const Damaged d = damaged(dir, [](Edit& e) {
    const auto doubled = [&](const char* column, auto zero) {
      using T = decltype(zero);
      const h5::Dataset data = e.dataset(std::string("windows/") + column);
      h5::Shape shape = data.shape();
      std::vector<T> values = data.read<T>();
      values.insert(values.end(), values.begin(), values.end());
      shape[0] *= 2;
      e.replace<T>(std::string("windows/") + column, values, shape);
    };
    doubled("start", std::int64_t());
    doubled("material", std::int32_t());
    doubled("recording", std::int32_t());
    doubled("action", float());
    doubled("target", float());
  });
  expect_every_reader_refuses(dir, d, {"rows, more than the", "windows its recordings hold"});
}

}  // namespace
}  // namespace haptex::test
