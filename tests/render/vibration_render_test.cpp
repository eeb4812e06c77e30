// Rendering a trajectory into vibration (render/vibration_render.hpp) and writing it as WAV
// (render/wav_writer.hpp), with a small model trained in memory on the synthetic problem.
#include "render/vibration_render.hpp"
#include "dataset/window.hpp"
#include "predict/texture_choice.hpp"

#include <gtest/gtest.h>
#include <sndfile.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "predict/train.hpp"
#include "predict/trajectory.hpp"
#include "render/wav_writer.hpp"
#include "tests/predict/synthetic_problem.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/wav_file.hpp"

namespace haptex::render {
namespace {
namespace fs = std::filesystem;

const predict::Model& model() {
  static const predict::Model trained = [] {
    predict::TrainOptions o;
    o.latent = 8, o.texture_hidden = 16, o.predictor_hidden = 32, o.max_epochs = 20, o.texture_max_epochs = 5;
    return predict::train_model(test::synthetic_problem(), o);
  }();
  return trained;
}

predict::TextureCode code(int material = 1) { return predict::Predictor(model()).material_code(material); }

// A stroke as a hand makes it: speed swinging 40..240 mm/s, force wandering 0.7..2.3 N.
predict::Trajectory stroke(std::size_t n) {
  predict::Trajectory t;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = double(i) * 1e-4;
    t.speed.push_back(float(140 + 100 * std::sin(2 * std::numbers::pi * 0.7 * s)));
    t.force.push_back(float(1.5 + 0.8 * std::sin(2 * std::numbers::pi * 0.3 * s + 1)));
  }
  return t;
}

predict::Trajectory constant(std::size_t n, float force, float speed) {
  return {std::vector<float>(n, force), std::vector<float>(n, speed)};
}

RenderOptions with(Reconstruction r, std::size_t iterations) {
  RenderOptions o;
  o.reconstruction = r;
  if (r == Reconstruction::fgla)
    o.fgla.iterations = iterations;
  else
    o.online.iterations = iterations;
  return o;
}

TEST(RenderVibrationRender, OneFramePerHundredSamplesFromSampleZero) {
  EXPECT_EQ(render_frames(9), 0u);
  EXPECT_EQ(render_frames(10), 1u);
  EXPECT_EQ(render_frames(100), 1u);
  EXPECT_EQ(render_frames(101), 2u);
  EXPECT_EQ(frame_action_sample(0, 2345), 500u);
  EXPECT_EQ(frame_action_sample(18, 2345), 2300u);
  EXPECT_EQ(frame_action_sample(19, 2345), 2344u);  // past the end: the 45 ms up to the last sample
  const predict::Trajectory t = stroke(2345);
  for (Reconstruction r : {Reconstruction::fgla, Reconstruction::online}) {
    const Rendering out = render_vibration(model(), code(), t, with(r, 4));
    ASSERT_EQ(out.signal.size(), t.force.size());
    ASSERT_EQ(out.targets.frames, 24u);  // frames from samples 0, 100, ..., 2300
    EXPECT_EQ(out.first_frame_sample, 0u);
    // Frame m is the model's spectrum for the action ending at its middle, 500 + 100 m (or the last sample).
    predict::Predictor p(model());
    std::vector<float> spectrum(dataset::kTargetBins);
    std::vector<double> expected(kReconstructionBins);
    float action[dataset::kActionValues];
    for (std::size_t m : {0u, 7u, 23u}) {
      predict::action_at(t, std::min<std::size_t>(500 + 100 * m, 2344), action);
      p.predict(code(), action, spectrum);
      target_magnitude_frame(std::span<const float>(spectrum), expected);
      for (std::size_t k = 0; k < kReconstructionBins; ++k) ASSERT_NEAR(out.targets.row(m)[k], expected[k], 1e-12) << m << " " << k;
    }
    // Frame 0 starts at sample 0, where the periodic Hann window is 0: sample 0 is silent, sample 1 on sound.
    EXPECT_EQ(out.signal[0], 0.0) << reconstruction_name(r);
    double early = 0;
    for (std::size_t n = 1; n < 100; ++n) early = std::max(early, std::abs(out.signal[n]));
    EXPECT_GT(early, 0.0) << reconstruction_name(r);
    for (double x : out.signal) ASSERT_TRUE(std::isfinite(x));
  }
}

// The offline method with its full 100 iterations and the live one (a few frames at a time) are about
// as consistent with the predicted spectra (on this problem within 0.3 dB of each other, either way
// depending on the model), and both far better than the random initial phase alone, in spectral
// convergence and in the evaluation's spectral distance.
TEST(RenderVibrationRender, FglaAndOnlineBeatRandomPhase) {
  const predict::Trajectory t = stroke(30000);
  double sc[3], distance[3];
  RenderOptions steady = with(Reconstruction::online, 4);
  steady.online.scatter = false;  // the reconstruction's own consistency; scatter moves it off the prediction on purpose
  const RenderOptions options[3] = {with(Reconstruction::fgla, 100), steady, with(Reconstruction::fgla, 0)};
  const char* names[3] = {"fgla 100", "online (steady)", "random phase"};
  for (int i = 0; i < 3; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const Rendering out = render_vibration(model(), code(), t, options[i]);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(complete_frames(out), 291u);  // 100 m + 1000 <= 30000
    sc[i] = rendered_convergence_db(out);
    distance[i] = rendered_distance(out);
    double norm = 0;
    for (std::size_t m = 0; m < complete_frames(out); ++m) {
      double e = 0;
      for (std::size_t k = 0; k < 100; ++k) e += double(out.spectra[m * 100 + k]) * out.spectra[m * 100 + k];
      norm += std::sqrt(e) / double(complete_frames(out));
    }
    std::printf("[ figures  ] %s: SC %.1f dB, spectral distance %.4f m/s^2 (%.0f %% of the spectra's norm), %.1f ms per second of vibration\n",
                names[i], sc[i], distance[i], 100 * distance[i] / norm, seconds / 3 * 1e3);
  }
  // The model's spectra are expected values, smoother than any signal's, so no signal has them
  // exactly: FGLA levels off near -15 dB (300 iterations gain 0.1 dB) and the online method comes
  // as close. Both are far from the random initial phase, in the evaluation's distance too.
  EXPECT_LT(sc[0], -12.0);
  EXPECT_LT(sc[1], -12.0);
  EXPECT_LT(sc[1], sc[2] - 6.0);
  EXPECT_LT(std::max(distance[0], distance[1]), 0.6 * distance[2]);
  EXPECT_LT(sc[2], 0.0);
}

// The online method's look-ahead is compensated: its rendering lines up with the offline one. A
// stroke that starts slow and light and turns fast and firm at sample 15000 gets louder at the same
// place in both, just before the step (the frames are centred on their actions); uncompensated, the
// online one would rise 300 samples later. As played (live), it is the compensated signal delayed by
// half a frame, the latency and one sample.
TEST(RenderVibrationRender, OnlineLatencyIsCompensatedOrPlayedAsLive) {
  predict::Trajectory t = constant(30000, 0.3f, 30.0f);
  std::fill(t.force.begin() + 15000, t.force.end(), 2.8f);
  std::fill(t.speed.begin() + 15000, t.speed.end(), 280.0f);
  auto rise = [](const std::vector<double>& x) {  // first 100-sample block at half the loud RMS
    std::vector<double> rms;
    for (std::size_t b = 0; b + 100 <= x.size(); b += 100) {
      double e = 0;
      for (std::size_t n = b; n < b + 100; ++n) e += x[n] * x[n];
      rms.push_back(std::sqrt(e / 100));
    }
    double loud = 0;
    for (std::size_t b = 200; b < 280; ++b) loud += rms[b] / 80;
    std::size_t b = 0;
    while (rms[b] < 0.5 * loud) ++b;
    return long(b);
  };
  const Rendering offline = render_vibration(model(), code(), t, with(Reconstruction::fgla, 100));
  const Rendering online = render_vibration(model(), code(), t, with(Reconstruction::online, 4));
  EXPECT_EQ(online.latency_samples, 300u);
  const long offline_rise = rise(offline.signal), online_rise = rise(online.signal);
  std::printf("[ figures  ] the step at block 150: rendering at half its loud RMS from block %ld\n", offline_rise);
  // Frames predicted from the action at their start would rise about 5 blocks later, from their end 5 earlier.
  EXPECT_GE(offline_rise, 148);
  EXPECT_LE(offline_rise, 153);
  EXPECT_NEAR(online_rise, offline_rise, 1);

  RenderOptions live = with(Reconstruction::online, 4);
  live.as_played = true;
  const Rendering played = render_vibration(model(), code(), t, live);
  // The tick that knows the action ending at a frame's middle plays it from the next sample on.
  const std::size_t delay = 500 + online.latency_samples + 1;
  EXPECT_EQ(played.first_frame_sample, delay);
  for (std::size_t n = 0; n < delay; ++n) ASSERT_EQ(played.signal[n], 0.0) << n;
  for (std::size_t n = delay; n < t.force.size(); ++n) ASSERT_EQ(played.signal[n], online.signal[n - delay]) << n;
  EXPECT_NEAR(rendered_convergence_db(played), rendered_convergence_db(online), 0.5);
}

// At rest the model saturates force and speed into its training range: finite output, every frame
// flagged, and still a consistent rendering.
TEST(RenderVibrationRender, ZeroForceAndSpeedGiveFiniteOutput) {
  const predict::Trajectory t = constant(5000, 0.0f, 0.0f);
  for (Reconstruction r : {Reconstruction::fgla, Reconstruction::online}) {
    const Rendering out = render_vibration(model(), code(), t, with(r, 4));
    EXPECT_EQ(out.saturated_frames, out.targets.frames) << reconstruction_name(r);
    for (double x : out.signal) ASSERT_TRUE(std::isfinite(x)) << reconstruction_name(r);
    EXPECT_TRUE(std::isfinite(rendered_convergence_db(out))) << reconstruction_name(r);
  }
  EXPECT_EQ(render_vibration(model(), code(), stroke(3000), with(Reconstruction::fgla, 1)).saturated_frames, 0u);
}

TEST(RenderVibrationRender, ShortTrajectories) {
  try {
    render_vibration(model(), code(), stroke(9));
    FAIL() << "9 samples rendered";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("at least 10"), std::string::npos) << e.what();
  }
  predict::Trajectory unpaired = stroke(500);
  unpaired.speed.pop_back();
  EXPECT_THROW(render_vibration(model(), code(), unpaired), Error);
  // Under 0.1 s after the first frame no frame lies wholly inside the signal: no SC.
  for (Reconstruction r : {Reconstruction::fgla, Reconstruction::online}) {
    const Rendering out = render_vibration(model(), code(), stroke(999), with(r, 2));
    EXPECT_EQ(out.signal.size(), 999u);
    EXPECT_EQ(complete_frames(out), 0u);
    EXPECT_TRUE(std::isnan(rendered_convergence_db(out)));
    EXPECT_EQ(complete_frames(render_vibration(model(), code(), stroke(1000), with(r, 2))), 1u);
  }
}

