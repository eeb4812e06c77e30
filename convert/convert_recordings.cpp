#include "convert/convert_recordings.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <set>

#include "convert/cluster_database.hpp"
#include "convert/csv_recording_reader.hpp"
#include "convert/field_map.hpp"
#include "convert/hatt_recording_reader.hpp"
#include "convert/preprocess.hpp"
#include "convert/texture_names.hpp"
#include "core/error.hpp"
#include "core/text/utf8.hpp"
#include "core/input_file.hpp"
#include "core/h5/atomic_file.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::convert {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// .xml, .xml.gz (read_input_file decompresses it) or .csv.
bool is_xml_file(const fs::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".xml" || (ext == ".gz" && lower_extension(path.stem()) == ".xml");
}

bool is_recording_file(const fs::path& path) { return is_xml_file(path) || lower_extension(path) == ".csv"; }

}  // namespace

std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  std::set<fs::path> seen;  // a file named twice (or inside a named directory too) is one recording
  auto add = [&](const fs::path& file) {
    text::require_utf8(file.string(), file.string(), "the file's name");  // it is stored as the recording's source
    std::error_code ec;
    if (seen.insert(fs::weakly_canonical(file, ec)).second) files.push_back(file.string());
  };
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (fs::is_directory(input, ec)) {
      std::vector<fs::path> found;
      fs::path listing = input;  // the folder being read when listing fails: the entry last seen, or input itself
      // A link to a folder is followed, as capture extract does; a dangling link is refused by name
      // (review 14, F8), and so is a link to a folder holding it, which would be read forever.
      for (auto it = fs::recursive_directory_iterator(input, fs::directory_options::follow_directory_symlink, ec);
           !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        listing = it->path();
        refuse_dangling_link(it->path().string());
        refuse_link_to_its_own_folder(it->path());
        if (is_recording_file(it->path()) && !it->is_directory()) {
          require_regular_file(it->path().string());  // a FIFO or a dangling link is refused by name, not skipped
          found.push_back(it->path());
        }
      }
      if (ec) throw input_error(listing.string(), "", "cannot list the folder (" + ec.message() + ")", "Check its permissions");
      if (found.empty())
        throw input_error(input, "", "the directory holds no .xml, .xml.gz or .csv recordings", "Point at the recordings' folder");
      std::sort(found.begin(), found.end());
      for (const auto& file : found) add(file);
    } else if (!fs::exists(fs::symlink_status(input, ec))) {
      throw input_error(input, "", "no such file or directory", "Check the path");
    } else {
      require_regular_file(input);  // a FIFO, a device, a dangling link: said so
      add(input);
    }
  }
  if (files.empty()) throw input_error("(command line)", "", "no input files given", "Name files or directories to convert");
  return files;
}

namespace {

// Reads source i (and the bytes it read) and writes it into the open recordings file, in turn.
ConvertResult write_all(h5::AtomicFile& out, const std::vector<std::string>& sources, const Progress& progress,
                        const std::function<Recording(std::size_t, std::uintmax_t&)>& read) {
  ConvertResult result;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (progress) progress(i, sources.size(), sources[i]);
    std::uintmax_t bytes = 0;
    const Recording recording = read(i, bytes);
    const dataset::WrittenRecording written = dataset::write_recording(out.root(), preprocess(recording));
    result.recordings.push_back({sources[i], recording.material, written.material_id, written.index,
                                 recording.samples(), recording.sample_rate_hz});
    result.input_bytes += bytes;
  }
  if (progress) progress(sources.size(), sources.size(), "");
  out.commit();
  return result;
}

}  // namespace

ConvertResult convert_recordings(const std::vector<std::string>& inputs, const std::string& output,
                                 const ConvertOptions& options, const Progress& progress) {
  const FieldMap map = options.map_path ? load_field_map(*options.map_path) : default_field_map();
  const std::vector<std::string> files = expand_inputs(inputs);
  h5::AtomicFile out(output, options.overwrite, dataset::format_name(dataset::Kind::recordings));
  dataset::stamp(out.root(), dataset::Kind::recordings, options.provenance);
  out.root().set_attr(dataset::layout::kFieldMap, map.origin);
  return write_all(out, files, progress, [&](std::size_t i, std::uintmax_t& bytes) {
    bytes = fs::file_size(files[i]);
    return lower_extension(files[i]) == ".csv" ? read_csv_recording(files[i], map, options.max_bytes)
                                               : read_hatt_recording_xml(files[i], map, options.max_bytes);
  });
}

ConvertResult convert_cluster(const std::string& root, const std::string& output, const ConvertOptions& options,
                              const std::optional<std::string>& names_path, const Progress& progress) {
  const std::map<int, std::string> names = names_path ? read_texture_names(*names_path) : std::map<int, std::string>{};
  const std::vector<ClusterTake> takes = find_cluster_takes(root);
  const std::vector<int> unused = names_path ? check_cluster_materials(takes, names, *names_path) : std::vector<int>{};
  std::vector<std::string> sources;
  for (const auto& take : takes) sources.push_back(take.accel);
  h5::AtomicFile out(output, options.overwrite, dataset::format_name(dataset::Kind::recordings));
  dataset::stamp(out.root(), dataset::Kind::recordings, options.provenance);
  out.root().set_attr(dataset::layout::kFieldMap, kClusterLayout);
  ConvertResult result = write_all(out, sources, progress, [&](std::size_t i, std::uintmax_t& bytes) {
    const ClusterTake& take = takes[i];
    bytes = fs::file_size(take.accel) + fs::file_size(take.force) + fs::file_size(take.position);
    return read_cluster_take(take, names, options.max_bytes);
  });
  for (const int texture : unused)
    result.notes.push_back(*names_path + ": texture " + std::to_string(texture) + " is named, but the database has no take of it");
  return result;
}

}  // namespace haptex::convert
