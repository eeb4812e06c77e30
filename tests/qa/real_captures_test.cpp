// The GelSight thresholds against real sensor captures (../shared/data/gelsight; skipped when absent):
// real presses pass every per-press check, so the thresholds are not tuned to synthetic frames only.
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/sha256.hpp"
#include "dataset/gelsight_file.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "qa/run_qa.hpp"
#include "tests/qa/qa_fixture.hpp"
#include "tests/support/npy.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

// Still images as presses: the no-contact image as every press's reference, each contact image as
// the peak and its frames, thresholds as capture derives them from a single no-contact image.
std::string gelsight_file(const TempDir& dir, const std::string& material, const fs::path& reference_path,
                          const std::vector<fs::path>& presses) {
  const cv::Mat reference = cv::imread(reference_path.string(), cv::IMREAD_COLOR);
  const auto contact = capture::ContactReference::from_image(capture::scoring_image(reference));
  const std::string out = dir.file(material + ".h5");
  dataset::GelsightWriter writer(out, false, "qa real-capture test");
  for (const auto& path : presses) {
    dataset::GelsightPress p;
    p.source_file = path.string();
    p.source_sha256 = sha256_file(path.string());
    p.reference = reference;
    p.peak = cv::imread(path.string(), cv::IMREAD_COLOR);
    // A still image as a video of 12 like frames, its numbers agreeing (gelsight.frame_numbers).
    p.frames.assign(12, p.peak);
    p.frame_indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
    p.contrast.assign(12, contact.score(capture::scoring_image(p.peak)));
    p.frame_start = 0, p.frame_end = 11, p.contact_first = 0, p.contact_last = 11, p.peak_index = 5;
    p.peak_score = p.contrast[0];
    p.reference_note = "image " + reference_path.string();
    p.noise = contact.noise();
    p.pixel_threshold = contact.pixel_threshold();
    p.trigger = contact.trigger();
    p.release = contact.release();
    writer.add_press(material, p);
  }
  writer.commit();
  return out;
}

void expect_press_checks_pass(const qa::Report& r) {
  for (const char* id : {"gelsight.reference", "gelsight.peak_score", "gelsight.saturation", "gelsight.blur",
                         "gelsight.resolution", "layout.required", "layout.dtype", "layout.shape"}) {
    ASSERT_NE(r.find(id), nullptr) << id;
    EXPECT_EQ(r.find(id)->status, qa::Status::pass) << id << ": " << r.find(id)->message;
  }
}

TEST(RealCaptures, GelSlimBallPressesPass) {
  const fs::path dir = fs::path(shared_data_dir()) / "gelsight" / "gelslim4";
  if (shared_data_dir().empty() || !fs::exists(dir / "ref.jpg")) GTEST_SKIP() << "../shared/data/gelsight/gelslim4 is absent";
  std::vector<fs::path> presses;
  for (const auto& f : fs::directory_iterator(dir))
    if (f.path().filename().string().rfind("sample_", 0) == 0) presses.push_back(f.path());
  ASSERT_GE(presses.size(), 8u);
  // The 8 weakest presses (scored as capture scores them): the ones a threshold would fail first.
  // (Writing all 40 takes seconds; the strong ones prove nothing more.)
  const cv::Mat reference = cv::imread((dir / "ref.jpg").string(), cv::IMREAD_COLOR);
  const auto contact = capture::ContactReference::from_image(capture::scoring_image(reference));
  std::vector<std::pair<float, fs::path>> scored;
  for (const auto& p : presses) scored.emplace_back(contact.score(capture::scoring_image(cv::imread(p.string()))), p);
  std::sort(scored.begin(), scored.end());
  presses.clear();
  for (std::size_t i = 0; i < 8; ++i) presses.push_back(scored[i].second);
  TempDir tmp;
  const qa::Report r = qa::run_qa({gelsight_file(tmp, "Ball", dir / "ref.jpg", presses), {}});
  expect_press_checks_pass(r);
  EXPECT_EQ(r.verdict(), "clean") << describe(r);
}

TEST(RealCaptures, GelSightMiniPressesPassAndThreeAreTooFew) {
  const fs::path dir = fs::path(shared_data_dir()) / "gelsight" / "gs_sdk_gsmini";
  if (shared_data_dir().empty() || !fs::exists(dir / "background.png")) GTEST_SKIP() << "../shared/data/gelsight/gs_sdk_gsmini is absent";
  TempDir tmp;
  const qa::Report r =
      qa::run_qa({gelsight_file(tmp, "Objects", dir / "background.png", {dir / "bead.png", dir / "key.png", dir / "seed.png"}), {}});
  expect_press_checks_pass(r);
  expect_only(r, "gelsight.press_count");
}

}  // namespace
}  // namespace haptex::test
