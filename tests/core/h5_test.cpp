#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>

#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/temporary_name.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::h5 {
namespace {

using test::TempDir;

TEST(H5, DatasetsOfAnyRankRoundTrip) {
  TempDir dir;
  const std::string path = dir.file("a.h5");
  std::vector<double> line(1000);
  std::iota(line.begin(), line.end(), 0.5);
  std::vector<float> matrix(300 * 3);
  std::iota(matrix.begin(), matrix.end(), -10.0f);
  std::vector<std::uint8_t> cube(4 * 5 * 3, 7);
  {
    AtomicFile out(path, false);
    Group g = out.root().create_group("materials").create_group("book");
    g.write("line", line);
    g.write_array<float>("matrix", matrix, {300, 3});
    g.write_array<std::uint8_t>("cube", cube, {4, 5, 3}, DatasetOptions{.compress = false, .chunk = {}});
    g.write<double>("empty", std::vector<double>{});
    g.write_strings("names", {"Book", "Brick 2", "Ünïcode"});
    out.commit();
  }
  File in = File::open(path);
  Group g = in.root().open_group("materials").open_group("book");
  EXPECT_EQ(g.open_dataset("line").read<double>(), line);
  auto m = g.open_dataset("matrix");
  EXPECT_EQ(m.shape(), (Shape{300, 3}));
  EXPECT_EQ(m.dtype(), "float32");
  EXPECT_EQ(m.read<float>(), matrix);
  EXPECT_EQ(g.open_dataset("cube").shape(), (Shape{4, 5, 3}));
  EXPECT_EQ(g.open_dataset("cube").read<std::uint8_t>(), cube);
  EXPECT_EQ(g.open_dataset("empty").elements(), 0u);
  EXPECT_EQ(g.open_dataset("names").read_strings(), (std::vector<std::string>{"Book", "Brick 2", "Ünïcode"}));
}

// Review 17, F7: h5py writes numpy bytes arrays as fixed-length strings; they read as the
// variable-length ones do, and what is no text says so (it was "truncated or damaged").
TEST(H5, FixedLengthStringDatasetsRead) {
  TempDir dir;
  const std::string path = dir.file("fixed.h5");
  {
    AtomicFile out(path, false);
    out.root().write("numbers", std::vector<double>{1.0});
    out.commit();
  }
  {
    test::Edit edit(path);
    edit.write_fixed_strings("names", {"Book", "Brick 2", "\xC3\x9Cn"});
    edit.write_fixed_strings("nul", {"Book", std::string("Bri\0ck", 6)});
    edit.write_fixed_strings("long", {std::string(kLongestFixedString + 1, 'x')});  // review 18, F8
    edit.write_fixed_strings("spaces", {"Book", "Brick 2"}, false, true);           // review 18, F10
    edit.write_fixed_strings("@label", {"Brick 2"}, false, true);
  }
  const Group root = File::open(path).root();
  EXPECT_EQ(root.open_dataset("names").read_strings(), (std::vector<std::string>{"Book", "Brick 2", "Ün"}));
  EXPECT_EQ(root.open_dataset("spaces").read_strings(), (std::vector<std::string>{"Book", "Brick 2"}));
  EXPECT_EQ(root.attr_string("label"), "Brick 2");
  const auto refusal = [&](const std::string& name) {
    try {
      root.open_dataset(name).read_strings();
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(refusal("nul").find("element 1 holds a NUL byte inside its text"), std::string::npos) << refusal("nul");
  EXPECT_NE(refusal("numbers").find("holds float64 values, not text"), std::string::npos) << refusal("numbers");
  EXPECT_NE(refusal("long").find("declares fixed-length strings of 65537 bytes each, over the 64 KiB"), std::string::npos)
      << refusal("long");
}

// Review 21, F3: 3.5 million names of 1 KiB declared in a few hundred KB of unwritten chunks ran out of
// memory; review 20, F1: a name of 60 MB was read and copied whole. Both are refused, naming the object.
TEST(H5, AbsurdTextIsRefusedBeforeItIsCopied) {
  TempDir dir;
  const std::string path = dir.file("big.h5");
  {
    AtomicFile out(path, false);
    out.root().set_attr("long", std::string(kLongestText + 1, 'x'));
    out.root().write_strings("fine", std::vector<std::string>{"Book", "Brick 2"});
    out.commit();
  }
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hsize_t dims[1] = {3500000}, chunk[1] = {16000};
    const hid_t type = H5Tcopy(H5T_C_S1), space = H5Screate_simple(1, dims, nullptr), plist = H5Pcreate(H5P_DATASET_CREATE);
    H5Tset_size(type, 1024);
    H5Pset_chunk(plist, 1, chunk);
    H5Pset_deflate(plist, 1);
    H5Dclose(H5Dcreate2(file, "names", type, space, H5P_DEFAULT, plist, H5P_DEFAULT));
    H5Pclose(plist), H5Sclose(space), H5Tclose(type), H5Fclose(file);
  }
  EXPECT_LT(std::filesystem::file_size(path), kLongestText + (std::uintmax_t(1) << 20));  // the names: unwritten chunks
  const Group root = File::open(path).root();
  EXPECT_EQ(root.open_dataset("fine").read_strings(), (std::vector<std::string>{"Book", "Brick 2"}));
  try {
    root.open_dataset("names").read_strings();
    ADD_FAILURE() << "3.5 million names read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/names: holds 3500000 strings of 1024 bytes, more than a list of names"), std::string::npos) << e.what();
  }
  try {
    root.attr_string("long");
    ADD_FAILURE() << "5 MB of text read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("attribute 'long' holds 4194305 bytes of text, over the 4 MiB"), std::string::npos) << e.what();
  }
}

