// Each GelSight check fires, alone, on a copy of the good gelsight file with one defect.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "dataset/press_images.hpp"
#include "core/error.hpp"
#include "dataset/format.hpp"
#include "qa/integrity.hpp"
#include "qa/run_qa.hpp"
#include "tests/qa/qa_fixture.hpp"
#include "tests/support/mutations.hpp"

namespace haptex::test {
namespace {

const std::string kPress = "materials/sandpaper_1/presses/0";

class GelsightMutation : public ::testing::Test {
 protected:
  qa::Report qa() const { return qa::run_qa({file_, {}}); }
  TempDir dir_;
  std::string file_ = copy_into(dir_, small_pipeline().gelsight, "gelsight.h5");
};

// Replaces the encoded images of `path` by `bgr`, stored as PNG.
void replace_images(Edit& e, const std::string& path, const std::vector<cv::Mat>& bgr) {
  const auto slash = path.rfind('/');
  h5::Group g = e.group(path.substr(0, slash));
  e.remove(path);
  std::vector<dataset::EncodedImage> png;
  for (const cv::Mat& image : bgr) png.push_back(dataset::encode_png(image));
  dataset::write_press_images(g, path.substr(slash + 1), png, "replaced by a qa test");
}

std::vector<cv::Mat> images_at(const Edit& e, const std::string& path) {
  const auto slash = path.rfind('/');
  return dataset::read_press_images(e.group(path.substr(0, slash)), path.substr(slash + 1));
}

// Every image of `path` through `change` (RGB in, RGB out), stored again as PNG.
void change_frames(Edit& e, const std::string& path, const std::function<void(cv::Mat&)>& change) {
  std::vector<cv::Mat> images = images_at(e, path);
  for (cv::Mat& image : images) {
    cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
    change(image);
    cv::cvtColor(image, image, cv::COLOR_RGB2BGR);
  }
  replace_images(e, path, images);
}

TEST_F(GelsightMutation, MissingContrastIsLayoutRequired) {
  Edit(file_).remove(kPress + "/contrast");
  expect_only(qa(), "layout.required");
}

// The images carry their size inside; the press's attributes must state the same. gelsight.images
// (which merge and align run, decoding nothing) reports it from the headers too.
TEST_F(GelsightMutation, ImagesOfAnotherSizeThanTheAttributesIsGelsightResolution) {
  Edit(file_).group(kPress).set_attr("width", std::int64_t(320));
  const qa::Report r = qa();
  EXPECT_EQ(failed_ids(r), (std::set<std::string>{"gelsight.resolution", "gelsight.images"})) << describe(r);
  EXPECT_NE(r.find("gelsight.resolution")->message.find("width and height differ"), std::string::npos)
      << r.find("gelsight.resolution")->message;
}

// Images stored as pixels (gelsight/1) or as bytes that are no image are reported, not crashed on.
TEST_F(GelsightMutation, FramesThatAreNoEncodedImagesAreLayoutDtype) {
  {
    Edit e(file_);
    e.remove(kPress + "/frames");
    e.group(kPress).write_array<std::uint8_t>("frames", std::vector<std::uint8_t>(12 * 120 * 160 * 3, 128), {12, 120, 160, 3});
  }
  const qa::Report r = qa();
  ASSERT_NE(r.find("layout.dtype"), nullptr);
  EXPECT_EQ(r.find("layout.dtype")->status, qa::Status::fail) << r.find("layout.dtype")->message;
}

// Issue 11 point 5: capture extract counts the frames of a press's source that did not decode.
TEST_F(GelsightMutation, ASourceWithUnreadableFramesIsGelsightSourceDamage) {
  Edit(file_).group(kPress).set_attr("source_frames_unreadable", std::int64_t(16));
  const qa::Report r = qa();
  expect_only(r, "gelsight.source_damage");
  EXPECT_NE(r.find("gelsight.source_damage")->message.find("16 frames that did not decode"), std::string::npos)
      << r.find("gelsight.source_damage")->message;
}

// The any-sensor issue, section 3: an order qa cannot read is reported, and its images not judged.
TEST_F(GelsightMutation, AnUnknownChannelOrderIsGelsightChannelOrder) {
  Edit(file_).group(kPress).set_attr("channel_order", "GRB");
  const qa::Report r = qa();
  expect_only(r, "gelsight.channel_order");
  EXPECT_NE(r.find("gelsight.channel_order")->message.find("unknown channel order 'GRB'"), std::string::npos)
      << r.find("gelsight.channel_order")->message;
}

TEST_F(GelsightMutation, AnImageContradictingItsPressIsGelsightChannelOrder) {
  Edit(file_).dataset(kPress + "/frames").set_attr("channel_order", "BGR");
  const qa::Report r = qa();
  expect_only(r, "gelsight.channel_order");
  EXPECT_NE(r.find("gelsight.channel_order")->message.find("says BGR but its press says RGB"), std::string::npos)
      << r.find("gelsight.channel_order")->message;
}

TEST_F(GelsightMutation, APressStoredBlueFirstPassesLikeTheOriginal) {
  {
    Edit e(file_);
    for (const std::string name : {"reference", "peak", "frames"}) {
      change_frames(e, kPress + "/" + name, [](cv::Mat& rgb) { cv::cvtColor(rgb, rgb, cv::COLOR_RGB2BGR); });
      e.dataset(kPress + "/" + name).set_attr("channel_order", "BGR");
    }
    e.group(kPress).set_attr("channel_order", "BGR");
  }
  EXPECT_TRUE(failed_ids(qa()).empty()) << describe(qa());
}

TEST_F(GelsightMutation, ReferenceTakenDuringContactIsGelsightReference) {
  {
    Edit e(file_);
    // Another press's peak frame as this press's "no-contact" reference.
    replace_images(e, kPress + "/reference", images_at(e, "materials/sandpaper_1/presses/1/peak"));
  }
  const qa::Report r = qa();
  expect_only(r, "gelsight.reference");
  EXPECT_NE(r.find("gelsight.reference")->message.find("it shows contact"), std::string::npos);
}

TEST_F(GelsightMutation, PeakWithoutContactIsGelsightPeakScore) {
  {
    Edit e(file_);
    replace_images(e, kPress + "/peak", images_at(e, kPress + "/reference"));
  }
  const qa::Report r = qa();
  expect_only(r, "gelsight.peak_score");
  EXPECT_EQ(r.find("gelsight.peak_score")->where, std::vector<std::string>{"/" + kPress + "/peak"});
}

TEST_F(GelsightMutation, OverexposedFramesAreGelsightSaturation) {
  {
    Edit e(file_);
    // An LED hot spot: a tenth of every frame at full white.
    change_frames(e, kPress + "/frames", [](cv::Mat& rgb) { cv::circle(rgb, {30, 30}, 25, cv::Scalar(255, 255, 255), -1); });
  }
  const qa::Report r = qa();
  expect_only(r, "gelsight.saturation");
  EXPECT_EQ(r.find("gelsight.saturation")->where.size(), 12u);
}

// The synthetic gel is flat and marker-less, and MJPG smooths its noise: its references have no detail
// a blurred frame could fall under, so the check says it cannot judge rather than pass.
TEST_F(GelsightMutation, SmoothReferencesLeaveBlurUnjudged) {
  {
    Edit e(file_);
    change_frames(e, kPress + "/frames", [](cv::Mat& rgb) { cv::GaussianBlur(rgb, rgb, {0, 0}, 2.0); });
  }
  const qa::Report r = qa();
  ASSERT_NE(r.find("gelsight.blur"), nullptr);
  EXPECT_EQ(r.find("gelsight.blur")->status, qa::Status::skip) << r.find("gelsight.blur")->message;
  EXPECT_EQ(r.verdict(), "clean") << describe(r);
}

// A gel with printed markers, as most GelSight sensors have: now a blurred press stands out.
TEST_F(GelsightMutation, BlurredFramesAreGelsightBlurAWarning) {
  {
    Edit e(file_);
    const auto markers = [](cv::Mat& rgb) {
      for (int y = 6; y < rgb.rows; y += 12)
        for (int x = 6; x < rgb.cols; x += 12) cv::circle(rgb, {x, y}, 2, cv::Scalar(30, 30, 30), -1);
    };
    for (const std::string& material : e.group("materials").children())
      for (const std::string& press : e.group("materials/" + material + "/presses").children())
        for (const char* image : {"reference", "peak", "frames"})
          change_frames(e, "materials/" + material + "/presses/" + press + "/" + image, markers);
    change_frames(e, kPress + "/frames", [](cv::Mat& rgb) { cv::GaussianBlur(rgb, rgb, {0, 0}, 2.0); });
  }
  const qa::Report r = qa();
  expect_only(r, "gelsight.blur");
  EXPECT_EQ(r.find("gelsight.blur")->where.size(), 12u);
  EXPECT_EQ(r.verdict(), "warnings");
}

TEST_F(GelsightMutation, OnePressAtHalfSizeIsGelsightResolution) {
  {
    Edit e(file_);
    const std::string press = "materials/woven_1/presses/4";
    auto half = [](const cv::Mat& m) {
      cv::Mat out;
      cv::resize(m, out, {m.cols / 2, m.rows / 2}, 0, 0, cv::INTER_AREA);
      return out;
    };
    for (const char* image : {"reference", "peak", "frames"}) change_frames(e, press + "/" + image, [&](cv::Mat& rgb) { rgb = half(rgb); });
    h5::Group g = e.group(press);
    g.set_attr("width", std::int64_t(80));
    g.set_attr("height", std::int64_t(60));
  }
  const qa::Report r = qa();
  expect_only(r, "gelsight.resolution");
  EXPECT_NE(r.find("gelsight.resolution")->message.find("160x120 (4), 80x60 (1)"), std::string::npos)
      << r.find("gelsight.resolution")->message;
}

TEST_F(GelsightMutation, FourPressesAreGelsightPressCount) {
  Edit(file_).remove("materials/woven_1/presses/4");
  const qa::Report r = qa();
  expect_only(r, "gelsight.press_count");
  EXPECT_NE(r.find("gelsight.press_count")->message.find("4 presses, at least 5"), std::string::npos);
}

// Issue 32: a reference PNG whose chunk no longer matches its CRC was left out of the image checks
// ("not checked") and the file passed.
TEST_F(GelsightMutation, AnImageWhosePngCrcFailsIsGelsightImages) {
  Edit(file_).change_image(kPress + "/reference", 0, [](std::vector<std::uint8_t>& png) {
    ASSERT_EQ(png[1], 'P') << "the small pipeline's references are PNG";
    std::fill(png.begin() + std::ptrdiff_t(png.size() / 2), png.begin() + std::ptrdiff_t(png.size() / 2 + 20), 0);
  });
  const qa::Report r = qa();
  ASSERT_NE(r.find("gelsight.images"), nullptr);
  EXPECT_EQ(r.find("gelsight.images")->status, qa::Status::fail);
  EXPECT_NE(r.find("gelsight.images")->message.find(kPress + "/reference[0]"), std::string::npos) << r.find("gelsight.images")->message;
}

// Review 3: a press or peak reached by a second hard link was "clean" to qa while merge and align
// refused the file. qa now reports every such link (layout.links), so the three agree.
TEST_F(GelsightMutation, AnObjectLinkedTwiceIsLayoutLinks) {
  {
    Edit e(file_);
    e.remove("materials/woven_1/presses/4/peak");
    const h5::Group root = e.root();
    H5Lcreate_hard(root.id(), "materials/woven_1/presses/3/peak", root.id(), "materials/woven_1/presses/4/peak", H5P_DEFAULT, H5P_DEFAULT);
  }
  const qa::Report r = qa();
  ASSERT_NE(r.find("layout.links"), nullptr);
  EXPECT_EQ(r.find("layout.links")->status, qa::Status::fail);
  EXPECT_NE(r.find("layout.links")->message.find("/materials/woven_1/presses/4/peak: is a second link to /materials/woven_1/presses/3/peak"),
            std::string::npos)
      << r.find("layout.links")->message;
  EXPECT_THROW(qa::require_integrity(h5::File::open(file_).root(), dataset::Kind::gelsight), Error) << "merge and align refuse it too";
}

}  // namespace
}  // namespace haptex::test
