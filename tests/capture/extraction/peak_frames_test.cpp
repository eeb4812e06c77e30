// Scoring a source, cutting presses and choosing the 12 frames around each peak.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <regex>
#include <tuple>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/extraction/peak_frames.hpp"
#include "core/error.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

using fixtures::quick_presses;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

SegmenterSettings segmenter() { return SegmenterSettings{}; }

bool consecutive(const std::vector<std::int64_t>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (v[i] != v[i - 1] + 1) return false;
  return true;
}

// After a grasp the gel may settle a little apart from where it started (GelSight Wedge footage: 6 % of
// the press's excess). A video ending in that steady state (end_level) ends in it, not in a second
// press; a press held to the end is no settled state and stays.
TEST(PlanPresses, TheSettledEndOfAVideoIsNoPress) {
  SegmenterSettings s;
  s.level = 0.3f, s.trigger = 0.4f, s.release = 0.35f;
  std::vector<float> scores(40, 0.3f);
  for (int i = 0; i < 10; ++i) scores.push_back(0.3f + 0.2f * float(std::min(i, 9 - i)));  // a press to 1.1
  for (int i = 0; i < 5; ++i) scores.push_back(0.3f);                                     // released
  for (int i = 0; i < 30; ++i) scores.push_back(0.45f);                                   // settled a little higher
  EXPECT_EQ(plan_presses(scores, s, 12, 10).size(), 2u) << "without the end's level, the settled state is a press";
  const auto plans = plan_presses(scores, s, 12, 10, 0.45f);
  ASSERT_EQ(plans.size(), 1u);
  EXPECT_EQ(plans[0].contact.peak, 44);
  std::vector<float> held(40, 0.3f);
  for (int i = 0; i < 40; ++i) held.push_back(std::min(1.1f, 0.3f + 0.2f * float(i)));  // pressed and held to the end
  EXPECT_EQ(plan_presses(held, s, 12, 10, 1.1f).size(), 1u);
  // A weaker press held to the end that a person sees (twice the trigger's margin and more) stays, as
  // does a weak press in the middle of a video that ends settled.
  std::vector<float> weak_held(scores.begin(), scores.begin() + 55);
  weak_held.insert(weak_held.end(), 30, 0.55f);
  EXPECT_EQ(plan_presses(weak_held, s, 12, 10, 0.55f).size(), 2u);
  std::vector<float> weak_middle(scores.begin(), scores.begin() + 55);
  for (float v : {0.5f, 0.5f, 0.5f, 0.5f, 0.3f, 0.3f}) weak_middle.push_back(v);
  weak_middle.insert(weak_middle.end(), 30, 0.45f);
  EXPECT_EQ(plan_presses(weak_middle, s, 12, 10, 0.45f).size(), 2u);
}

TEST(PlanPresses, KeepsTwelveConsecutiveFramesAroundThePeakThatScoreHighest) {
  std::vector<float> s(60, 0.0f);
  for (int i = 20; i < 40; ++i) s[std::size_t(i)] = 1.0f + 0.1f * float(i - 20);  // rising to the peak at 39
  for (int i = 40; i < 45; ++i) s[std::size_t(i)] = 0.7f;  // still over a fifth of the peak: the same press
  const auto plans = plan_presses(s, segmenter(), 12, 10);
  ASSERT_EQ(plans.size(), 1u);
  const PressPlan& p = plans[0];
  EXPECT_EQ(p.contact.peak, 39);
  ASSERT_EQ(p.frame_indices.size(), 12u);
  EXPECT_TRUE(consecutive(p.frame_indices));
  // The best-scoring run ending at the peak: the rising frames, not the release.
  EXPECT_EQ(p.frame_indices.front(), 28);
  EXPECT_EQ(p.frame_indices.back(), 39);
  EXPECT_EQ(p.range_first, 10);
  EXPECT_EQ(p.range_last, 54);
}

