#include "qa/run_qa.hpp"

#include <filesystem>
#include <fstream>

#include "dataset/format.hpp"
#include "core/error.hpp"
#include "core/format_version.hpp"
#include "core/input_file.hpp"
#include "core/h5/file.hpp"
#include "qa/checkers.hpp"
#include "qa/layout_spec.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::qa {
namespace {

// The formats qa checks, by root attribute haptex_format.
const std::vector<std::pair<std::string, FileKind>> kFormats = {{dataset::format_name(dataset::Kind::recordings), FileKind::recordings},
                                                               {dataset::format_name(dataset::Kind::gelsight), FileKind::gelsight},
                                                               {dataset::format_name(dataset::Kind::dataset), FileKind::dataset}};

bool looks_like_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  return in.gcount() == 8 && std::string(signature, 8) == std::string("\x89HDF\r\n\x1a\n", 8);
}

void append(std::vector<CheckResult>& out, std::vector<CheckResult> more) {
  for (auto& r : more) out.push_back(std::move(r));
}

Report check_hdf5(const QaOptions& options) {
  const h5::File file = h5::File::open(options.file);
  const h5::Group root = file.root();
  const std::string format = dataset::read_format(file);
  const auto known = std::find_if(kFormats.begin(), kFormats.end(), [&](const auto& f) { return f.first == format; });
  for (const auto& [name, kind] : kFormats)
    if (is_newer_version(format, name)) throw newer_version_error(options.file, "/@haptex_format", format, name);
  if (known == kFormats.end())
    throw input_error(options.file, "/@haptex_format", "'" + format + "' is not a format qa checks",
                      "qa checks " + kFormats[0].first + ", " + kFormats[1].first + " and " + kFormats[2].first + " files and split manifests");
  Report report{options.file, known->second, options.split, {}};
  if (options.split && report.kind != FileKind::dataset)
    throw input_error(options.file, "", "--split goes with a dataset file, this is a " + format + " file",
                      "Run: haptex qa DATASET.h5 --split " + *options.split);
  append(report.checks, check_layout(root, format));
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
  char first = 0;
  while (in.get(first) && std::isspace(static_cast<unsigned char>(first))) {
  }
  if (first != '{')
    throw input_error(options.file, "", "neither an HDF5 file nor a JSON split manifest",
                      "Give a recordings, gelsight or dataset file, or a split manifest");
  const SplitManifestDocument manifest = split::read_split_manifest(options.file);
  Report report{options.file, FileKind::split, std::nullopt, {}};
  append(report.checks, check_split(manifest, split::locate_dataset(manifest)));
  return report;
}

}  // namespace haptex::qa
