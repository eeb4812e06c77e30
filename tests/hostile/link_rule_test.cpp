// The link rule (core/h5/link_rule.hpp) holds in every reader: a file with a dataset kept outside it
// (external raw storage on a FIFO or /dev/zero, a virtual dataset), a soft-linked dataset or a
// recording linked twice is refused by split, train, windows, merge and align before any value is
// read, and qa reports it under layout.links and reads nothing more (review 4, findings 2 and 4:
// qa, merge and align hung on the FIFO, qa called the external and virtual files clean, split and
// train took the soft and hard links); so are a named datatype and a dataset declaring more than
// haptex reads at once (review 10, F1: qa called them clean, merge refused them).
#include <gtest/gtest.h>

#include <hdf5.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "core/sha256.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

// The first recording's accel of `file`'s first material.
std::string accel_path(const std::string& file) { return "materials/" + material_ids(file).front() + "/recordings/0/accel"; }

// Replaces `path` by a float32 dataset of `values` values stored in `outside` (an external raw file).
void store_outside(const std::string& file, const std::string& path, const std::string& outside, hsize_t values) {
  Edit edit(file);
  edit.remove(path);
  const hid_t space = H5Screate_simple(1, &values, nullptr), list = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_external(list, outside.c_str(), 0, values * 4);
  const hid_t d = H5Dcreate2(edit.root().id(), path.c_str(), H5T_NATIVE_FLOAT, space, H5P_DEFAULT, list, H5P_DEFAULT);
  H5Dclose(d), H5Pclose(list), H5Sclose(space);
}

// Replaces `path` by a virtual dataset mapping the same path of `source`.
void make_virtual(const std::string& file, const std::string& path, const std::string& source, hsize_t values) {
  Edit edit(file);
  edit.remove(path);
  const hid_t space = H5Screate_simple(1, &values, nullptr), list = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_virtual(list, space, source.c_str(), ("/" + path).c_str(), space);
  const hid_t d = H5Dcreate2(edit.root().id(), path.c_str(), H5T_NATIVE_FLOAT, space, H5P_DEFAULT, list, H5P_DEFAULT);
  H5Dclose(d), H5Pclose(list), H5Sclose(space);
}

hsize_t values_of(const std::string& file, const std::string& path) {
  Edit edit(file);
  return edit.dataset(path).shape().at(0);
}

struct Breach {
  std::string name;
  std::function<void(const std::string& file, const std::string& accel)> make;
  std::string says;
};