TEST(RenderVibrationRender, ReconstructionNames) {
  EXPECT_EQ(parse_reconstruction("fgla"), Reconstruction::fgla);
  EXPECT_EQ(parse_reconstruction(reconstruction_name(Reconstruction::online)), Reconstruction::online);
  EXPECT_EQ(parse_reconstruction(reconstruction_name(Reconstruction::noise)), Reconstruction::noise);
  EXPECT_THROW(parse_reconstruction("pghi"), Error);
}

// The live loop's tick predicts, converts and pushes without touching the heap, with RTISI-LA or
// shaped noise; the noise has no look-ahead, so every tick returns its 100 samples.
TEST(RenderVibrationRender, LiveTicksDoNotAllocate) {
  {
    const test::CountAllocations probe;
    const std::vector<double> v(100);
    ASSERT_GT(probe.count(), 0u) << "the allocation counter sees nothing";
  }
  const predict::Trajectory t = stroke(3000);
  for (const bool noise : {false, true}) {
    VibrationLoop loop = noise ? VibrationLoop(model(), code(), ShapedNoiseOptions{}) : VibrationLoop(model(), code(), OnlineReconstructionOptions{});
    float action[dataset::kActionValues];
    std::size_t samples = 0;
    for (std::size_t m = 0; m < render_frames(t.force.size()); ++m) {
      predict::action_at(t, frame_action_sample(m, t.force.size()), action);
      const test::CountAllocations counter;
      samples += loop.tick(action).size();
      ASSERT_EQ(counter.count(), 0u) << "tick " << m << " allocated" << (noise ? " (noise)" : "");
    }
    EXPECT_EQ(samples, (render_frames(t.force.size()) - (noise ? 0 : 3)) * 100);
    EXPECT_EQ(loop.flush().size(), (noise ? 0u : 300u) + 900u);
  }
}

