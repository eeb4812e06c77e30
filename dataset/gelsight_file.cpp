#include "dataset/gelsight_file.hpp"

#include "core/error.hpp"
#include "core/naming.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/description.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {
namespace {

void set_press_attributes(h5::Group& g, const GelsightPress& p) {
  g.set_attr(layout::kSourceFile, p.source_file);
  g.set_attr(layout::kSourceSha256, p.source_sha256);
  g.set_attr(layout::kPressInSource, p.press_in_source);
  g.set_attr(layout::kFrameStart, p.frame_start);
  g.set_attr(layout::kFrameEnd, p.frame_end);
  g.set_attr(layout::kSamples, std::int64_t(p.contrast.size()));
  g.set_attr(layout::kContactFirst, p.contact_first);
  g.set_attr(layout::kContactLast, p.contact_last);
  g.set_attr(layout::kPeakScore, double(p.peak_score));
  g.set_attr(layout::kHeight, std::int64_t(p.peak.rows));
  g.set_attr(layout::kWidth, std::int64_t(p.peak.cols));
  g.set_attr(layout::kChannelOrder, channel_order_name(kWrittenChannelOrder));
  if (p.fps > 0) g.set_attr(layout::kFps, p.fps);
  g.set_attr(layout::kReferenceSource, p.reference_note);
  g.set_attr(layout::kScoreMethod, "mean over the grey image averaged in 2, 4 or 8 pixel blocks of max(0, |d - drift(d)| - pixel_threshold), "
                             "d = frame - reference, drift = the robust least-squares fit of an offset and a multiple of the "
                             "reference (docs/capture.md)");
  g.set_attr(layout::kNoise, double(p.noise));
  g.set_attr(layout::kPixelThreshold, double(p.pixel_threshold));
  g.set_attr(layout::kNoContactLevel, double(p.level));
  g.set_attr(layout::kTrigger, double(p.trigger));
  g.set_attr(layout::kRelease, double(p.release));
  if (!p.contact_sheet.empty()) g.set_attr(layout::kContactSheet, p.contact_sheet);
  if (!p.contact_sheet_sha256.empty()) g.set_attr(layout::kContactSheetSha256, p.contact_sheet_sha256);
  g.set_attr(layout::kSourceFramesUnreadable, p.source_frames_unreadable);
}

// The source's bytes when it gave them for every frame, else every frame as PNG (one encoding a dataset).
std::vector<EncodedImage> stored_frames(const GelsightPress& p) {
  if (!p.frames_encoded.empty()) {
    if (p.frames_encoded.size() != p.frames.size()) throw failure("GelsightWriter: frames and their bytes differ in number");
    return p.frames_encoded;
  }
  std::vector<EncodedImage> png;
  for (const cv::Mat& frame : p.frames) png.push_back(encode_png(frame));
  return png;
}


}  // namespace

GelsightWriter::GelsightWriter(const std::string& path, bool overwrite, const std::string& provenance)
    : file_(path, overwrite, format_name(Kind::gelsight)) {
  stamp(file_.root(), Kind::gelsight, provenance);
}

int GelsightWriter::add_press(const std::string& material_name, const GelsightPress& p) {
  const std::string id = checked_material_id(material_name, p.source_file, "material name");
  h5::Group materials = file_.root().require_group(layout::kMaterials);
  const bool first = !materials.has_group(id);
  h5::Group material = materials.require_group(id);
  if (first) material.set_attr(layout::kName, material_name);  // the first spelling of a name is kept
  h5::Group presses = material.require_group(layout::kPresses);
  const int j = int(presses.children().size());
  h5::Group g = presses.create_group(std::to_string(j));
  set_press_attributes(g, p);
  write_press_images(g, layout::kReference, {encode_png(p.reference)},
                              "no-contact reference (" + p.reference_note + ")");
  write_press_images(g, layout::kPeak, {p.peak_encoded.empty() ? encode_png(p.peak) : p.peak_encoded},
                              "the press's highest-scoring frame");
  // A scalar dataset: one number, as h5py users expect (f[...][layout::kPeakIndex][()]).
  describe(g.write_array<std::int64_t>(layout::kPeakIndex, std::span<const std::int64_t>(&p.peak_index, 1), {},
                                              h5::DatasetOptions{.compress = false, .gzip_level = 0, .chunk = {}}),
                  "", "frame number of the peak in the source file");
  write_press_images(g, layout::kFrames, stored_frames(p), "the peak and its neighbours: consecutive frames of the source");
  describe(g.write(layout::kFrameIndices, p.frame_indices), "", "frame numbers of `frames` in the source file");
  describe(g.write(layout::kContrast, p.contrast), "grey levels",
                  "contact score of each frame from frame_start to frame_end (docs/capture.md)");
  return j;
}


}  // namespace haptex::dataset