TEST(PlanPresses, CentresThePeakWhenScoresAreEvenAndStaysInsideTheSource) {
  std::vector<float> s(40, 0.0f);
  for (int i = 0; i < 30; ++i) s[std::size_t(i)] = 2.0f;
  s[4] = 3.0f;  // the peak near the start: centred, the run would begin at frame -1
  const auto plans = plan_presses(s, segmenter(), 12, 10);
  ASSERT_EQ(plans.size(), 1u);
  EXPECT_EQ(plans[0].frame_indices.front(), 0) << "cannot start before frame 0";
  std::vector<float> even(60, 0.0f);
  for (int i = 10; i < 50; ++i) even[std::size_t(i)] = 2.0f;
  even[30] = 2.5f;
  const auto centred = plan_presses(even, segmenter(), 12, 10);
  const std::int64_t start = centred[0].frame_indices.front();
  EXPECT_TRUE(start == 24 || start == 25) << "peak at position 5 or 6 of 12, not " << start;
}

TEST(PlanPresses, AvoidsFramesThatDidNotDecodeAndNeverSharesFrames) {
  std::vector<float> s(80, 0.0f);
  for (int i = 10; i < 30; ++i) s[std::size_t(i)] = 3.0f;
  s[20] = 4.0f;
  s[24] = kNaN;
  for (int i = 34; i < 60; ++i) s[std::size_t(i)] = 3.0f;
  const auto plans = plan_presses(s, segmenter(), 12, 10);
  ASSERT_EQ(plans.size(), 2u);
  for (std::int64_t k : plans[0].frame_indices) EXPECT_NE(k, 24);
  EXPECT_LT(plans[0].range_last, plans[1].range_first);
  EXPECT_LT(plans[0].frame_indices.back(), plans[1].frame_indices.front());
}

// An in-memory source: frames are solid images whose grey level is their index; frames from 40 on
// come with their bytes (as an MJPG video's do), the earlier ones without.
class MemorySource : public FrameSource {
 public:
  explicit MemorySource(int frames) : frames_(frames) {}
  const std::string& path() const override { return path_; }
  cv::Size frame_size() const override { return {32, 24}; }
  double fps() const override { return 30; }
  std::string sha256() const override { return {}; }
  bool lossless() const override { return true; }
  void scan(const Visitor&, const std::function<bool(std::int64_t)>&) override {}
  void read(const std::vector<std::int64_t>& indices, const Delivery& deliver) override {
    requested = indices;
    for (auto i : indices) {
      const cv::Mat frame(24, 32, CV_8UC3, cv::Scalar::all(double(i)));
      deliver(i, frame, i >= 40 ? dataset::encode_png(frame) : dataset::EncodedImage{});
    }
  }
  std::vector<std::int64_t> requested;

 private:
  int frames_;
  std::string path_ = "memory";
};

TEST(ReadPressFrames, ReadsEachFrameOnceAndHandsOverEveryPressInOrder) {
  MemorySource source(100);
  PressPlan a, b;
  a.contact = {10, 20, 15, 1};
  a.frame_indices = {12, 13, 14, 15, 16};
  b.contact = {40, 50, 44, 1};
  b.frame_indices = {42, 43, 44, 45};
  std::vector<std::int64_t> seen_peaks;
  std::vector<std::size_t> encoded;
  read_press_frames(source, {a, b}, [&](const PressPlan& plan, PressFrames p) {
    ASSERT_EQ(p.frames.size(), plan.frame_indices.size());
    for (std::size_t i = 0; i < p.frames.size(); ++i) EXPECT_EQ(p.frames[i].at<cv::Vec3b>(0, 0)[0], plan.frame_indices[i]);
    seen_peaks.push_back(p.peak.at<cv::Vec3b>(0, 0)[0]);
    encoded.push_back(p.frames_encoded.size());
    for (std::size_t i = 0; i < p.frames_encoded.size(); ++i)
      EXPECT_EQ(cv::imdecode(p.frames_encoded[i], cv::IMREAD_COLOR).at<cv::Vec3b>(0, 0)[0], plan.frame_indices[i]);
    if (!p.frames_encoded.empty()) EXPECT_EQ(cv::imdecode(p.peak_encoded, cv::IMREAD_COLOR).at<cv::Vec3b>(0, 0)[0], 44);
    else EXPECT_TRUE(p.peak_encoded.empty());
  });
  EXPECT_EQ(seen_peaks, (std::vector<std::int64_t>{15, 44}));
  EXPECT_EQ(encoded, (std::vector<std::size_t>{0, 4})) << "bytes for all of a press's frames, or for none";
  EXPECT_EQ(source.requested, (std::vector<std::int64_t>{12, 13, 14, 15, 16, 42, 43, 44, 45}));
}