std::vector<Breach> breaches(const TempDir& dir) {
  const std::string fifo = dir.file("values.fifo");
  if (!fs::exists(fifo)) mkfifo(fifo.c_str(), 0600);
  return {
      {"fifo", [fifo](const std::string& f, const std::string& a) { store_outside(f, a, fifo, values_of(f, a)); }, "outside the file"},
      {"zero", [](const std::string& f, const std::string& a) { store_outside(f, a, "/dev/zero", values_of(f, a)); }, "outside the file"},
      {"virtual", [](const std::string& f, const std::string& a) { make_virtual(f, a, small_pipeline().dataset, values_of(f, a)); },
       "outside the file"},
      // Review 5: info and qa followed an external link to a FIFO and hung.
      {"external", [fifo](const std::string& f, const std::string& a) {
         Edit edit(f);
         const std::string lp = a.substr(0, a.rfind('/')) + "/speed_lp";
         edit.remove(lp);
         H5Lcreate_external(fifo.c_str(), "/x", edit.root().id(), lp.c_str(), H5P_DEFAULT, H5P_DEFAULT);
       }, "an external link"},
      {"soft", [](const std::string& f, const std::string& a) {
         Edit edit(f);
         const std::string lp = a.substr(0, a.rfind('/')) + "/speed_lp", speed = "/" + a.substr(0, a.rfind('/')) + "/speed";
         edit.remove(lp);
         H5Lcreate_soft(speed.c_str(), edit.root().id(), lp.c_str(), H5P_DEFAULT, H5P_DEFAULT);
       }, "soft link"},
      {"hard", [](const std::string& f, const std::string&) {
         const std::vector<std::string> ids = material_ids(f);
         Edit edit(f);
         const std::string twice = "materials/" + ids.back() + "/recordings/0", first = "materials/" + ids.front() + "/recordings/0";
         edit.remove(twice);
         H5Lcreate_hard(edit.root().id(), first.c_str(), edit.root().id(), twice.c_str(), H5P_DEFAULT, H5P_DEFAULT);
       }, "second link to"},
      // Review 10, F1: qa called clean a file holding a named datatype, or an extra dataset declaring 4 TiB
      // (chunked, never written: the file stays small), which merge refused.
      {"named_type", [](const std::string& f, const std::string& a) {
         Edit edit(f);
         const hid_t type = H5Tcopy(H5T_NATIVE_DOUBLE);
         H5Tcommit2(edit.root().id(), (a.substr(0, a.rfind('/')) + "/mytype").c_str(), type, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
         H5Tclose(type);
       }, "neither a group nor a dataset"},
      {"declared_4_tib", [](const std::string& f, const std::string& a) {
         Edit edit(f);
         const hsize_t values = hsize_t(1) << 40, chunk = 4096;
         const hid_t space = H5Screate_simple(1, &values, nullptr), list = H5Pcreate(H5P_DATASET_CREATE);
         H5Pset_chunk(list, 1, &chunk);
         const hid_t d = H5Dcreate2(edit.root().id(), (a.substr(0, a.rfind('/')) + "/junk").c_str(), H5T_NATIVE_FLOAT, space, H5P_DEFAULT,
                                    list, H5P_DEFAULT);
         H5Dclose(d), H5Pclose(list), H5Sclose(space);
       }, "more than haptex reads at once (4 GiB). The file is damaged or not what haptex wrote: remove the dataset"},  // qa too (review 15, R4)
      // Review 5: 40 000 attributes on one object took info minutes (each found by reading those before it).
      {"attributes", [](const std::string& f, const std::string& a) {
         Edit edit(f);
         h5::Group recording = edit.group(a.substr(0, a.rfind('/')));
         for (int i = 0; i < 1001; ++i) recording.set_attr("extra_" + std::to_string(i), double(i));
       }, "holds 10"},
  };
}

// The small pipeline's split, made to name `file` by its SHA-256, so train and windows get past the
// split's hash to the file itself (split refuses to make one).
std::string split_naming(const TempDir& dir, const std::string& file) {
  std::string text = file_bytes(small_pipeline().split);
  const std::string old_hash = sha256_file(small_pipeline().dataset), new_hash = sha256_file(file);
  for (std::size_t at = text.find(old_hash); at != std::string::npos; at = text.find(old_hash, at)) text.replace(at, old_hash.size(), new_hash);
  const std::string path = dir.file(fs::path(file).stem().string() + ".split.json");
  std::ofstream(path) << text;
  return path;
}

// A hang is exit 124 here, not a test that never ends.
CommandResult run_bounded(std::vector<std::string> args) {
  args.insert(args.begin(), {"timeout", "60", haptex_binary()});
  return run_program(args);
}

TEST(LinkRule, EveryReaderOfADatasetFileRefusesABreachBeforeReadingAValue) {
  const TempDir dir;
  for (const Breach& breach : breaches(dir)) {
    SCOPED_TRACE(breach.name);
    const std::string file = copy_into(dir, small_pipeline().dataset, breach.name + ".h5");
    breach.make(file, accel_path(file));
    const CommandResult qa = run_bounded({"qa", file});
    EXPECT_EQ(qa.exit_code, 1) << qa.err;
    EXPECT_NE(qa.out.find("layout.links"), std::string::npos) << qa.out;
    EXPECT_NE(qa.out.find(breach.says), std::string::npos) << qa.out;
    EXPECT_EQ(qa.out.find("signal.nan"), std::string::npos) << "no other check runs: " << qa.out;
    expect_refusal(run_bounded({"info", file}), {file, breach.says});
    const std::string out = dir.file(breach.name + "_out"), split = split_naming(dir, file);
    for (const std::vector<std::string>& command : std::vector<std::vector<std::string>>{
             {"split", file, "-o", out + ".json", "--no-plots"},
             quick_train_args(file, split, out + ".model.h5"),
             {"windows", file, "--split", split, "-o", out + ".windows.h5"},
             {"merge", file, "-o", out + ".merged.h5"}}) {
      SCOPED_TRACE(command.front());
      expect_refusal(run_bounded(command), {file, breach.says});
    }
  }
  EXPECT_EQ(partial_files(dir.path().string()), std::vector<std::string>{});
}

TEST(LinkRule, AlignRefusesARecordingKeptOnAFifo) {
  const TempDir dir;
  const std::string recordings = copy_into(dir, small_pipeline().recordings, "r.h5");
  store_outside(recordings, accel_path(recordings), dir.file("values.fifo"), values_of(recordings, accel_path(recordings)));
  mkfifo(dir.file("values.fifo").c_str(), 0600);
  expect_refusal(run_bounded({"align", "--recordings", recordings, "--gelsight", small_pipeline().gelsight, "-o", dir.file("a.h5")}),
                 {recordings, "/recordings/0/accel", "outside the file"});
  EXPECT_FALSE(fs::exists(dir.file("a.h5")));
}

}  // namespace
}  // namespace haptex::test