TEST(H5, CompressedDatasetsUseGzipAndShuffle) {
  TempDir dir;
  const std::string path = dir.file("c.h5");
  {
    AtomicFile out(path, false);
    out.root().write("x", std::vector<double>(100000, 1.0));
    out.commit();
  }
  EXPECT_LT(std::filesystem::file_size(path), 100000u);  // 800 kB of ones compress to almost nothing
  File in = File::open(path);
  Handle plist(H5Dget_create_plist(in.root().open_dataset("x").id()));
  ASSERT_EQ(H5Pget_nfilters(plist.get()), 2);
  unsigned flags = 0, cd[4];
  size_t n = 4;
  EXPECT_EQ(H5Pget_filter2(plist.get(), 0, &flags, &n, cd, 0, nullptr, nullptr), H5Z_FILTER_SHUFFLE);
  n = 4;
  EXPECT_EQ(H5Pget_filter2(plist.get(), 1, &flags, &n, cd, 0, nullptr, nullptr), H5Z_FILTER_DEFLATE);
}

TEST(H5, AttributesRoundTrip) {
  TempDir dir;
  const std::string path = dir.file("attrs.h5");
  {
    AtomicFile out(path, false);
    Group root = out.root();
    root.set_attr("rate", 10000.0);
    root.set_attr("count", 42);
    root.set_attr("units", "m/s^2");
    root.set_attr("name", std::string("Brick 2 — grès"));
    const std::vector<double> corners = {1.5, 2.5};
    root.set_attr("corners", corners);
    root.set_attr("rate", 20000.0);  // overwriting replaces
    stamp_root(root, "recordings/1", "unit test");
    out.commit();
  }
  Group root = File::open(path).root();
  EXPECT_EQ(root.attr_double("rate"), 20000.0);
  EXPECT_EQ(root.attr_int("count"), 42);
  EXPECT_EQ(root.attr_double("count"), 42.0);
  EXPECT_EQ(root.attr_string("units"), "m/s^2");
  EXPECT_EQ(root.attr_string("name"), "Brick 2 — grès");
  EXPECT_EQ(root.attr_doubles("corners"), (std::vector<double>{1.5, 2.5}));
  EXPECT_EQ(root.attr_string("haptex_format"), "recordings/1");
  EXPECT_EQ(root.attr_string("created_utc").size(), 20u);
  EXPECT_THROW(root.attr_int("units"), Error);
  EXPECT_THROW(root.attr_double("corners"), Error);  // two values where one is expected
  try {
    root.attr_string("missing");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("attribute 'missing' is missing"), std::string::npos);
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
  }
}

