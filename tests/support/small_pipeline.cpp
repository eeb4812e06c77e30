#include "tests/support/small_pipeline.hpp"

#include <algorithm>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dataset/gelsight_file.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "core/h5/file.hpp"
#include "core/sha256.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/synth/press_frames.hpp"
#include "tests/support/file_text.hpp"

namespace haptex::test {
namespace fs = std::filesystem;
namespace {

void run_or_fail(const std::vector<std::string>& args) {
  const CommandResult r = run_haptex(args);
  if (r.exit_code != 0) {
    std::string line = "haptex";
    for (const auto& a : args) line += " " + a;
    throw std::runtime_error(line + " failed (" + std::to_string(r.exit_code) + "): " + r.err + r.out);
  }
}

// What capture extract does with one press video (capture/extraction/peak_frames.hpp), for synth's MJPG
// press_<j>.avi: reference = mean of the 10 leading no-contact frames, contact score of
// every frame, the peak and the 12 highest-scoring consecutive frames around it. The pixel threshold
// is 4 x the frames' noise without capture's 6-grey-level floor, which is meant for full-size frames:
// 160 x 120 frames are not averaged down before scoring.
dataset::GelsightPress press_from_video(const fs::path& video) {
  std::vector<cv::Mat> frames, scoring;
  for (cv::Mat& frame : read_press_frames(video.string())) {
    frames.push_back(frame);
    scoring.push_back(capture::scoring_image(frame));
  }
  constexpr int kReferenceFrames = 10, kKept = 12;
  if (frames.size() < std::size_t(kReferenceFrames + kKept)) throw std::runtime_error(video.string() + ": too few frames");
  capture::ScoreSettings settings;
  settings.pixel_threshold = 0.0f;
  const auto contact = capture::ContactReference::from_frames(
      std::vector<cv::Mat>(scoring.begin(), scoring.begin() + kReferenceFrames), settings);
  dataset::GelsightPress p;
  cv::Mat sum = cv::Mat::zeros(frames.front().size(), CV_64FC3);
  for (int i = 0; i < kReferenceFrames; ++i) cv::accumulate(frames[std::size_t(i)], sum);
  sum.convertTo(p.reference, CV_8UC3, 1.0 / kReferenceFrames);
  for (const auto& s : scoring) p.contrast.push_back(contact.score(s));
  const auto peak = std::size_t(std::max_element(p.contrast.begin(), p.contrast.end()) - p.contrast.begin());
  const std::size_t first = std::min(frames.size() - kKept, peak > kKept / 2 ? peak - kKept / 2 : 0);
  for (std::size_t i = first; i < first + kKept; ++i) p.frames.push_back(frames[i]), p.frame_indices.push_back(std::int64_t(i));
  p.source_file = video.string();
  p.source_sha256 = sha256_file(video.string());
  p.frame_start = 0;
  p.frame_end = std::int64_t(frames.size()) - 1;
  p.peak_index = std::int64_t(peak);
  p.peak = frames[peak];
  p.peak_score = p.contrast[peak];
  p.contact_first = p.contact_last = std::int64_t(peak);
  while (p.contact_first > 0 && p.contrast[std::size_t(p.contact_first - 1)] > contact.release()) --p.contact_first;
  while (p.contact_last + 1 < std::int64_t(frames.size()) && p.contrast[std::size_t(p.contact_last + 1)] > contact.release())
    ++p.contact_last;
  p.fps = 30;
  p.reference_note = "mean of frames 0-9";
  p.noise = contact.noise();
  p.pixel_threshold = contact.pixel_threshold();
  p.trigger = contact.trigger();
  p.release = contact.release();
  return p;
}

// Every material folder's press videos, in press order, into a gelsight file.
void write_gelsight(const fs::path& synth_gelsight, const std::string& output) {
  dataset::GelsightWriter writer(output, false, "test fixture: synth press frames scored as capture extract does");
  std::vector<fs::path> materials;
  for (const auto& m : fs::directory_iterator(synth_gelsight))
    if (m.is_directory()) materials.push_back(m.path());
  std::sort(materials.begin(), materials.end());
  for (const auto& material : materials)
    for (int j = 0; fs::exists(material / ("press_" + std::to_string(j) + ".avi")); ++j)
      writer.add_press(material.filename().string(), press_from_video(material / ("press_" + std::to_string(j) + ".avi")));
  writer.commit();
}

// The files live in a folder beside the test program, built once per build of haptex and the tests:
// ctest runs every test in its own process, and rebuilding per process would cost seconds per test.
// A lock keeps parallel test processes from building it twice; a stamp (the binaries' modification
// times) says whether it is current. Tests only read these files; mutations go to copies.
fs::path test_program() { return fs::read_symlink("/proc/self/exe"); }
// One folder per test program: the stamp names the program, and two programs sharing a folder would
// rebuild it under each other's feet.
fs::path cache_dir() { return test_program().parent_path() / ("small_pipeline_" + test_program().filename().string()); }

std::string build_stamp() {
  auto mtime = [](const fs::path& p) { return std::to_string(fs::last_write_time(p).time_since_epoch().count()); };
  return haptex_binary() + " " + mtime(haptex_binary()) + " " + mtime(test_program()) + "\n";
}

SmallPipeline files_in(const fs::path& root) {
  return {(root / "r.h5").string(), (root / "g.h5").string(), (root / "d.h5").string(), (root / "split.json").string(),
          (root / "synth" / "truth.h5").string()};
}

void build(const fs::path& root) {
  const std::string synth = (root / "synth").string();
  const SmallPipeline files = files_in(root);
  // Materials 0-4 are Polished, Sandpaper, Brushed, Grooved and Woven 1. Smooth and fine surfaces leave
  // almost no mark in a 160 x 120 GelSight frame (capture's contact trigger would not even see their
  // presses, and qa flags them with gelsight.peak_score), so the good files keep Sandpaper and Woven.
  run_or_fail({"synth", "materials", "-n", "5", "--size", "160x120", "--presses", "5", "--recordings", "1", "--seconds", "3",
               "-o", synth});
  for (const char* dropped : {"polished_1", "brushed_1", "grooved_1"})
    fs::remove(root / "synth" / "recordings" / (std::string(dropped) + "_0.xml.gz"));
  for (const char* dropped : {"Polished 1", "Brushed 1", "Grooved 1"}) fs::remove_all(root / "synth" / "gelsight" / dropped);
  run_or_fail({"convert", "hatt", synth + "/recordings", "-o", files.recordings});
  // capture extract finds no press in 160 x 120 frames with its full-size thresholds: the press
  // frames are scored here the way it scores them.
  write_gelsight(root / "synth" / "gelsight", files.gelsight);
  run_or_fail({"align", "--recordings", files.recordings, "--gelsight", files.gelsight, "-o", files.dataset});
  run_or_fail({"split", files.dataset, "-o", files.split, "--no-plots"});
}

}  // namespace

const SmallPipeline& small_pipeline() {
  static std::optional<SmallPipeline> files;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    try {
      const fs::path root = cache_dir();
      const int lock = ::open((root.string() + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
      if (lock < 0 || ::flock(lock, LOCK_EX) != 0) throw std::runtime_error("cannot lock " + root.string() + ".lock");
      try {
        const std::string stamp = build_stamp();
        if (file_text(root / "stamp") != stamp) {
          fs::remove_all(root);
          fs::create_directories(root);
          build(root);
          std::ofstream(root / "stamp") << stamp;
        }
      } catch (...) {
        ::close(lock);
        throw;
      }
      ::close(lock);  // releases the lock
      files = files_in(root);
    } catch (const std::exception& e) {
      failure = e.what();
    }
  });
  // A failure is kept and reported by every test rather than retried by each.
  if (!files) throw std::runtime_error("the small pipeline test fixture could not be built: " + failure);
  return *files;
}

std::string small_material() {
  std::ifstream in(small_pipeline().split);
  return nlohmann::json::parse(in)["materials"][0]["id"];
}

std::string copy_into(const TempDir& dir, const std::string& file, const std::string& name) {
  const fs::path to = dir.path() / name;
  fs::copy_file(file, to, fs::copy_options::overwrite_existing);
  return to.string();
}

std::vector<std::string> material_ids(const std::string& file) {
  return h5::File::open(file).root().open_group("materials").children();
}

std::string copy_with_materials(const TempDir& dir, const std::string& file, const std::string& name,
                                const std::vector<std::string>& keep) {
  const std::string copy = copy_into(dir, file, name);
  const std::vector<std::string> ids = material_ids(copy);
  Edit edit(copy);
  for (const std::string& id : ids)
    if (std::find(keep.begin(), keep.end(), id) == keep.end()) edit.remove("materials/" + id);
  return copy;
}

}  // namespace haptex::test
