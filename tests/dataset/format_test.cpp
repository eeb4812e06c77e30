// One place checks what kind of haptex file a reader was given (dataset/format.hpp).
#include "dataset/format.hpp"

#include <gtest/gtest.h>

#include <functional>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "tests/support/bad_input.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::dataset {
namespace {

std::string file_with_format(const test::TempDir& dir, const std::string& name, const std::string& format) {
  const std::string path = dir.file(name);
  h5::AtomicFile out(path, false);
  if (!format.empty()) h5::stamp_root(out.root(), format, "test");
  out.commit();
  return path;
}

std::string refusal(const std::function<void()>& open) {
  try {
    open();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    return e.what();
  }
  return "";
}

std::string refusal(const std::string& path, Kind kind) {
  return refusal([&] { open_checked(path, kind); });
}

TEST(Format, NamesAndKindsAgree) {
  EXPECT_EQ(format_name(Kind::dataset), "dataset/4");
  EXPECT_EQ(format_name(Kind::recordings), "recordings/1");
  EXPECT_EQ(format_name(Kind::model), "model/3");
  EXPECT_EQ(format_name(Kind::windows), "windows/2");
  const std::vector<Kind> merged = {Kind::recordings, Kind::gelsight, Kind::dataset};
  EXPECT_EQ(format_list(merged), "recordings/1, gelsight/2 or dataset/4");
  EXPECT_EQ(format_list(merged, " and "), "recordings/1, gelsight/2 and dataset/4");
}

TEST(Format, OpenAnyTakesEachKindItNamesAndNamesThemForAnother) {
  const test::TempDir dir;
  const std::vector<Kind> kinds = {Kind::recordings, Kind::dataset};
  EXPECT_EQ(open_any(file_with_format(dir, "d.h5", "dataset/4"), kinds, "x reads", "fix").kind, Kind::dataset);
  EXPECT_EQ(open_any(file_with_format(dir, "r.h5", "recordings/1"), kinds, "x reads", "fix").kind, Kind::recordings);
  const std::string path = file_with_format(dir, "m.h5", "model/3");
  EXPECT_EQ(refusal([&] { open_any(path, kinds, "x reads", "Give one of those"); }),
            path + ": /@haptex_format: is 'model/3': x reads recordings/1 or dataset/4 files. Give one of those");
  EXPECT_NE(refusal([&] { open_any(file_with_format(dir, "d3.h5", "dataset/3"), kinds, "x reads", "fix"); }).find("older haptex"),
            std::string::npos);
}

TEST(Format, OpensTheRightKindAndRefusesEveryOtherWithTheFix) {
  const test::TempDir dir;
  const std::string name = "it's \"a\" `file`.h5";  // quotes and back-quotes reach no shell
  EXPECT_NO_THROW(open_checked(file_with_format(dir, name, "dataset/4"), Kind::dataset));

  const std::string older = refusal(file_with_format(dir, "old.h5", "dataset/1"), Kind::dataset);
  EXPECT_NE(older.find("old.h5"), std::string::npos) << older;
  EXPECT_NE(older.find("/@haptex_format"), std::string::npos) << older;
  EXPECT_NE(older.find("older haptex"), std::string::npos) << older;
  EXPECT_NE(older.find("haptex align again"), std::string::npos) << older;

  // gelsight/1 and dataset/2 stored the press images as pixels.
  const std::string pixels = refusal(file_with_format(dir, "g1.h5", "gelsight/1"), Kind::gelsight);
  EXPECT_NE(pixels.find("as pixels"), std::string::npos) << pixels;
  EXPECT_NE(pixels.find("Run haptex capture extract again to write gelsight/2"), std::string::npos) << pixels;
  const std::string dataset2 = refusal(file_with_format(dir, "d2.h5", "dataset/2"), Kind::dataset);
  EXPECT_NE(dataset2.find("dataset/2 stored the press images as pixels"), std::string::npos) << dataset2;
  // dataset/3 and model/2 took the 1 ms at the window's middle as the action.
  const std::string dataset3 = refusal(file_with_format(dir, "d3.h5", "dataset/3"), Kind::dataset);
  EXPECT_NE(dataset3.find("dataset/3 took the 1 ms at the window's middle"), std::string::npos) << dataset3;
  EXPECT_NE(dataset3.find("Run haptex align again to write dataset/4"), std::string::npos) << dataset3;
  const std::string model2 = refusal(file_with_format(dir, "m2.h5", "model/2"), Kind::model);
  EXPECT_NE(model2.find("Run haptex train again to write model/3"), std::string::npos) << model2;

  const std::string other = refusal(file_with_format(dir, "rec.h5", "recordings/1"), Kind::dataset);
  EXPECT_NE(other.find("'recordings/1': a recordings file (haptex convert writes those), not a dataset file (dataset/4)"), std::string::npos) << other;
  EXPECT_NE(other.find("haptex align wrote"), std::string::npos) << other;

  // Review 15, R2: a version that is no plain decimal was "a recordings file ..., not a recordings file".
  int n = 0;
  for (const std::string bad : {"recordings/01", "recordings/-1", "recordings/+1", "recordings/ 1", "recordings/99999999999999999999"}) {
    const std::string edited = refusal(file_with_format(dir, "edited" + std::to_string(++n) + ".h5", bad), Kind::recordings);
    EXPECT_NE(edited.find("is '" + bad + "', which is no version haptex writes (recordings/N"), std::string::npos) << edited;
    EXPECT_NE(edited.find("Make the file again with haptex convert"), std::string::npos) << edited;
  }

  const std::string plain = refusal(file_with_format(dir, "plain.h5", ""), Kind::model);
  EXPECT_NE(plain.find("no haptex_format"), std::string::npos) << plain;
  EXPECT_NE(plain.find("haptex train"), std::string::npos) << plain;

  std::ofstream(dir.file("text.h5")) << "not HDF5";
  EXPECT_NE(refusal(dir.file("text.h5"), Kind::gelsight).find("text.h5"), std::string::npos);
  EXPECT_NE(refusal(dir.file("missing.h5"), Kind::gelsight).find("missing.h5"), std::string::npos);
}

// --force replaces a file only when haptex wrote it as an earlier output of the kind being written; a
// user's file, another kind of haptex file and a newer haptex's file are left alone.
TEST(Format, OnlyAnEarlierFileOfTheSameKindIsReplaceable) {
  const test::TempDir dir;
  EXPECT_NO_THROW(h5::require_replaceable(dir.file("new.h5"), "recordings/2"));
  EXPECT_NO_THROW(h5::require_replaceable(file_with_format(dir, "ours.h5", "recordings/1"), "recordings/2"));
  EXPECT_NO_THROW(h5::require_replaceable(file_with_format(dir, "same.h5", "recordings/2"), "recordings/2"));
  std::ofstream(dir.file("notes.h5")) << "my notes";
  const std::vector<std::pair<std::string, std::string>> refused = {
      {dir.file("notes.h5"), "--force replaces only a file haptex wrote as an earlier recordings/2 output"},
      {file_with_format(dir, "plain.h5", ""), "--force replaces only a file haptex wrote as an earlier recordings/2 output"},
      {file_with_format(dir, "gel.h5", "gelsight/2"), "is a gelsight/2 file; this command writes recordings/2"},
      {file_with_format(dir, "newer.h5", "recordings/3"), "is recordings/3, written by a newer haptex"},
  };
  for (const auto& [theirs, says] : refused) {
    const std::string message = test::bad_input_message([&] { h5::require_replaceable(theirs, "recordings/2"); });
    EXPECT_NE(message.find(theirs + ": " + says), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace haptex::dataset
