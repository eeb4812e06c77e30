#include "tests/support/pipeline_fixture.hpp"

#include <filesystem>
#include <opencv2/imgproc.hpp>

#include "align/align_dataset.hpp"
#include "core/sha256.hpp"
#include "dataset/gelsight_file.hpp"
#include "convert/convert_recordings.hpp"
#include "tests/support/sample_recording.hpp"

namespace haptex::test {
namespace {

// `source` tells the presses' videos apart: each is its own, with its own peak image, as a sensor's
// noise makes a real press's (qa's gelsight.duplicate compares both).
dataset::GelsightPress tiny_press(int size, int seed, int source) {
  dataset::GelsightPress p;
  p.source_file = "press_" + std::to_string(source) + ".mkv";
  p.source_sha256 = sha256_hex(p.source_file);
  p.reference = cv::Mat(size, size, CV_8UC3, cv::Scalar(100, 110, 120));
  p.peak = p.reference.clone();
  cv::circle(p.peak, {size / 2, size / 2}, size / 4, cv::Scalar(150 + seed, 90, 60), -1);
  p.peak.at<cv::Vec3b>(0, 0) = cv::Vec3b(std::uint8_t(source % 256), std::uint8_t(source / 256 % 256), 0);
  for (int i = 0; i < 12; ++i) p.frames.push_back(p.peak.clone()), p.frame_indices.push_back(20 + i);
  p.peak_index = 25;
  p.frame_start = 15;
  p.frame_end = 35;
  p.contact_first = 18;
  p.contact_last = 32;
  p.contrast.assign(21, 1.0f);
  p.peak_score = 5;
  return p;
}

}  // namespace

void make_pipeline_inputs(PipelineFiles& in, const PipelineSpec& spec) {
  std::filesystem::create_directory(in.dir.file("xml"));
  auto xml = [&](const std::string& file, const std::string& material, std::uint64_t seed) {
    SampleRecordingSpec s;
    s.material = material;
    s.seed = seed;
    s.seconds = spec.seconds;
    write_text_file(in.dir.file("xml/" + file), sample_recording_xml(s));
  };
  xml("book_0.xml", "Book", 1);
  xml("book_1.xml", "Book", 2);
  xml("sand.xml", "Sandpaper_100", 3);
  xml("felt.xml", "Felt", 4);
  convert::convert_recordings({in.dir.file("xml")}, in.recordings, {});
  dataset::GelsightWriter writer(in.gelsight, false, "test");
  for (int j = 0; j < 5; ++j) {
    writer.add_press("Book", tiny_press(j == 4 && spec.odd_press_size ? spec.odd_press_size : 32, j, 3 * j));
    writer.add_press("sandpaper 100", tiny_press(32, j, 3 * j + 1));
    writer.add_press("Glass", tiny_press(32, j, 3 * j + 2));
  }
  writer.commit();
}

void make_pipeline_dataset(PipelineFiles& files, const PipelineSpec& spec) {
  make_pipeline_inputs(files, spec);
  align::AlignOptions o;
  o.recordings = files.recordings;
  o.gelsight = files.gelsight;
  o.output = files.dataset;
  align::align_dataset(o);
}

}  // namespace haptex::test