TEST(H5, ChildrenSortNumbersNumerically) {
  TempDir dir;
  AtomicFile out(dir.file("n.h5"), false);
  Group g = out.root();
  for (const char* name : {"10", "2", "1", "beta", "alpha"}) g.create_group(name);
  EXPECT_EQ(g.children(), (std::vector<std::string>{"1", "2", "10", "alpha", "beta"}));
  EXPECT_TRUE(g.has_group("10"));
  EXPECT_FALSE(g.has_dataset("10"));
  EXPECT_THROW(g.open_dataset("10"), Error);
}

TEST(H5, SameContentGivesSameBytes) {
  TempDir dir;
  setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  for (const char* name : {"one.h5", "two.h5"}) {
    AtomicFile out(dir.file(name), false);
    stamp_root(out.root(), "recordings/1", "test");
    out.root().create_group("g").write("x", std::vector<double>{1, 2, 3});
    out.commit();
  }
  unsetenv("SOURCE_DATE_EPOCH");
  auto bytes = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(dir.file("one.h5")), bytes(dir.file("two.h5")));
}

TEST(H5, UncommittedFileLeavesNothing) {
  TempDir dir;
  const std::string path = dir.file("never.h5");
  {
    AtomicFile out(path, false);
    out.root().write("x", std::vector<double>{1, 2, 3});
    EXPECT_EQ(temporaries_of(path), std::vector<std::string>{out.partial_path()});
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(temporaries_of(path).empty());
}

TEST(H5, SecondWriterOfTheSameOutputIsRefused) {
  TempDir dir;
  const std::string path = dir.file("busy.h5");
  AtomicFile first(path, false);
  first.root().write("x", std::vector<double>{1, 2, 3});
  try {
    AtomicFile second(path, true, "recordings/1");
    FAIL() << "a second writer was allowed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("another haptex run is writing"), std::string::npos) << e.what();
  }
  first.commit();  // the refused writer did not disturb the first one
  EXPECT_EQ(File::open(path).root().open_dataset("x").read<double>(), (std::vector<double>{1, 2, 3}));
}

TEST(H5, CommitFinishesTheFileEvenWithHandlesStillOpen) {
  TempDir dir;
  const std::string path = dir.file("open-handles.h5");
  AtomicFile out(path, false);
  Group g = out.root().create_group("g");
  Dataset d = g.write("x", std::vector<double>(1000, 2.0));
  out.commit();  // g and d are still alive here
  EXPECT_EQ(File::open(path).root().open_group("g").open_dataset("x").read<double>()[999], 2.0);
}

TEST(H5, ANamePartialIsNeitherFollowedNorEmptied) {
  TempDir dir;
  const std::string path = dir.file("stale.h5"), kept = dir.file("kept.txt");
  { std::ofstream(path + ".partial") << "a file of the user's"; }
  { std::ofstream(kept) << "keep me"; }
  std::filesystem::create_symlink(kept, path + ".x");
  AtomicFile out(path, false);
  out.root().set_attr("ok", 1);
  out.commit();
  EXPECT_EQ(File::open(path).root().attr_int("ok"), 1);
  std::ifstream user(path + ".partial"), link(kept);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(user), {}), "a file of the user's");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(link), {}), "keep me");
  EXPECT_TRUE(temporaries_of(path).empty());
}

TEST(H5, RefusesExistingOutputUnlessOverwrite) {
  TempDir dir;
  const std::string path = dir.file("exists.h5");
  { std::ofstream(path) << "keep me"; }
  EXPECT_THROW(AtomicFile(path, false), Error);
  std::ifstream in(path);
  std::string kept;
  std::getline(in, kept);
  EXPECT_EQ(kept, "keep me");
  EXPECT_THROW(AtomicFile(path, true, "recordings/1"), Error) << "--force replaces only a file haptex wrote";
  std::filesystem::remove(path);
  {
    AtomicFile ours(path, false);
    ours.root().set_attr(kFormatAttribute, "recordings/1");
    ours.commit();
  }
  AtomicFile replaced(path, true, "recordings/1");
  replaced.commit();
  std::filesystem::create_directory(dir.file("a_directory"));
  EXPECT_THROW(AtomicFile(dir.file("a_directory"), true, "recordings/1"), Error);
  EXPECT_GT(H5Fis_hdf5(path.c_str()), 0);
}