class VideoScores : public ::testing::Test {
 protected:
  haptex::test::TempDir dir_;
};

TEST_F(VideoScores, SkipsBlackFramesAveragesTheNextTenAndFindsEveryPress) {
  const std::string video = dir_.file("press_0.mkv");
  const auto depth = fixtures::write_press_video(video, quick_presses(2), 90);
  auto source = open_video(video);
  EXPECT_EQ(source->frame_size(), cv::Size(160, 120));
  EXPECT_NEAR(source->fps(), 30.0, 0.01);
  const SourceScores scores = score_source(*source, {});
  ASSERT_EQ(scores.scores.size(), 90u);
  EXPECT_EQ(scores.black_frames, 5);
  EXPECT_EQ(scores.reference_note, "mean of frames 5-14");
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(std::isnan(scores.scores[std::size_t(i)]));
  const auto plans = plan_presses(scores.scores, scores.contact->segmenter({}), 12, 10);
  ASSERT_EQ(plans.size(), 2u);
  for (const auto& p : plans) {
    EXPECT_EQ(depth[std::size_t(p.contact.peak)], 1.0) << "the peak is a fully pressed frame";
    EXPECT_GT(depth[std::size_t(p.contact.first)], 0.0);
    EXPECT_LE(depth[std::size_t(p.contact.last + 1)], 0.2) << "contact ends with the release";
  }
}

// A video that starts in contact (a press under way at frame 3) and ends released takes its no-contact
// reference from its end (docs/capture.md, "The no-contact reference"), says so, and finds the press.
TEST_F(VideoScores, AVideoThatStartsInContactTakesItsEnd) {
  const std::string video = dir_.file("touched.mkv");
  PressSchedule s = quick_presses(1);
  s.black_frames = 0;
  s.idle_frames = 3;
  const auto depth = fixtures::write_press_video(video, s, 60);
  auto source = open_video(video);
  const SourceScores scores = score_source(*source, {});
  EXPECT_EQ(scores.stale_frames, 0) << "a press under way is no stale start";
  EXPECT_EQ(scores.reference_kind, ReferenceKind::end);
  EXPECT_NE(scores.reference_note.find("mean of frames 50-59, the video's end (its start, frames 0-9, is not a steady "
                                       "no-contact stretch"),
            std::string::npos)
      << scores.reference_note;
  const auto plans = plan_presses(scores.scores, scores.contact->segmenter({}), 12, 10);
  ASSERT_EQ(plans.size(), 1u);
  EXPECT_EQ(depth[std::size_t(plans[0].contact.peak)], 1.0) << "the peak is a fully pressed frame";
}

