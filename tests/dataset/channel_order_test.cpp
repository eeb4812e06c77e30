// Where a file says the order of its images' colour channels, and what a reader makes of it
// (dataset/channel_order.hpp).
#include "dataset/channel_order.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::dataset {
namespace {

class ChannelOrderOf : public ::testing::Test {
 protected:
  // A press group holding one image; `press` and `image` set their channel_order attributes ("" : none).
  ChannelOrder read(const std::string& press, const std::string& image) {
    const std::string path = dir_.file("f" + std::to_string(++files_) + ".h5");
    {
      h5::File f = h5::File::create(path);
      h5::Group g = f.root().create_group("materials").create_group("cork").create_group("presses").create_group("0");
      const std::vector<std::uint8_t> pixels(2 * 2 * 3, 7);
      h5::Dataset d = g.write_array<std::uint8_t>("peak", pixels, {2, 2, 3});
      if (!press.empty()) g.set_attr("channel_order", press);
      if (!image.empty()) d.set_attr("channel_order", image);
    }
    const h5::File f = h5::File::open(path);
    return read_channel_order(f.root().open_group("materials/cork/presses/0"), "peak");
  }
  std::string refusal(const std::string& press, const std::string& image) {
    try {
      read(press, image);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      return e.what();
    }
    ADD_FAILURE() << "read " << press << "/" << image;
    return "";
  }
  test::TempDir dir_;
  int files_ = 0;
};

TEST_F(ChannelOrderOf, ThePressStatesItAndItsImagesMayRepeatIt) {
  EXPECT_EQ(read("RGB", ""), ChannelOrder::rgb);
  EXPECT_EQ(read("BGR", "BGR"), ChannelOrder::bgr);
  EXPECT_EQ(read("", "BGR"), ChannelOrder::bgr) << "files whose press predates the attribute: the image's";
}

TEST_F(ChannelOrderOf, AnUnknownMissingOrContradictedOrderIsRefusedByName) {
  EXPECT_NE(refusal("GRB", "").find("f1.h5: /materials/cork/presses/0/@channel_order: unknown channel order 'GRB'. Set it to RGB or BGR"),
            std::string::npos) << refusal("GRB", "");
  EXPECT_NE(refusal("rgb", "").find("unknown channel order 'rgb'"), std::string::npos) << "the names are exact";
  EXPECT_NE(refusal("RGB", "BRG").find("/materials/cork/presses/0/peak/@channel_order: unknown channel order 'BRG'"),
            std::string::npos);
  EXPECT_NE(refusal("", "").find("/materials/cork/presses/0/@channel_order: missing"), std::string::npos);
  EXPECT_NE(refusal("RGB", "BGR").find("/peak/@channel_order: says BGR but its press says RGB"), std::string::npos);
}

TEST(ReorderChannels, SwapsTheFirstAndThirdChannelOnlyWhenTheOrdersDiffer) {
  std::vector<std::uint8_t> pixels = {1, 2, 3, 4, 5, 6};
  reorder_channels(pixels, ChannelOrder::rgb, ChannelOrder::rgb);
  EXPECT_EQ(pixels, (std::vector<std::uint8_t>{1, 2, 3, 4, 5, 6}));
  reorder_channels(pixels, ChannelOrder::bgr, ChannelOrder::rgb);
  EXPECT_EQ(pixels, (std::vector<std::uint8_t>{3, 2, 1, 6, 5, 4}));
  EXPECT_STREQ(channel_order_name(kWrittenChannelOrder), "RGB");
}

}  // namespace
}  // namespace haptex::dataset