TEST(H5, RefusesUnwritableDirectory) {
  if (geteuid() == 0) {
    // root writes anywhere; a missing directory still exercises the refusal
    TempDir dir;
    EXPECT_THROW(AtomicFile(dir.file("no/such/dir/x.h5"), false), Error);
    return;
  }
  TempDir dir;
  std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  EXPECT_THROW(AtomicFile(dir.file("x.h5"), false), Error);
}

TEST(H5, OpenRefusesMissingAndNonHdf5Files) {
  TempDir dir;
  EXPECT_THROW(File::open(dir.file("absent.h5")), Error);
  { std::ofstream(dir.file("text.h5")) << "not hdf5"; }
  try {
    File::open(dir.file("text.h5"));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not an HDF5 file"), std::string::npos);
  }
}

// A writer killed with SIGKILL at any point leaves either no file under the final name or a complete one.
void write_many_datasets(const std::string& path, int write_fd) {
  AtomicFile out(path, false);
  Group root = out.root();
  std::vector<double> block(50000);
  for (int i = 0; i < 60; ++i) {
    std::iota(block.begin(), block.end(), double(i));
    root.write("d" + std::to_string(i), block);
    out.file().flush();
    if (i == 20) {
      char ready = 'x';
      if (::write(write_fd, &ready, 1) != 1) _exit(3);
    }
  }
  root.set_attr("complete", 1);
  out.commit();
}

bool opens_as_complete_file(const std::string& path) {
  File in = File::open(path);
  Group root = in.root();
  if (!root.has_attr("complete")) return false;
  for (int i = 0; i < 60; ++i) {
    auto values = root.open_dataset("d" + std::to_string(i)).read<double>();
    if (values.size() != 50000 || values[49999] != 49999.0 + i) return false;
  }
  return true;
}

TEST(H5, KilledWriterNeverLeavesHalfFile) {
  TempDir dir;
  for (int trial = 0; trial < 3; ++trial) {
    const std::string path = dir.file("killed" + std::to_string(trial) + ".h5");
    int pipe_fds[2];
    ASSERT_EQ(pipe(pipe_fds), 0);
    pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      close(pipe_fds[0]);
      write_many_datasets(path, pipe_fds[1]);
      _exit(0);
    }
    close(pipe_fds[1]);
    char ready;
    ASSERT_EQ(read(pipe_fds[0], &ready, 1), 1);  // the writer is in the middle of its work
    usleep(trial * 2000);
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    close(pipe_fds[0]);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the writer did not die by our SIGKILL";
    EXPECT_FALSE(std::filesystem::exists(path)) << "a killed writer left a file under the final name";
  }
  // And a writer left alone finishes with a complete file.
  const std::string path = dir.file("finished.h5");
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    int devnull[2];
    if (pipe(devnull) != 0) _exit(4);
    write_many_datasets(path, devnull[1]);
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_TRUE(opens_as_complete_file(path));
}

}  // namespace
}  // namespace haptex::h5

namespace haptex::h5 {
namespace {

TEST(H5, CopiesGroupsBetweenFiles) {
  test::TempDir dir;
  {
    AtomicFile out(dir.file("src.h5"), false);
    Group g = out.root().create_group("rec");
    g.set_attr("rate", 10000.0);
    g.create_group("inner").write("x", std::vector<double>{1, 2, 3}).set_attr("units", "N");
    out.commit();
  }
  const File source = File::open(dir.file("src.h5"));
  AtomicFile out(dir.file("dst.h5"), false);
  out.root().create_group("materials").copy_from(source.root(), "rec", "0");
  out.commit();
  const Group copied = File::open(dir.file("dst.h5")).root().open_group("materials").open_group("0");
  EXPECT_EQ(copied.attr_double("rate"), 10000.0);
  EXPECT_EQ(copied.open_group("inner").open_dataset("x").read<double>(), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(copied.open_group("inner").open_dataset("x").attr_string("units"), "N");
}

}  // namespace
}  // namespace haptex::h5