// Frames of a gel pressed over discs (one depth list per disc centre), with noise, as a PNG sequence;
// `light` grey levels per frame, when given, are added to the whole image (a drifting light).
std::string pressed_sequence(const std::string& folder, const std::vector<std::pair<cv::Point, std::vector<double>>>& discs,
                             const std::vector<double>& light = {}) {
  std::filesystem::create_directories(folder);
  cv::RNG rng(5);
  for (std::size_t i = 0; i < discs.front().second.size(); ++i) {
    cv::Mat frame(120, 160, CV_32FC3);
    const float offset = light.empty() ? 0.0f : float(light[i]);
    for (int y = 0; y < frame.rows; ++y)
      for (int x = 0; x < frame.cols; ++x) frame.at<cv::Vec3f>(y, x) = cv::Vec3f::all(80.0f + offset + 0.5f * float(x) + 0.3f * float(y));
    for (const auto& [centre, depth] : discs) {
      cv::Mat mask = cv::Mat::zeros(frame.size(), CV_8U);
      cv::circle(mask, centre, discs.size() == 1 ? 50 : 25, cv::Scalar(255), cv::FILLED);
      cv::add(frame, cv::Scalar::all(depth[i]), frame, mask);
    }
    cv::Mat noise(frame.size(), CV_32FC3);
    rng.fill(noise, cv::RNG::NORMAL, 0, 1.0);
    cv::Mat pixels;
    cv::Mat(frame + noise).convertTo(pixels, CV_8UC3);
    cv::imwrite(folder + "/frame_" + std::to_string(100 + i) + ".png", pixels);
  }
  return folder;
}

// depth(i) for frames 0 to n - 1.
std::vector<double> depths(int n, const std::function<double(int)>& depth) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) out.push_back(depth(i));
  return out;
}

// The peak frame of the only press planned from `scores`; -1, and a failure, when there is not one.
std::int64_t only_peak(const SourceScores& scores) {
  const auto plans = plan_presses(scores.scores, scores.contact->segmenter({}), 12, 10);
  EXPECT_EQ(plans.size(), 1u) << scores.reference_note;
  return plans.size() == 1 ? plans[0].contact.peak : -1;
}

// Stale start-up frames (a driver's buffers of an earlier moment: here 4 frames of another touch, on
// the left) end in one jump to the live gel, larger than any later change: they are skipped as black
// frames are, and the press that follows (centre, rising over 5 frames) is the only one.
TEST_F(VideoScores, StaleStartUpFramesBeforeAJumpAreSkipped) {
  std::vector<double> stale, press;
  for (int i = 0; i < 50; ++i) {
    stale.push_back(i < 4 ? 40.0 : 0.0);
    press.push_back(i >= 20 && i < 35 ? 5.0 * std::min({i - 19, 35 - i, 5}) : 0.0);
  }
  auto source = open_image_sequence(pressed_sequence(dir_.file("stale"), {{{35, 60}, stale}, {{100, 60}, press}}));
  const SourceScores scores = score_source(*source, {});
  EXPECT_EQ(scores.stale_frames, 4);
  EXPECT_EQ(scores.reference_kind, ReferenceKind::start);
  EXPECT_NE(scores.reference_note.find("mean of frames 4-13; frames 0-3 are stale start-up frames"), std::string::npos)
      << scores.reference_note;
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::isnan(scores.scores[std::size_t(i)]));
  const std::int64_t peak = only_peak(scores);
  EXPECT_GE(peak, 24);
  EXPECT_LE(peak, 30);
}

// Stale frames in several jumps (one image at frame 0, another at frames 1 to 4, as the grasp-and-slip
// clips of docs/capture.md have them) before a press that comes on in one frame, a change more than
// half the last jump: they are skipped all the same, since neither stale image recurs.
TEST_F(VideoScores, StaleFramesInSeveralJumpsAreSkipped) {
  const auto first = depths(60, [](int i) { return i == 0 ? 60.0 : 0.0; });
  const auto second = depths(60, [](int i) { return i >= 1 && i < 5 ? 25.0 : 0.0; });
  const auto press = depths(60, [](int i) { return i >= 30 && i < 40 ? 20.0 : 0.0; });  // on and off in a frame each
  auto source = open_image_sequence(
      pressed_sequence(dir_.file("stale2"), {{{30, 40}, first}, {{30, 85}, second}, {{120, 60}, press}}));
  const SourceScores scores = score_source(*source, {});
  EXPECT_EQ(scores.stale_frames, 5) << scores.reference_note;
  EXPECT_EQ(scores.reference_kind, ReferenceKind::start);
  EXPECT_NE(scores.reference_note.find("mean of frames 5-14; frames 0-4 are stale start-up frames"), std::string::npos)
      << scores.reference_note;
  const std::int64_t peak = only_peak(scores);
  EXPECT_GE(peak, 30);
  EXPECT_LT(peak, 40);
}

