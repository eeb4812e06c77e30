// The /windows table round-trips through HDF5 and a damaged one is refused naming the object
// (dataset/window_table.hpp); h5py reads the same columns.
#include "dataset/window_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::dataset {
namespace {

WindowTable two_windows() {
  WindowTable t;
  t.materials = {"book", "brick_2"};
  t.material = {0, 1};
  t.recording = {0, 3};
  t.start = {0, 100};
  t.stride = 100;
  for (std::size_t i = 0; i < 2 * kActionValues; ++i) t.action.push_back(float(i));
  for (std::size_t i = 0; i < 2 * kTargetBins; ++i) t.target.push_back(0.5f * float(i));
  return t;
}

// The recordings two_windows() is cut from, as long as it needs: a table with more rows than its
// recordings hold is refused (most_windows).
void write_recordings(h5::Group root) {
  h5::Group materials = root.create_group(layout::kMaterials);
  for (const auto& [material, recording] : {std::pair{"book", "0"}, {"brick_2", "3"}})
    materials.create_group(material).create_group(layout::kRecordings).create_group(recording).write_array<float>(
        layout::kAccel, std::vector<float>(1100, 0.0f), h5::Shape{1100});
}

std::string written(const test::TempDir& dir, const WindowTable& t, const std::string& name = "d.h5") {
  h5::AtomicFile out(dir.file(name), true, format_name(Kind::dataset));
  stamp(out.root(), Kind::dataset, "test");
  write_recordings(out.root());
  write_window_table(out.root(), t);
  out.commit();
  return dir.file(name);
}

std::string refusal(const std::string& path) {
  try {
    read_window_table(open_checked(path, Kind::dataset));
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    return e.what();
  }
  return "";
}

TEST(WindowTableFile, RoundTripsWithTheContractsAttributes) {
  const test::TempDir dir;
  const WindowTable t = two_windows();
  const WindowTable back = read_window_table(open_checked(written(dir, t), Kind::dataset));
  EXPECT_EQ(back.materials, t.materials);
  EXPECT_EQ(back.material, t.material);
  EXPECT_EQ(back.recording, t.recording);
  EXPECT_EQ(back.start, t.start);
  EXPECT_EQ(back.action, t.action);
  EXPECT_EQ(back.target, t.target);
  EXPECT_EQ(back.stride, 100u);
  EXPECT_EQ(back.action_of(1)[0], float(kActionValues));
  EXPECT_EQ(back.target_of(1)[kTargetBins - 1], 0.5f * float(2 * kTargetBins - 1));
  const h5::File file = h5::File::open(dir.file("d.h5"));
  EXPECT_EQ(file.root().open_group("windows").attr_int("action_end"), std::int64_t(kActionEnd));
  EXPECT_EQ(file.root().open_group("windows").attr_int("action_step"), std::int64_t(kActionStep));
}

TEST(WindowTableFile, RefusesAnotherContractOrDamagedColumnsNamingTheObject) {
  const test::TempDir dir;
  const std::string path = written(dir, two_windows());
  {
    h5::File f = h5::File::open(path, true);
    f.root().open_group("windows").set_attr("action_end", std::int64_t(9));  // dataset/1's action before the window
  }
  std::string m = refusal(path);
  EXPECT_NE(m.find("/windows/@action_end"), std::string::npos) << m;
  EXPECT_NE(m.find("is 9"), std::string::npos) << m;
  EXPECT_NE(m.find("haptex align again"), std::string::npos) << m;
  {
    h5::File f = h5::File::open(path, true);
    f.root().open_group("windows").set_attr("action_end", std::int64_t(kActionEnd));
    f.root().open_group("windows").set_attr("action_step", std::int64_t(1));  // dataset/3's 1 ms
  }
  m = refusal(path);
  EXPECT_NE(m.find("/windows/@action_step"), std::string::npos) << m;
  EXPECT_NE(m.find("is 1, this haptex's windows have 50"), std::string::npos) << m;
  {  // review 18, F9: the material names as a (1, 2) table were read flat by split and train
    h5::File f = h5::File::open(path, true);
    f.root().open_group("windows").set_attr("action_step", std::int64_t(kActionStep));
    const h5::Group group = f.root().open_group("windows");
    const hid_t windows = group.id();
    H5Ldelete(windows, "materials", H5P_DEFAULT);
    const hsize_t dims[2] = {1, 2};
    const hid_t type = H5Tcopy(H5T_C_S1), space = H5Screate_simple(2, dims, nullptr);
    H5Tset_size(type, 8);
    const char names[] = "book\0\0\0\0brick_2";
    const hid_t d = H5Dcreate2(windows, "materials", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, names);
    H5Dclose(d), H5Sclose(space), H5Tclose(type);
  }
  m = refusal(path);
  EXPECT_NE(m.find("/windows/materials: has shape (1, 2), expected (materials)"), std::string::npos) << m;

  const std::string broken = dir.file("broken \"`x`\".h5");
  {
    h5::AtomicFile out(broken, true, format_name(Kind::dataset));
    stamp(out.root(), Kind::dataset, "test");
    const WindowTable t = two_windows();
    write_recordings(out.root());
    h5::Group w = out.root().create_group("windows");
    const std::pair<const char*, std::size_t> attributes[] = {
        {"stride", 100}, {"action_samples", kActionSamples}, {"window_samples", kWindowSamples}, {"action_end", kActionEnd}, {"action_step", kActionStep}};
    for (const auto& [name, value] : attributes) w.set_attr(name, std::int64_t(value));
    w.write_strings("materials", t.materials);
    w.write("material", t.material);
    w.write("recording", t.recording);
    w.write("start", t.start);
    w.write_array<float>("action", t.action, {2, kActionValues});
    w.write_array<std::int32_t>("target", std::vector<std::int32_t>(2 * kTargetBins, 1), {2, kTargetBins});  // integers
    out.commit();
  }
  EXPECT_NO_THROW(open_checked(broken, Kind::dataset));
  m = refusal(broken);
  EXPECT_NE(m.find("/windows/target"), std::string::npos) << m;
  EXPECT_NE(m.find("expected float values"), std::string::npos) << m;
  EXPECT_NE(m.find("broken"), std::string::npos) << m;
}

}  // namespace
}  // namespace haptex::dataset
