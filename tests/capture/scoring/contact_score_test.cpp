// The contact score ignores noise and uniform brightness changes and grows with a press.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "capture/scoring/contact_score.hpp"

namespace haptex::capture {
namespace {

cv::Mat flat_gel() {
  cv::Mat image(120, 160, CV_32F);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) image.at<float>(y, x) = 80.0f + 0.5f * float(x) + 0.3f * float(y);
  return image;
}

cv::Mat with_noise(const cv::Mat& image, double sigma, std::uint64_t seed) {
  cv::Mat noise(image.size(), CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
  return image + noise;
}

// `count` frames of image, each with its own noise (seeds from `seed` up).
std::vector<cv::Mat> noisy_frames(const cv::Mat& image, double sigma, int count, std::uint64_t seed) {
  std::vector<cv::Mat> frames;
  for (int i = 0; i < count; ++i) frames.push_back(with_noise(image, sigma, seed + std::uint64_t(i)));
  return frames;
}

cv::Mat pressed(const cv::Mat& image, float depth, int radius = 25) {
  cv::Mat out = image.clone();
  cv::circle(out, {80, 60}, radius, cv::Scalar(0), cv::FILLED);  // mask, filled below
  cv::Mat mask = cv::Mat::zeros(image.size(), CV_8U);
  cv::circle(mask, {80, 60}, radius, cv::Scalar(255), cv::FILLED);
  out = image.clone();
  cv::add(out, cv::Scalar(depth), out, mask);
  return out;
}

TEST(ContactScore, IsZeroForTheReferenceAndForNoiseBelowTheThreshold) {
  const cv::Mat ref = flat_gel();
  EXPECT_EQ(contact_score(ref, ref, 6), 0.0f);
  EXPECT_LT(contact_score(with_noise(ref, 1.0, 1), ref, 6), 1e-4f);
}

TEST(ContactScore, IgnoresUniformBrightnessDrift) {
  const cv::Mat ref = flat_gel();
  EXPECT_LT(contact_score(ref + 15.0, ref, 6), 1e-6f) << "an exposure step moves the median, not the score";
  EXPECT_GT(contact_score(pressed(ref, 20) + 15.0, ref, 6), 0.5f) << "the press still shows through the drift";
}

TEST(ContactScore, GrowsWithDepthAndArea) {
  const cv::Mat ref = flat_gel();
  const float shallow = contact_score(pressed(ref, 10), ref, 6);
  const float deep = contact_score(pressed(ref, 30), ref, 6);
  const float wide = contact_score(pressed(ref, 30, 40), ref, 6);
  EXPECT_GT(shallow, 0.0f);
  EXPECT_GT(deep, shallow);
  EXPECT_GT(wide, deep);
  // Mean excess over the threshold: a disc of radius 25 (1963 of 19200 pixels) 30 levels deep.
  EXPECT_NEAR(deep, (30 - 6) * 1963.0f / 19200.0f, 0.1f);
}

// The footage's own frames set the thresholds: the score is the plain mean |residual| (no per-pixel
// threshold), and the leave-one-out scores of the reference frames give the no-contact level and
// its jitter. This gel is a pure ramp, so the drift fit's gain column (the reference less its ramps)
// is the other frames' mean noise and takes it out: the residual is the frame's own noise, and the
// level is E |N(0, sigma)| = sqrt(2 / pi) sigma = 0.798 sigma. Over 19200 pixels its jitter is far
// smaller, and the level term (half the level) sets the trigger.
TEST(ContactReference, TheFootagesOwnNoiseSetsTheThresholds) {
  const cv::Mat gel = flat_gel();
  std::vector<cv::Mat> quiet, noisy;
  for (int i = 0; i < 10; ++i) {
    quiet.push_back(with_noise(gel, 0.5, 10 + std::uint64_t(i)));
    noisy.push_back(with_noise(gel, 3.0, 30 + std::uint64_t(i)));
  }
  const ContactReference q = ContactReference::from_frames(quiet);
  const ContactReference n = ContactReference::from_frames(noisy);
  EXPECT_NEAR(q.noise(), 0.5f, 0.05f);
  EXPECT_NEAR(n.noise(), 3.0f, 0.2f);
  EXPECT_EQ(n.pixel_threshold(), 0.0f);
  EXPECT_NEAR(n.level(), 0.798f * 3.0f, 0.05f);
  EXPECT_NEAR(n.level() / q.level(), 6.0f, 0.3f) << "the level scales with the noise";
  EXPECT_LT(n.spread(), 0.05f * n.level()) << "a mean over 19200 pixels hardly moves from frame to frame";
  EXPECT_FLOAT_EQ(n.trigger(), n.level() + std::max({5 * n.spread(), 0.5f * n.level(), 0.05f}));
  EXPECT_FLOAT_EQ(n.trigger(), 1.5f * n.level());
  EXPECT_FLOAT_EQ(n.release(), 1.25f * n.level());
  EXPECT_TRUE(q.steady() && n.steady());
  // A fresh noisy frame (not among the reference frames) stays at the level, under the trigger; a
  // press 40 grey levels deep over a tenth of the gel (13 sigma) is well above it.
  EXPECT_LT(n.score(with_noise(gel, 3.0, 99)), 1.1f * n.level());
  EXPECT_GT(n.score(with_noise(pressed(gel, 40), 3.0, 98)), 1.5f * n.trigger());
  const SegmenterSettings s = n.segmenter({});
  EXPECT_EQ(s.level, n.level());
  EXPECT_EQ(s.trigger, n.trigger());
}

// Where the score jitters from frame to frame (a sensor whose noise changes: compression at a
// varying rate, flicker), the jitter sets the trigger: five robust standard deviations over the level.
TEST(ContactReference, TheScoresJitterSetsTheTriggerWhereItIsLarge) {
  const cv::Mat gel = flat_gel();
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(with_noise(gel, 1.0 + 0.25 * (i % 4), 600 + std::uint64_t(i)));
  const ContactReference r = ContactReference::from_frames(frames);
  EXPECT_GT(5 * r.spread(), 0.5f * r.level()) << "level " << r.level() << " spread " << r.spread();
  EXPECT_FLOAT_EQ(r.trigger(), r.level() + 5 * r.spread());
  EXPECT_LT(r.score(with_noise(gel, 1.75, 700)), r.trigger()) << "the noisiest no-contact frame is no press";
}

// A press coming during the reference frames is refused, even when it spoils most of them.
TEST(ContactReference, APressDuringTheReferenceFramesIsNoSteadyReference) {
  const cv::Mat gel = flat_gel();
  std::vector<cv::Mat> ramp;
  for (int i = 0; i < 10; ++i) ramp.push_back(with_noise(pressed(gel, std::max(0.0f, float(i - 2)) * 4.0f), 1.0, 50 + std::uint64_t(i)));
  const ContactReference r = ContactReference::from_frames(ramp);
  EXPECT_FALSE(r.steady()) << "level " << r.level() << " trigger " << r.trigger() << " worst " << r.worst_reference_score() << " noise " << r.noise();
  std::vector<cv::Mat> touch;
  for (int i = 0; i < 10; ++i) touch.push_back(with_noise(i == 6 || i == 7 ? pressed(gel, 30) : gel, 1.0, 70 + std::uint64_t(i)));
  EXPECT_FALSE(ContactReference::from_frames(touch).steady());
}

// A lone odd frame (an encoder's first frame at another quality, a flicker) is no press: a press
// lasts, and the segmenter asks for two frames in a row too.
TEST(ContactReference, ALoneOddFrameInTheReferenceIsNoPress) {
  const cv::Mat gel = flat_gel();
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(with_noise(gel, i == 0 ? 3.0 : 1.0, 80 + std::uint64_t(i)));
  const ContactReference r = ContactReference::from_frames(frames);
  EXPECT_TRUE(r.steady()) << "worst two in a row " << r.worst_reference_score() << " trigger " << r.trigger();
  EXPECT_GT(r.score(frames[0]), r.trigger()) << "alone, the frame is contact";
}

// Nor does a lone odd frame with structure (a checkerboard of 8 grey levels, as an encoder's first
// frame can show) make a trend: the frame least like the others is left out of the halves' means.
TEST(ContactReference, ALoneStructuredOddFrameMakesNoTrend) {
  const cv::Mat gel = flat_gel();
  cv::Mat checker(gel.size(), CV_32F);
  for (int y = 0; y < gel.rows; ++y)
    for (int x = 0; x < gel.cols; ++x) checker.at<float>(y, x) = (x / 4 + y / 4) % 2 ? 8.0f : -8.0f;
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(with_noise(i == 0 ? gel + checker : gel, 1.0, 200 + std::uint64_t(i)));
  const ContactReference r = ContactReference::from_frames(frames);
  EXPECT_FALSE(r.trending()) << "trend " << r.trend() << " over " << r.trend_limit();
  EXPECT_TRUE(r.steady());
}

// A press coming on so slowly that no frame stands out from the mean of the others still changes the
// first half of the reference frames against the second: the trend refuses it.
TEST(ContactReference, APressComingSlowlyIsATrend) {
  const cv::Mat gel = flat_gel();
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 10; ++i) frames.push_back(with_noise(pressed(gel, 0.6f * float(i), 50), 1.0, 300 + std::uint64_t(i)));
  const ContactReference r = ContactReference::from_frames(frames);
  EXPECT_LE(r.worst_reference_score(), r.trigger()) << "no two frames in a row stand out";
  EXPECT_TRUE(r.trending()) << "trend " << r.trend() << " over " << r.trend_limit();
  EXPECT_FALSE(r.steady());
}

// Inter-frame video: the reference frames copy each other (no noise to see), so the noise, t and the
// level come from the later no-contact frames, robust to a press in a few of them.
TEST(ContactReference, CalibrationTakesTheThresholdsFromLaterFrames) {
  const cv::Mat gel = flat_gel();
  const cv::Mat first = with_noise(gel, 2.0, 90);
  const std::vector<cv::Mat> copies(10, first);
  std::vector<cv::Mat> later;
  for (int i = 0; i < 25; ++i) later.push_back(with_noise(i == 3 || i == 4 ? pressed(first, 30) : first, 2.0, 100 + std::uint64_t(i)));
  const ContactReference own = ContactReference::from_frames(copies);
  EXPECT_LT(own.noise(), 0.01f) << "copies show no noise";
  const ContactReference c = ContactReference::from_calibration(copies, later);
  EXPECT_NEAR(c.noise(), 2.0f, 0.2f);
  EXPECT_EQ(c.pixel_threshold(), 0.0f);
  // Against a noise-free reference r ~ N(0, 2): E |r| = sqrt(2 / pi) x 2 = 1.596.
  EXPECT_NEAR(c.level(), 0.798f * 2.0f, 0.06f) << "the press in frames 3 and 4 does not move the median";
  EXPECT_FLOAT_EQ(c.trigger(), c.level() + std::max({5 * c.spread(), 0.5f * c.level(), 0.05f}));
  EXPECT_TRUE(c.steady());
  EXPECT_FALSE(c.held_contact());
  EXPECT_GT(c.score(later[3]), c.trigger() + 2 * (c.trigger() - c.level()));
  ScoreSettings fixed;
  fixed.trigger = 0.4f;
  const ContactReference given = ContactReference::from_calibration(copies, later, fixed);
  EXPECT_EQ(given.trigger(), 0.4f) << "the user's trigger stands";
  EXPECT_NEAR(given.level(), c.level(), 1e-6f) << "and the level is still measured";
  EXPECT_EQ(ContactReference::from_calibration(copies, {}).trigger(), own.trigger()) << "no later frames: the reference's own";
  // A video cut short after its reference: too few later frames to judge by, and no trend either
  // (the copies' own level is near 0, which a step of compression would pass).
  std::vector<cv::Mat> stepped = copies;
  for (std::size_t i = 5; i < stepped.size(); ++i) stepped[i] = first + 0.5;
  const std::vector<cv::Mat> three(later.begin() + 10, later.begin() + 13);
  const ContactReference short_video = ContactReference::from_calibration(stepped, three);
  EXPECT_EQ(short_video.trigger(), ContactReference::from_frames(stepped).trigger());
  EXPECT_FALSE(short_video.trending());
}

// A touch while an inter-frame video's reference frames are taken (frames 6 to 9, copies of a pressed
// frame) and its first calibration frames: the quiet frames' own level judges it, not their level
// against the reference mean, which the touch raises as much as the touch's own scores.
TEST(ContactReference, ATouchDuringAnInterFrameReferenceIsNotSteady) {
  const cv::Mat gel = flat_gel();
  const cv::Mat first = with_noise(gel, 2.0, 90), touched = with_noise(pressed(gel, 10), 2.0, 91);
  std::vector<cv::Mat> copies(10, first);
  for (std::size_t i = 6; i < 10; ++i) copies[i] = touched;
  std::vector<cv::Mat> later;
  for (int i = 0; i < 25; ++i) later.push_back(with_noise(i < 4 ? pressed(first, 10) : first, 2.0, 500 + std::uint64_t(i)));
  const ContactReference c = ContactReference::from_calibration(copies, later);
  EXPECT_FALSE(c.steady()) << "worst " << c.worst_reference_score() << " limit " << c.reference_limit() << " trend "
                           << c.trend() << " limit " << c.trend_limit();
}

// A noise-free source (PNG from a simulator) has a level of 0: a change of a fraction of a grey level
// in a few pixels is no trend.
TEST(ContactReference, TheTrendHasAFloorForANoiseFreeSource) {
  cv::Mat step = flat_gel();
  step(cv::Rect(10, 10, 4, 4)) += 2.0;
  std::vector<cv::Mat> frames(5, flat_gel());
  for (int i = 0; i < 5; ++i) frames.push_back(step);
  const ContactReference r = ContactReference::from_frames(frames);
  EXPECT_LT(r.level(), 1e-4f);
  EXPECT_GT(r.trend(), r.level()) << "over the level alone, the step would be refused";
  EXPECT_TRUE(r.steady()) << "trend " << r.trend() << " limit " << r.trend_limit();
}

// A press in most of the calibration frames (18 of 25, a user who pressed right after the reference)
// is left out of them: it scores over the trigger their quietest quarter sets, so the level stays the
// no-contact one and the press stands above the trigger.
TEST(ContactReference, CalibrationLeavesOutAPressInMostOfItsFrames) {
  const cv::Mat gel = flat_gel();
  const cv::Mat first = with_noise(gel, 2.0, 90);
  const std::vector<cv::Mat> copies(10, first);
  std::vector<cv::Mat> later;
  for (int i = 0; i < 25; ++i)
    later.push_back(with_noise(i >= 2 && i < 20 ? pressed(first, 10) : first, 2.0, 400 + std::uint64_t(i)));
  const ContactReference c = ContactReference::from_calibration(copies, later);
  EXPECT_NEAR(c.noise(), 2.0f, 0.2f);
  EXPECT_NEAR(c.level(), 0.798f * 2.0f, 0.06f);
  EXPECT_GT(c.score(later[10]), c.trigger()) << "the press is found";
  EXPECT_LT(c.score(later[22]), c.trigger());
}

// A grasp held from right after the reference to the end (docs/capture.md, "The thresholds"): every
// calibration frame is in contact, and their level against the reference, far over their noise, is
// the contact's. The reference frames' own level judges, so the grasp stands over the trigger.
TEST(ContactReference, ACalibrationHeldInContactKeepsTheReferencesLevel) {
  const cv::Mat gel = flat_gel();
  const std::vector<cv::Mat> frames = noisy_frames(gel, 2.0, 10, 600), later = noisy_frames(pressed(gel, 40, 30), 2.0, 25, 700);
  const ContactReference own = ContactReference::from_frames(frames);
  const ContactReference c = ContactReference::from_calibration(frames, later);
  EXPECT_TRUE(c.held_contact());
  EXPECT_EQ(c.level(), own.level());
  EXPECT_GT(c.score(later[12]), c.trigger());
  EXPECT_TRUE(c.steady()) << "trend " << c.trend() << " limit " << c.trend_limit();
}

// A still clip of an inter-frame codec (WeakFootage's still_synthetic_gel_0_mp4v; review 17, F2's
// H.264 clips): each group of 12 pictures nearly copies its key frame, and each key frame changes a few
// pixels of the gel (the median pixel not at all, so the noise is tiny), by as much against the group
// before as against the reference's. That is the codec, not a contact, though its level stands far
// over the noise; and where the frames copy one another exactly, no noise is seen at all.
TEST(ContactReference, ACodecsGroupsOfPicturesAreNoHeldContact) {
  const cv::Mat gel = flat_gel();
  const cv::Mat first = with_noise(gel, 2.0, 90);
  for (double jitter : {0.02, 0.0}) {
    SCOPED_TRACE("jitter " + std::to_string(jitter));
    const auto frame = [&](const cv::Mat& key, int i) { return jitter > 0 ? with_noise(key, jitter, 1000 + std::uint64_t(i)) : key.clone(); };
    std::vector<cv::Mat> reference, later;
    for (int i = 0; i < 10; ++i) reference.push_back(frame(first, i));
    for (int i = 0; i < 36; ++i) {  // groups of 12 frames
      cv::RNG rng(800 + std::uint64_t(i / 12));
      cv::Mat key = first.clone();
      for (auto& v : cv::Mat_<float>(key)) v += rng.uniform(0.0f, 1.0f) < 0.1f ? float(rng.gaussian(5.0)) : 0.0f;
      later.push_back(frame(key, 100 + i));
    }
    const ContactReference c = ContactReference::from_calibration(reference, later);
    if (jitter > 0) {
      EXPECT_GT(c.level(), 2.5f * c.noise()) << "the level alone would call it held";
    }
    EXPECT_FALSE(c.held_contact());
  }
}

// A driver's stale buffers: ten copies of one frame, then the live stream, whose noise an inter-frame
// codec bakes into a texture that barely changes from frame to frame (review 17, F5). The live frames
// stand far from the copies against their own small noise, but the change is everywhere alike.
TEST(ContactReference, LiveNoiseAfterStaleCopiesIsNoHeldContact) {
  const cv::Mat gel = flat_gel();
  const std::vector<cv::Mat> stale(10, gel);
  const std::vector<cv::Mat> later = noisy_frames(with_noise(gel, 1.0, 77), 0.05, 25, 1100);
  const ContactReference c = ContactReference::from_calibration(stale, later);
  EXPECT_GT(c.level(), 2.5f * c.noise()) << "the level alone would call it held";
  EXPECT_FALSE(c.held_contact());
}

// The camera's exposure changes for good right after the reference (review 17, F1: a gamma on the whole
// image, and the light falling off towards the edges): every calibration frame is far from the
// reference, as in a grasp, but a change of the light explains it, and it is no contact.
TEST(ContactReference, AChangeOfTheLightAfterTheReferenceIsNoHeldContact) {
  const cv::Mat gel = 20.0f + (flat_gel() - 80.0f) * 1.8f;  // grey 20 to 228: a gamma bends it
  cv::Mat gamma(gel.size(), CV_32F), edges(gel.size(), CV_32F);
  for (int y = 0; y < gel.rows; ++y)
    for (int x = 0; x < gel.cols; ++x) {
      const float g = gel.at<float>(y, x), u = float(x) / float(gel.cols) - 0.5f;
      gamma.at<float>(y, x) = 255.0f * std::pow(g / 255.0f, 0.6f);
      edges.at<float>(y, x) = g + 40.0f * u * u;
    }
  const std::vector<cv::Mat> frames = noisy_frames(gel, 0.5, 10, 900);
  for (const cv::Mat& lit : {gamma, edges}) {
    const ContactReference c = ContactReference::from_calibration(frames, noisy_frames(lit, 0.5, 25, 950));
    EXPECT_GT(c.level(), 2.5f * c.noise()) << "far from the reference, as a grasp is";
    EXPECT_FALSE(c.held_contact());
  }
}

TEST(ContactReference, AGivenImageUsesTheFloors) {
  const ContactReference r = ContactReference::from_image(flat_gel());
  EXPECT_EQ(r.noise(), 0.0f);
  EXPECT_FLOAT_EQ(r.pixel_threshold(), 6.0f);
  EXPECT_FLOAT_EQ(r.trigger(), 0.25f);
}

}  // namespace
}  // namespace haptex::capture