// A press coming on in two large steps at frames 7 to 9 and held, then eased off slowly: the steady
// frames after its onset are no live start, since the untouched gel before it recurs at the end.
TEST_F(VideoScores, APressComingOnAtTheStartIsNoStaleStart) {
  const auto press = depths(60, [](int i) { return i < 8 ? 0.0 : i == 8 ? 15.0 : i < 30 ? 30.0 : std::max(0.0, 30.0 - 2.0 * (i - 30)); });
  auto source = open_image_sequence(pressed_sequence(dir_.file("onset"), {{{80, 60}, press}}));
  const SourceScores scores = score_source(*source, {});
  EXPECT_EQ(scores.stale_frames, 0) << scores.reference_note;
  EXPECT_EQ(scores.reference_kind, ReferenceKind::end) << scores.reference_note;
  const std::int64_t peak = only_peak(scores);
  EXPECT_GE(peak, 9);
  EXPECT_LT(peak, 31);
}

// Review 18, F1 and F2: a press on at frame 3 under a light that brightens 4 grey levels over the
// video (the untouched gel recurs, brighter), and one under way at frame 0 eased off over five frames
// (motion, not a driver's jump): neither start is stale, and each press is found.
TEST_F(VideoScores, APressAtTheStartUnderADriftingLightOrEasedOffIsNoStaleStart) {
  // on_at_3: a mean change of 2.5 grey levels, less than the drift
  const auto on_at_3 = depths(100, [](int i) { return i >= 3 && i <= 60 ? 6.0 : 0.0; });
  const auto eased = depths(100, [](int i) { return i < 5 ? 30.0 : std::max(0.0, 30.0 - 6.0 * (i - 4)); });
  const auto light = depths(100, [](int i) { return 4.0 * i / 99.0; });
  for (const auto& [name, depth, drift] : {std::tuple{"drift", on_at_3, light}, std::tuple{"eased", eased, std::vector<double>{}}}) {
    SCOPED_TRACE(name);
    auto source = open_image_sequence(pressed_sequence(dir_.file(name), {{{80, 60}, depth}}, drift));
    const SourceScores scores = score_source(*source, {});
    EXPECT_EQ(scores.stale_frames, 0) << scores.reference_note;
    const std::int64_t peak = only_peak(scores);
    ASSERT_GE(peak, 0);
    EXPECT_EQ(depth[std::size_t(peak)], *std::max_element(depth.begin(), depth.end())) << "the peak is a fully pressed frame";
  }
}

// A video that starts mid-touch and ends with dark frames (the sensor unplugged, a fade): the dark
// frames are no gel image, so the end's reference is the last frames before them.
TEST_F(VideoScores, DarkFramesAtTheEndAreNoReference) {
  std::vector<double> easing, press;
  for (int i = 0; i < 50; ++i) {
    easing.push_back(std::max(0.0, 30.0 - 3.0 * i));
    press.push_back(i >= 20 && i < 30 ? 6.0 * std::min(i - 19, 30 - i) : 0.0);
  }
  const std::string folder = pressed_sequence(dir_.file("dark"), {{{35, 60}, easing}, {{100, 60}, press}});
  for (int i = 50; i < 60; ++i) cv::imwrite(folder + "/frame_" + std::to_string(100 + i) + ".png", cv::Mat(120, 160, CV_8UC3, cv::Scalar::all(3)));
  auto source = open_image_sequence(folder);
  const SourceScores scores = score_source(*source, {});
  EXPECT_EQ(scores.reference_kind, ReferenceKind::end);
  EXPECT_EQ(scores.reference_first, 40);
  EXPECT_EQ(scores.reference_last, 49);
  const auto plans = plan_presses(scores.scores, scores.contact->segmenter({}), 12, 10);
  ASSERT_FALSE(plans.empty());
  EXPECT_TRUE(std::any_of(plans.begin(), plans.end(), [](const PressPlan& p) { return p.contact.peak >= 23 && p.contact.peak <= 26; }))
      << "the press at frames 20 to 29 is found";
}