TEST(RenderVibrationRender, TextureChoiceNamesTheModel) {
  const predict::Predictor p(model());
  EXPECT_EQ(predict::choose_texture(p, "m.h5", {"material_2", "", ""}).first_layer, p.material_code(2).first_layer);
  try {
    predict::choose_texture(p, "m.h5", {"no_such", "", ""});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("m.h5"), std::string::npos) << e.what();
  }
}

// --- WAV ---

TEST(RenderWavWriter, TwentyFourBitPcmAtTenKilohertzWithItsGain) {
  const test::TempDir dir;
  const Rendering r = render_vibration(model(), code(), stroke(12345), with(Reconstruction::online, 2));
  const WavSummary w = write_wav(dir.file("v.wav"), r.signal);
  EXPECT_TRUE(temporaries_of(dir.file("v.wav")).empty());
  const test::WavFile back = test::read_wav_file(dir.file("v.wav"));
  EXPECT_EQ(back.info.samplerate, 10000);
  EXPECT_EQ(back.info.channels, 1);
  EXPECT_EQ(back.info.format, SF_FORMAT_WAV | SF_FORMAT_PCM_24);
  ASSERT_EQ(back.samples.size(), 12345u);
  EXPECT_EQ(back.comment, w.comment);
  const double full_scale = back.full_scale();
  EXPECT_EQ(full_scale_from_comment(back.comment), full_scale);
  EXPECT_EQ(full_scale, w.full_scale_m_s2);
  EXPECT_GE(full_scale, w.peak_m_s2);
  EXPECT_LE(full_scale, w.peak_m_s2 * 1.01);
  double peak = 0;
  for (std::size_t n = 0; n < r.signal.size(); ++n) {
    ASSERT_NEAR(back.samples[n] * full_scale, r.signal[n], full_scale * 0x1p-22) << n;
    peak = std::max(peak, std::abs(back.samples[n]));
  }
  EXPECT_GT(peak, 0.99);  // peak-normalised

  // A fixed full scale is kept, and one below the peak is refused, leaving nothing behind.
  WavOptions fixed;
  fixed.full_scale_m_s2 = 4 * w.peak_m_s2;
  EXPECT_EQ(write_wav(dir.file("fixed.wav"), r.signal, fixed).full_scale_m_s2, fixed.full_scale_m_s2);
  EXPECT_NEAR(full_scale_from_comment(test::read_wav_file(dir.file("fixed.wav")).comment), fixed.full_scale_m_s2, 1e-8 * fixed.full_scale_m_s2);
  fixed.full_scale_m_s2 = 0.5 * w.peak_m_s2;
  EXPECT_THROW(write_wav(dir.file("clipped.wav"), r.signal, fixed), Error);
  EXPECT_FALSE(fs::exists(dir.file("clipped.wav")));
  EXPECT_TRUE(temporaries_of(dir.file("clipped.wav")).empty());
}

