#include "align/align_dataset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "align/window_table.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "tests/support/bad_input.hpp"
#include "tests/support/pipeline_fixture.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::align {
namespace {

using test::bad_input_message;
using test::TempDir;

using Inputs = test::PipelineFiles;

void make_inputs(Inputs& in, int odd_press_size = 0) { test::make_pipeline_inputs(in, {0.5, odd_press_size}); }

AlignOptions options_for(const Inputs& in) {
  AlignOptions o;
  o.recordings = in.recordings;
  o.gelsight = in.gelsight;
  o.output = in.dataset;
  return o;
}

TEST(AlignDataset, JoinsMaterialsByNormalisedNameAndListsTheRest) {
  Inputs in;
  make_inputs(in);
  const AlignResult r = align_dataset(options_for(in));
  ASSERT_EQ(r.match.pairs.size(), 2u);
  EXPECT_EQ(r.match.pairs[0].id, "book");
  EXPECT_EQ(r.match.pairs[1].id, "sandpaper_100");
  EXPECT_EQ(r.match.pairs[1].gelsight.name, "sandpaper 100");
  ASSERT_EQ(r.match.only_recordings.size(), 1u);
  EXPECT_EQ(r.match.only_recordings[0].name, "Felt");
  ASSERT_EQ(r.match.only_gelsight.size(), 1u);
  EXPECT_EQ(r.match.only_gelsight[0].name, "Glass");
  EXPECT_EQ(r.recordings, 3u);
  EXPECT_EQ(r.presses, 10u);
  // 5000 samples: starts 0, 100, ..., 4000 (t + 1000 <= 5000): 41 per recording.
  EXPECT_EQ(r.windows, 123u);

  const h5::Group root = h5::File::open(in.dataset).root();
  EXPECT_EQ(root.attr_string("haptex_format"), "dataset/4");
  EXPECT_EQ(root.open_group("windows").attr_int("action_end"), 500);
  EXPECT_EQ(root.attr_string("recordings_sha256").size(), 64u);
  const h5::Group book = root.open_group("materials").open_group("book");
  EXPECT_EQ(book.open_group("recordings").children(), (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(book.open_group("presses").children().size(), 5u);
  EXPECT_TRUE(book.open_group("recordings").open_group("1").has_dataset("accel_xyz"));
  EXPECT_EQ(root.open_group("windows").open_dataset("materials").read_strings(),
            (std::vector<std::string>{"book", "sandpaper_100"}));
}

TEST(AlignDataset, WindowsHoldTheSpectrumOf100MsAndTheActionAtItsMiddle) {
  Inputs in;
  make_inputs(in);
  align_dataset(options_for(in));
  const h5::Group root = h5::File::open(in.dataset).root();
  const h5::Group w = root.open_group("windows");
  const auto start = w.open_dataset("start").read<std::int64_t>();
  const auto material = w.open_dataset("material").read<std::int32_t>();
  const auto recording = w.open_dataset("recording").read<std::int32_t>();
  const auto action = w.open_dataset("action").read<float>();
  const auto target = w.open_dataset("target").read<float>();
  const std::size_t i = 58;  // book, recording 1, the 18th window
  ASSERT_EQ(material[i], 0);
  ASSERT_EQ(recording[i], 1);
  const std::int64_t t = start[i];
  EXPECT_EQ(t, 17 * 100);
  const h5::Group rec = root.open_group("materials").open_group("book").open_group("recordings").open_group("1");
  const auto force = rec.open_dataset("force_normal_lp").read<float>();
  const auto speed = rec.open_dataset("speed_lp").read<float>();
  const auto accel = rec.open_dataset("accel").read<float>();
  for (int k = 0; k < 10; ++k) {  // samples t + 50, t + 100, .. t + 500
    EXPECT_EQ(action[i * 20 + std::size_t(k)], force[std::size_t(t + 50 + 50 * k)]);
    EXPECT_EQ(action[i * 20 + 10 + std::size_t(k)], speed[std::size_t(t + 50 + 50 * k)]);
  }
  // The target by the definition, a direct DFT sum: 2 |X_k| / N, k = 1..100, of accel[t, t + 1000).
  for (int k = 1; k <= 100; k += 11) {
    std::complex<double> sum = 0;
    for (int n = 0; n < 1000; ++n)
      sum += double(accel[std::size_t(t + n)]) * std::polar(1.0, -2 * std::numbers::pi * k * n / 1000.0);
    EXPECT_NEAR(target[i * 100 + std::size_t(k - 1)], 2 * std::abs(sum) / 1000, 1e-5 + 1e-5 * std::abs(sum) / 500) << k;
  }
}

TEST(AlignDataset, NameMapJoinsOtherNamesAndRefusesTwoToOne) {
  Inputs in;
  make_inputs(in);
  test::write_text_file(in.dir.file("names.json"), R"({"Glass": "Felt"})");
  AlignOptions o = options_for(in);
  o.names_file = in.dir.file("names.json");
  const AlignResult r = align_dataset(o);
  EXPECT_EQ(r.match.pairs.size(), 3u);
  EXPECT_TRUE(r.match.only_gelsight.empty());

  test::write_text_file(in.dir.file("twice.json"), R"({"Glass": "Book"})");
  o.names_file = in.dir.file("twice.json");
  o.overwrite = true;
  const std::string message = bad_input_message([&] { align_dataset(o); });
  EXPECT_NE(message.find("joined with two gelsight materials"), std::string::npos) << message;

  // Without a map two names could join them only when a material's name is not its id's, which the
  // gelsight file's own check refuses first, naming it (review 5: the message named no file; review 20, F2).
  h5::File::open(in.gelsight, true).root().open_group("materials").open_group("glass").set_attr("name", std::string("Book"));
  o.names_file.clear();
  const std::string by_names = bad_input_message([&] { align_dataset(o); });
  EXPECT_EQ(by_names.find(in.gelsight + ": /materials/glass/@name: 'Book' is the name of the material 'book'"), 0u) << by_names;
  h5::File::open(in.gelsight, true).root().open_group("materials").open_group("glass").set_attr("name", std::string("Glass"));

  test::write_text_file(in.dir.file("typo.json"), R"({"Glas": "Felt"})");
  o.names_file = in.dir.file("typo.json");
  EXPECT_NE(bad_input_message([&] { align_dataset(o); }).find("no such material in the gelsight file"), std::string::npos);
}

TEST(AlignDataset, RefusesPressesOfDifferentSizesWithinAMaterial) {
  Inputs in;
  make_inputs(in, 40);
  const std::string message = bad_input_message([&] { align_dataset(options_for(in)); });
  EXPECT_NE(message.find("/materials/book/presses/4: image size differs"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(in.dataset));
}

TEST(AlignDataset, RefusesAnotherSampleRateAndSwappedFiles) {
  Inputs in;
  make_inputs(in);
  {
    h5::File file = h5::File::open(in.recordings, true);
    file.root().open_group("materials").open_group("book").open_group("recordings").open_group("0").set_attr("sample_rate_hz", 5000.0);
  }
  const std::string message = bad_input_message([&] { align_dataset(options_for(in)); });
  EXPECT_NE(message.find("/materials/book/recordings/0"), std::string::npos) << message;
  EXPECT_NE(message.find("5000"), std::string::npos) << message;
  AlignOptions swapped = options_for(in);
  std::swap(swapped.recordings, swapped.gelsight);
  EXPECT_NE(bad_input_message([&] { align_dataset(swapped); }).find("a gelsight file (haptex capture extract writes those), not a recordings file (recordings/1)"), std::string::npos);
}

}  // namespace
}  // namespace haptex::align