// A press coming on slowly over the reference frames (0.6 grey levels a frame) puts no two of them
// over the trigger, but the trend between their halves rules the start out, and the note says why.
TEST_F(VideoScores, NamesTheTrendOfAPressComingDuringTheReferenceFrames) {
  std::vector<double> depth;
  for (int i = 0; i < 30; ++i) depth.push_back(0.6 * std::min(i, 12));
  auto source = open_image_sequence(pressed_sequence(dir_.file("slow"), {{{80, 60}, depth}}));
  const SourceScores scores = score_source(*source, {});
  EXPECT_NE(scores.reference_kind, ReferenceKind::start);
  EXPECT_NE(scores.reference_note.find("not a steady no-contact stretch: they change from the first to the last"),
            std::string::npos)
      << scores.reference_note;
}

// Contact at both ends, changing every frame (a grasp filmed from mid-squeeze to mid-release): the
// start's imprint (left) fades over the first 20 frames from 20 grey levels, the press (centre) rises
// to 30 at frame 20 and is gone by frame 30, the end's imprint (right) comes to 8. The end of least contact (the
// last frames) is the reference, and the strongest frame is the peak of the one press.
TEST_F(VideoScores, NeitherEndSteadyTakesTheEndOfLeastContact) {
  std::vector<double> left, centre, right;
  for (int i = 0; i < 40; ++i) {
    left.push_back(std::max(0.0, 20.0 - i));
    centre.push_back(std::max(0.0, 30.0 - 3.0 * std::abs(i - 20)));
    right.push_back(std::max(0.0, 0.6 * (i - 26)));
  }
  auto source = open_image_sequence(pressed_sequence(dir_.file("grasp"), {{{35, 60}, left}, {{80, 60}, centre}, {{125, 60}, right}}));
  const SourceScores scores = score_source(*source, {});
  EXPECT_EQ(scores.reference_kind, ReferenceKind::least_contact);
  EXPECT_NE(scores.reference_note.find("mean of frames 30-39, the video's end, the end of least contact"), std::string::npos)
      << scores.reference_note;
  const auto plans = plan_presses(scores.scores, scores.contact->segmenter({}), 12, 10);
  ASSERT_EQ(plans.size(), 1u) << "level " << scores.contact->level() << " jitter " << scores.contact->spread() << " trigger "
                              << scores.contact->trigger();
  EXPECT_NEAR(double(plans[0].contact.peak), 20.0, 1.0);
}

TEST_F(VideoScores, AGivenReferenceMustHaveTheFrameSize) {
  const std::string video = dir_.file("v.mkv");
  fixtures::write_press_video(video, quick_presses(1), 40);
  auto source = open_video(video);
  ExtractSettings settings;
  settings.reference_image = cv::Mat(100, 100, CV_8UC3, cv::Scalar::all(90));
  settings.reference_image_path = "ref.png";
  try {
    score_source(*source, settings);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ref.png: the reference image is 100x100 but the frames of"), std::string::npos) << e.what();
  }
}

TEST_F(VideoScores, RefusesFilesThatAreNotVideos) {
  const std::string path = dir_.file("notes.avi");
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("not a video", f);
  std::fclose(f);
  try {
    open_video(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("notes.avi"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace haptex::capture