TEST(RenderWavWriter, RefusesToOverwriteAndNonFiniteSamples) {
  const test::TempDir dir;
  const std::vector<double> x = {0.0, 0.5, -1.25, 0.25};
  write_wav(dir.file("a.wav"), x);
  const auto size = fs::file_size(dir.file("a.wav"));
  try {
    write_wav(dir.file("a.wav"), std::vector<double>(100, 0.1));
    FAIL() << "overwrote";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find(dir.file("a.wav")), std::string::npos) << e.what();
  }
  EXPECT_EQ(fs::file_size(dir.file("a.wav")), size);
  WavOptions overwrite;
  overwrite.overwrite = true;
  EXPECT_EQ(write_wav(dir.file("a.wav"), std::vector<double>(100, 0.1), overwrite).samples, 100u);
  EXPECT_EQ(test::read_wav_file(dir.file("a.wav")).samples.size(), 100u);
  EXPECT_THROW(write_wav(dir.file("nan.wav"), std::vector<double>{0.0, std::nan("")}), Error);
  EXPECT_FALSE(fs::exists(dir.file("nan.wav")));
  EXPECT_TRUE(temporaries_of(dir.file("nan.wav")).empty());
  // Silence is written with a full scale of 1 m/s^2.
  EXPECT_EQ(write_wav(dir.file("zero.wav"), std::vector<double>(10, 0.0)).full_scale_m_s2, 1.0);
}

