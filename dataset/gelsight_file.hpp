#pragma once
// The gelsight file's writer (schemas/hdf5-layout.md "GelSight file"; `haptex capture extract` writes
// it): per material and press, the no-contact reference, the peak frame (encoded images,
// dataset/press_images.hpp) and its index, the 12 frames around the peak, and the contact score of
// every frame in the press's range, with the source file and frame range as attributes. align, qa
// and merge read it through dataset/press_images.hpp and layout.hpp's names.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/h5/atomic_file.hpp"
#include "dataset/press_images.hpp"

namespace haptex::dataset {

struct GelsightPress {
  std::string source_file, source_sha256;
  int press_in_source = 0;
  std::int64_t frame_start = 0, frame_end = 0;      // the range `contrast` covers (inclusive)
  std::int64_t contact_first = 0, contact_last = 0;
  std::int64_t peak_index = 0;                      // frame number in the source
  float peak_score = 0;
  std::vector<std::int64_t> frame_indices;          // frame numbers of `frames`
  std::vector<cv::Mat> frames;                      // BGR
  cv::Mat peak, reference;                          // BGR
  // The source's own JPEG or PNG bytes of `frames` and `peak` (true colours once decoded), stored as
  // they are; empty when the source has none, and then the decoded frames are stored as PNG.
  std::vector<EncodedImage> frames_encoded;
  EncodedImage peak_encoded;
  std::vector<float> contrast;                      // scores of frame_start..frame_end
  double fps = 0;                                   // 0: unknown
  std::string reference_note;
  float noise = 0, pixel_threshold = 0, level = 0, trigger = 0, release = 0;
  std::string contact_sheet;                        // path of its PNG relative to the gelsight file, or empty
  std::string contact_sheet_sha256;                 // that PNG's SHA-256
  std::int64_t source_frames_unreadable = 0;        // frames of the source that did not decode (none is kept)
};

class GelsightWriter {
 public:
  GelsightWriter(const std::string& path, bool overwrite, const std::string& provenance);
  // Adds a press to the material (created on first use with its name); returns its press number.
  // Throws haptex::Error (bad_input) when the name has no letter or digit to make an id from.
  int add_press(const std::string& material_name, const GelsightPress& press);
  // The file as one output of a set (core/output_set.hpp); commit() renames it alone.
  h5::AtomicFile& output() { return file_; }
  void commit() { file_.commit(); }
  const std::string& path() const { return file_.final_path(); }

 private:
  h5::AtomicFile file_;
};

}  // namespace haptex::dataset
