#include "qa/run_qa.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>

#include "dataset/format.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/text/utf8.hpp"
#include "core/h5/file.hpp"
#include "qa/checkers.hpp"
#include "qa/layout_spec.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::qa {
namespace {

// The formats qa checks.
constexpr std::array kChecked{dataset::Kind::recordings, dataset::Kind::gelsight, dataset::Kind::dataset};

FileKind file_kind(dataset::Kind kind) {
  return kind == dataset::Kind::recordings ? FileKind::recordings : kind == dataset::Kind::gelsight ? FileKind::gelsight : FileKind::dataset;
}

bool looks_like_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  return in.gcount() == 8 && std::string(signature, 8) == std::string("\x89HDF\r\n\x1a\n", 8);
}

void append(std::vector<CheckResult>& out, std::vector<CheckResult> more) {
  for (auto& r : more) out.push_back(std::move(r));
}

bool links_broken(const std::vector<CheckResult>& checks) {
  return std::any_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.id == "layout.links" && c.status == Status::fail; });
}

Report check_hdf5(const QaOptions& options) {
  const dataset::OpenedFile opened =
      dataset::open_any(options.file, kChecked, "qa checks", "Give one of those, or a split manifest (haptex info FILE tells what a file is)",
                        dataset::Links::report);
  const h5::Group root = opened.file.root();
  const std::string format = dataset::format_name(opened.kind);
  Report report{options.file, file_kind(opened.kind), options.split, {}};
  if (options.split && report.kind != FileKind::dataset)
    throw input_error(options.file, "", "--split goes with a dataset file, this is a " + format + " file",
                      "Run: haptex qa DATASET.h5 --split " + *options.split);
  append(report.checks, check_layout(root, opened.kind));
  // The other checks read values, which such a file may keep anywhere (a FIFO, /dev/zero): docs/qa.md.
  if (links_broken(report.checks)) return report;
  if (report.kind != FileKind::gelsight) append(report.checks, check_recordings(root));
  if (report.kind != FileKind::recordings) append(report.checks, check_gelsight(root));
  if (report.kind == FileKind::dataset) append(report.checks, check_dataset(root));
  if (options.split) append(report.checks, check_split(split::read_split_manifest(*options.split), options.file));
  return report;
}

}  // namespace

Report run_qa(const QaOptions& options) {
  std::error_code ec;
  require_regular_file(options.file);
  if (looks_like_hdf5(options.file)) return check_hdf5(options);
  if (options.split)
    throw input_error(options.file, "", "is not an HDF5 file; --split goes with a dataset file",
                      "Run: haptex qa DATASET.h5 --split MANIFEST.json, or haptex qa MANIFEST.json");
  // Not HDF5: a split manifest (JSON) or nothing qa can read.
  std::ifstream in(options.file);
  std::string head(4096, '\0');
  head.resize(std::size_t(in.read(head.data(), std::streamsize(head.size())).gcount()));
  const std::string_view text = text::without_byte_order_mark(head);  // as train's JSON reader does (review 5)
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || text[first] != '{')
    throw input_error(options.file, "", "neither an HDF5 file nor a JSON split manifest",
                      "Give a recordings, gelsight or dataset file, or a split manifest");
  const SplitManifestDocument manifest = split::read_split_manifest(options.file);
  // Another haptex JSON file (a training log) is the wrong kind, as a model file is (review 5: its
  // fields were reported as a manifest's schema errors).
  if (const auto format = manifest.json.find("format");
      format != manifest.json.end() && format->is_string() && format->get<std::string>().rfind("split/", 0) != 0)
    throw input_error(options.file, "/format", "is '" + format->get<std::string>() + "', not a split manifest",
                      "Give a recordings, gelsight or dataset file, or a split manifest");
  Report report{options.file, FileKind::split, std::nullopt, {}};
  append(report.checks, check_split(manifest, split::locate_dataset(manifest)));
  return report;
}

}  // namespace haptex::qa