TEST(RenderWavWriter, FullScaleRoundsUpToThreeDigits) {
  EXPECT_EQ(rounded_full_scale(3.2134), 3.22);
  EXPECT_EQ(rounded_full_scale(3.22), 3.22);
  EXPECT_EQ(rounded_full_scale(0.012301), 0.0124);
  EXPECT_EQ(rounded_full_scale(999.2), 1000.0);
  EXPECT_EQ(rounded_full_scale(0.0), 1.0);
  EXPECT_EQ(full_scale_from_comment("full_scale_m_s2=0.0124; x"), 0.0124);
  EXPECT_TRUE(std::isnan(full_scale_from_comment("no gain here")));
}

TEST(RenderVibrationCsv, OneRowPerSampleInMetresPerSecondSquared) {
  const test::TempDir dir;
  const predict::Trajectory t = stroke(250);
  const std::vector<double> x(250, 0.125);
  write_vibration_csv(dir.file("v.csv"), t, x, false);
  EXPECT_TRUE(temporaries_of(dir.file("v.csv")).empty());
  const predict::Trajectory back = predict::read_trajectory(dir.file("v.csv"));  // it is a trajectory too
  EXPECT_EQ(back.force, t.force);
  EXPECT_EQ(back.speed, t.speed);
  EXPECT_THROW(write_vibration_csv(dir.file("v.csv"), t, x, false), Error);
  EXPECT_THROW(write_vibration_csv(dir.file("w.csv"), t, std::vector<double>(249, 0.0), false), Error);
  EXPECT_FALSE(fs::exists(dir.file("w.csv")));
}

// Review 5: a blank line among 2000 rows was skipped, shifting every later sample by 0.1 ms; a header
// with a byte order mark (or, review 6, quoted names) named "no force or no speed column".
TEST(Trajectory, ABlankLineAmongTheSamplesIsRefusedASpreadsheetsHeaderIsRead) {
  const test::TempDir dir;
  std::ofstream(dir.file("blank.csv")) << "force,speed\n1,100\n\n2,100\n";
  try {
    predict::read_trajectory(dir.file("blank.csv"));
    FAIL() << "a blank line among the samples was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("line 3: is blank, among the samples"), std::string::npos) << e.what();
  }
  std::ofstream(dir.file("sheet.csv")) << "\xEF\xBB\xBF\"force\",\"speed\"\r\n1,100\r\n2,150\r\n\r\n";
  const predict::Trajectory sheet = predict::read_trajectory(dir.file("sheet.csv"));
  EXPECT_EQ(sheet.force, (std::vector<float>{1, 2})) << "trailing blank lines end the samples";
  EXPECT_EQ(sheet.speed, (std::vector<float>{100, 150}));
}

}  // namespace
}  // namespace haptex::render
