#include "qa/catalog.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace haptex::qa {

std::string_view to_string(FileKind kind) {
  switch (kind) {
    case FileKind::recordings: return "recordings";
    case FileKind::gelsight: return "gelsight";
    case FileKind::dataset: return "dataset";
    case FileKind::split: return "split";
  }
  return "?";
}

const std::vector<CheckInfo>& all_checks() {
  using enum Severity;
  static const std::vector<CheckInfo> checks = {
      // layout: schemas/hdf5-layout.md
      {"layout.required", error,
       "every object and attribute the layout tables require 'always' is present, material groups are named by material ids of at "
       "most 100 bytes, and nothing else is at the root",
       "Rewrite the file with the haptex command that makes it (convert, capture extract, align), or remove what it added at the root"},
      {"layout.dtype", error, "objects and attributes have the dtype of their layout row",
       "Rewrite the file with haptex; tools that re-save it must keep float32/int64/string types"},
      {"layout.shape", error, "datasets have the shape of their layout row (N = the recording's samples)",
       "Rewrite the file with haptex; every signal of a recording must have `samples` rows"},
      {"layout.units", error, "datasets carry the `units` of their layout row (m/s^2, N, mm/s, mm)",
       "Convert the source again with the right units in its header or field map"},
      {"layout.links", error,
       "every object is reached by one hard link, is a group or a dataset and keeps its values in the file: no soft or external "
       "link, nothing linked twice, no named datatype, no external or virtual storage, no dataset declaring more than haptex reads "
       "at once, no object reference (when it fails, no other check runs: looking objects up would follow the links)",
       "Each finding says what to do with its object (remove an extra link or a dataset too large to read, store values in the "
       "file); or make the file again with the haptex command that wrote it"},
      // recordings (also inside dataset files)
      {"signal.nan", error, "no NaN or Inf in any signal of a recording",
       "Fix or cut the broken stretch of the source recording and convert it again"},
      {"signal.sample_rate", error, "`sample_rate_hz` is 10000",
       "Resample the recording to 10 kHz before converting it"},
      {"signal.duration", error,
       "`duration_s` = samples / sample rate, and at least one model window (1000 samples)",
       "Convert the recording again; recordings under 0.1 s cannot make a single window"},
      {"signal.short", warning, "at least 25 x 1000 samples (2.5 s), so every split section holds a window",
       "Record longer strokes (HaTT recordings are 10 s) or split with fewer --sections"},
      {"signal.clipping", error,
       "acceleration axes have at most 0.1% of samples in flat tops (runs of >= 3 equal samples at the extreme)",
       "Re-record with a larger accelerometer range or a lighter stroke; clipped vibration spectra are wrong"},
      {"signal.force_range", error, "raw normal force within [-0.5, 20] N and reaching at least 0.05 N",
       "Check the force units (N) and the load cell's offset and sign, then convert again"},
      {"signal.speed_range", error, "raw speed within [-1, 2000] mm/s and reaching at least 5 mm/s",
       "Check the speed units (mm/s) and sign, then convert again"},
      {"signal.accel_spectrum", error,
       "acceleration has >= 1% of its power and >= 0.001 m/s^2 RMS between 100 and 1000 Hz",
       "Record the accelerometer unfiltered (or anti-aliased above 1 kHz) at 10 kHz"},
      {"signal.reduction_energy", error,
       "every 100 ms window of accel holds 0.8 to 1.25 times the energy of the three raw axes in that window",
       "Convert the recording again: accel must be the frame-by-frame DFT321 of accel_xyz (older files reduced "
       "the whole recording at once)"},
      {"filter.lowpass", error, "force_normal_lp and speed_lp have at most 1e-5 of their power above 40 Hz",
       "Convert the recording again: the *_lp signals must be the 20 Hz zero-phase Butterworth output"},
      {"filter.raw", error, "force_normal and speed keep at least 1e-8 of their power above 40 Hz (unfiltered)",
       "Convert from the unfiltered source signals; the raw datasets must not be low-passed"},
      {"filter.stated", error,
       "a recording states the format's low-pass (order 4, cut-off 20 Hz) and reduction frames (1024 samples, hop 256)",
       "Convert the recording again: its signals were made otherwise than the format says"},
      {"recordings.duplicate", error, "no two recordings share a source SHA-256 or identical acceleration data",
       "Remove the repeated source file and convert again; duplicates leak between train and test"},
      // gelsight presses (also inside dataset files)
      {"gelsight.reference", error,
       "each reference scores under its press's contact trigger against the median reference of its size",
       "Extract again with --reference pointing at a no-contact image, or start the press videos untouched"},
      {"gelsight.peak_score", error, "the peak frame scores at least 0.9 x the press's contact trigger against the reference",
       "Extract again: the stored reference or peak is not the one the press was found with"},
      {"gelsight.saturation", error, "at most 2% of the pixels of the peak and its frames have a channel at 255",
       "Lower the sensor's exposure or LED current (capture --exposure) and capture the press again"},
      {"gelsight.blur", warning,
       "variance of the Laplacian of peak and frames >= 0.5 x the median of the no-contact references",
       "Hold the sensor still during the press and check its focus, then capture again"},
      {"gelsight.resolution", error, "all presses of a material have one image size",
       "Capture every press of a material with the same sensor mode (width x height)"},
      {"gelsight.press_count", error, "every material has at least 5 presses (3 train, 1 val, 1 test)",
       "Capture more presses of the material (haptex capture record)"},
      {"gelsight.source_damage", warning,
       "every press's source decoded whole (`source_frames_unreadable` is 0: no frame failed or went missing)",
       "Copy the video again from the sensor's machine (a damaged frame is never kept, but the press may be cut short)"},
      {"gelsight.duplicate", error,
       "no two presses are the same press of one source file (`source_sha256` and `press_in_source`), or have one peak image byte for byte",
       "Extract again without the repeated video (given twice, through a link, or copied); duplicates leak between train and test"},
      {"gelsight.channel_order", error,
       "every press states its images' channel order as RGB or BGR (`channel_order`), and its image datasets agree",
       "Set the press's channel_order to the order of its stored pixels (haptex writes RGB); its images are not judged until then"},
      {"gelsight.frame_numbers", error,
       "every press's frame numbers agree: frame_start <= contact_first <= peak_index <= contact_last <= frame_end, one contrast "
       "score per frame from frame_start to frame_end, frame_indices consecutive within them and holding peak_index",
       "Extract the press again from its video (haptex capture extract); the numbers were edited or damaged"},
      {"gelsight.images", error,
       "every stored image (reference, peak, frames) is a JPEG or PNG as its dataset's encoding says, its header stating the press's width and height, whole: each PNG chunk's CRC holds, each JPEG ends",
       "Extract the press again from its video (haptex capture extract); a damaged image is not judged by the other checks"},
      // dataset
      {"dataset.windows", error,
       "the window table's materials, recordings and starts exist and follow the stride (t = 0, stride, ...)",
       "Build the dataset again with haptex align"},
      {"dataset.cache", error, "cached action and target equal the low-passed signals and spectra they came from",
       "Build the dataset again with haptex align from the unchanged recordings"},
      // split manifest
      {"split.schema", error, "the manifest satisfies schemas/split.schema.json",
       "Write the manifest again with haptex split"},
      {"split.hashes", error, "the manifest's SHA-256 of the dataset and its sources match the files given",
       "Run haptex split again on this dataset file; the manifest was made for another one"},
      {"split.materials", error, "the manifest and the dataset list the same materials with the same recordings",
       "Run haptex split again on this dataset file"},
      {"split.sections", error, "section numbers are in range and no section is in two sets",
       "Run haptex split again; never edit a manifest's sections by hand"},
      {"split.sets", error, "every material has sections and windows in train, val and test",
       "Split with fewer --val/--test sections or more --sections, or record the material longer"},
      {"split.crossing", error,
       "the manifest's window counts are the windows lying wholly inside one set's sections",
       "Run haptex split again: a window that crosses a section boundary must belong to no set"},
      {"split.coverage", error,
       "val and test (force, speed) points inside the training hull, share >= the manifest's min_coverage",
       "Run haptex split with another --seed or more --sections, or record the material over a wider range"},
      {"split.coverage_recorded", warning, "the manifest's coverage figures match the recomputed ones within 0.02",
       "Run haptex split again on this dataset file"},
      {"split.presses", error, "every material has at least 3 train, 1 val and 1 test press, distinct and in the dataset",
       "Capture at least 5 presses per material and run haptex split again"},
  };
  return checks;
}

const CheckInfo& check_info(std::string_view id) {
  const auto& checks = all_checks();
  auto it = std::find_if(checks.begin(), checks.end(), [&](const CheckInfo& c) { return c.id == id; });
  if (it == checks.end()) throw failure("internal: no QA check named '" + std::string(id) + "'");
  return *it;
}

}  // namespace haptex::qa
