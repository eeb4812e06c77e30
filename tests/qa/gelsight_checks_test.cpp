// Each GelSight check fires, alone, on a copy of the good gelsight file with one defect.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "capture/storage/image_datasets.hpp"
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

// Every frame of an N x H x W x 3 stack through `change` (RGB in, RGB out).
// Every image of `path`: a stack N x H x W x 3 or a single H x W x 3 image.
void change_frames(Edit& e, const std::string& path, const std::function<void(cv::Mat&)>& change) {
  h5::Shape shape = e.dataset(path).shape();
  if (shape.size() == 3) shape.insert(shape.begin(), 1);
  e.change_bytes(path, [&](std::vector<std::uint8_t>& bytes) {
    const std::size_t frame = shape[1] * shape[2] * 3;
    for (std::size_t i = 0; i < shape[0]; ++i) {
      cv::Mat image(static_cast<int>(shape[1]), static_cast<int>(shape[2]), CV_8UC3, bytes.data() + i * frame);
      change(image);
    }
  });
}

void replace_image(Edit& e, const std::string& path, const cv::Mat& bgr) {
  const auto slash = path.rfind('/');
  h5::Group g = e.group(path.substr(0, slash));
  e.remove(path);
  capture::write_image(g, path.substr(slash + 1), bgr, "replaced by a qa test");
}

cv::Mat image_at(const Edit& e, const std::string& path) {
  const auto slash = path.rfind('/');
  return capture::read_image(e.group(path.substr(0, slash)), path.substr(slash + 1));
}

TEST_F(GelsightMutation, MissingContrastIsLayoutRequired) {
  Edit(file_).remove(kPress + "/contrast");
  expect_only(qa(), "layout.required");
}

TEST_F(GelsightMutation, FramesOfAnotherSizeThanTheAttributesIsLayoutShape) {
  Edit(file_).group(kPress).set_attr("width", std::int64_t(320));
  const qa::Report r = qa();
  expect_only(r, "layout.shape");
  EXPECT_NE(r.find("layout.shape")->message.find("= (H, W, 3)"), std::string::npos) << r.find("layout.shape")->message;
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
      e.change_bytes(kPress + "/" + name, [](std::vector<std::uint8_t>& pixels) {
        for (std::size_t i = 0; i + 2 < pixels.size(); i += 3) std::swap(pixels[i], pixels[i + 2]);
      });
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
    replace_image(e, kPress + "/reference", image_at(e, "materials/sandpaper_1/presses/1/peak"));
  }
  const qa::Report r = qa();
  expect_only(r, "gelsight.reference");
  EXPECT_NE(r.find("gelsight.reference")->message.find("it shows contact"), std::string::npos);
}

TEST_F(GelsightMutation, PeakWithoutContactIsGelsightPeakScore) {
  {
    Edit e(file_);
    replace_image(e, kPress + "/peak", image_at(e, kPress + "/reference"));
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
    const cv::Mat reference = half(image_at(e, press + "/reference")), peak = half(image_at(e, press + "/peak"));
    const h5::Shape shape = e.dataset(press + "/frames").shape();
    std::vector<cv::Mat> frames;
    change_frames(e, press + "/frames", [&](cv::Mat& rgb) {
      cv::Mat bgr;
      cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
      frames.push_back(half(bgr));
    });
    replace_image(e, press + "/reference", reference);
    replace_image(e, press + "/peak", peak);
    e.remove(press + "/frames");
    h5::Group g = e.group(press);
    capture::write_image_stack(g, "frames", frames, "resized by a qa test");
    g.set_attr("width", std::int64_t(reference.cols));
    g.set_attr("height", std::int64_t(reference.rows));
    ASSERT_EQ(shape[0], frames.size());
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

}  // namespace
}  // namespace haptex::test
