// Peak extraction speed on one core: the per-frame work of `haptex capture extract` (score a frame
// against the no-contact reference, whose drift fit is made once per press file) at 960 x 720 and
// 3280 x 2464, from decoded frames and from MJPG
// bytes (reduced-size decoding), and the whole extraction of a recorded press file.
// bench/run_bench.sh times bench/opencv_peak_loop.py (absdiff, threshold, sum) on the same JPEGs,
// which `bench_capture --export-frames DIR` writes, and the recorder's 60 s keep-up runs.
#include <benchmark/benchmark.h>
#include <linux/videodev2.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include "bench/run_benchmarks.hpp"
#include "capture/device/fake_camera.hpp"
#include "capture/extraction/extract_presses.hpp"
#include "capture/recording/press_recorder.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using namespace haptex::capture;
constexpr int kFrames = 16;  // press depths cycled through, so decoding sees changing content

struct SizedFrames {
  std::vector<cv::Mat> decoded;                  // BGR
  std::vector<std::vector<std::uint8_t>> jpeg;   // what the sensor sends
  cv::Mat reference;                             // scoring image of the no-contact frame
  std::shared_ptr<const DriftFit> fit;           // its drift fit, made once as extraction makes it
};

// Frames of the fake camera's scene: a gel with markers, pressed to depths 0..1.
const SizedFrames& frames(int width, int height) {
  static std::map<int, SizedFrames> cache;
  auto it = cache.find(width);
  if (it != cache.end()) return it->second;
  SizedFrames f;
  const FakeScene scene(V4L2_PIX_FMT_MJPEG, width, height, PressSchedule{});
  for (int i = 0; i < kFrames; ++i) {
    f.decoded.push_back(scene.image(i % (FakeScene::kDepthLevels + 1), i % 2));
    f.jpeg.emplace_back();
    cv::imencode(".jpg", f.decoded.back(), f.jpeg.back(), {cv::IMWRITE_JPEG_QUALITY, 90});
  }
  f.reference = scoring_image(scene.image(0, 0));
  f.fit = std::make_shared<const DriftFit>(f.reference);
  return cache.emplace(width, std::move(f)).first->second;
}

void BM_ScoreDecodedFrame(benchmark::State& state) {
  const SizedFrames& f = frames(int(state.range(0)), int(state.range(1)));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(f.fit->score(scoring_image(f.decoded[i++ % kFrames]), f.reference, 6));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScoreDecodedFrame)->Args({960, 720})->Args({3280, 2464})->Unit(benchmark::kMillisecond);

// The two halves of BM_ScoreDecodedFrame: the scoring image (grey, block means, float) and the score.
void BM_ScoringImage(benchmark::State& state) {
  const SizedFrames& f = frames(int(state.range(0)), int(state.range(1)));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(scoring_image(f.decoded[i++ % kFrames]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScoringImage)->Args({960, 720})->Args({3280, 2464})->Unit(benchmark::kMillisecond);

void BM_ScoreOnly(benchmark::State& state) {
  const SizedFrames& f = frames(int(state.range(0)), int(state.range(1)));
  std::vector<cv::Mat> images;
  for (const cv::Mat& frame : f.decoded) images.push_back(scoring_image(frame));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(f.fit->score(images[i++ % kFrames], f.reference, 6));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScoreOnly)->Args({960, 720})->Args({3280, 2464})->Unit(benchmark::kMillisecond);

void BM_ScoreMjpgFrame(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1));
  const SizedFrames& f = frames(w, h);
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(f.fit->score(scoring_image_from_jpeg(f.jpeg[i++ % kFrames], {w, h}), f.reference, 6));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ScoreMjpgFrame)->Args({960, 720})->Args({3280, 2464})->Unit(benchmark::kMillisecond);

// The whole command on one recorded press file (MJPG): score every frame, decode the 13 kept,
// write the gelsight file (gzip) and the contact sheet.
void BM_ExtractPressFile(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1));
  haptex::test::TempDir dir;
  FakeCameraConfig config;
  config.modes = {{V4L2_PIX_FMT_MJPEG, std::uint32_t(w), std::uint32_t(h), {30}}};
  FakeCamera camera(config);
  SessionRequest request;
  request.node = "/dev/video0";
  request.output_dir = dir.file("session");
  RecorderOptions options;
  options.material = "Bench";
  options.presses = 1;
  record_session(camera, request, options);
  ExtractOptions extract;
  extract.overwrite = true;
  std::int64_t frames_scored = 0;
  for (auto _ : state) frames_scored += extract_presses({dir.file("session/press_0.h5")}, dir.file("g.h5"), extract).frames_scored;
  state.SetItemsProcessed(frames_scored);
}
BENCHMARK(BM_ExtractPressFile)->Args({960, 720})->Args({3280, 2464})->Unit(benchmark::kMillisecond)->UseRealTime();

// Writes the JPEGs for bench/opencv_peak_loop.py: <dir>/<W>x<H>/frame_<i>.jpg and reference.png.
int export_frames(const std::string& dir) {
  for (const auto& [w, h] : {std::pair{960, 720}, std::pair{3280, 2464}}) {
    const std::filesystem::path sub = std::filesystem::path(dir) / (std::to_string(w) + "x" + std::to_string(h));
    std::filesystem::create_directories(sub);
    const SizedFrames& f = frames(w, h);
    for (int i = 0; i < kFrames; ++i) {
      std::ofstream out(sub / ("frame_" + std::to_string(i) + ".jpg"), std::ios::binary);
      out.write(reinterpret_cast<const char*>(f.jpeg[std::size_t(i)].data()), std::streamsize(f.jpeg[std::size_t(i)].size()));
    }
    cv::imwrite((sub / "reference.png").string(), FakeScene(V4L2_PIX_FMT_MJPEG, w, h, PressSchedule{}).image(0, 0));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  cv::setNumThreads(1);  // one core, as the figures say
  if (argc == 3 && std::strcmp(argv[1], "--export-frames") == 0) return export_frames(argv[2]);
  return haptex::bench::run_benchmarks(argc, argv);
}
