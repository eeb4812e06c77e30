#include "evaluate/baselines/hatt_published.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "convert/hatt_model_reader.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/naming.hpp"

namespace haptex::evaluate {
namespace {

namespace fs = std::filesystem;

// "Models_Brick 2.xml" -> "brick_2": the toolkit's naming, and a bare "<Material>.xml" too.
std::string id_from_file_name(const fs::path& file) {
  std::string id = material_id(file.stem().string());
  const std::string prefix = "models_";
  if (id.size() > prefix.size() && id.compare(0, prefix.size(), prefix) == 0) id.erase(0, prefix.size());
  return id;
}

std::vector<fs::path> xml_files(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw input_error(dir.string(), "", "is not a directory", "Give --hatt-models the toolkit's models folder");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".xml" || entry.is_directory()) continue;
    require_regular_file(entry.path().string());  // a FIFO would block its read, a device never end: refused by name
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The id of a file's <material>, or "" when the file is not a readable HaTT model.
std::string id_from_content(const fs::path& file) {
  try {
    return material_id(convert::read_hatt_model(file).material);
  } catch (const Error&) {
    return "";
  }
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t(0));
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string closest_names(const std::vector<fs::path>& files, const std::string& id) {
  std::vector<std::pair<std::size_t, std::string>> ranked;
  for (const fs::path& f : files) ranked.emplace_back(edit_distance(id_from_file_name(f), id), f.filename().string());
  std::sort(ranked.begin(), ranked.end());
  std::string out;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, ranked.size()); ++i)
    out += (i ? ", " : "") + ranked[i].second;
  return out.empty() ? "the directory holds no .xml files" : "the closest are " + out;
}

std::string listed(const std::vector<fs::path>& files) {
  std::string out;
  for (const fs::path& f : files) out += (out.empty() ? "" : ", ") + f.filename().string();
  return out;
}

std::vector<fs::path> matching(const std::vector<fs::path>& files, const std::string& id, bool by_content) {
  std::vector<fs::path> out;
  for (const fs::path& f : files)
    if ((by_content ? id_from_content(f) : id_from_file_name(f)) == id) out.push_back(f);
  return out;
}

}  // namespace

fs::path find_hatt_model_file(const fs::path& dir, std::string_view material) {
  const std::string id = material_id(material);
  const std::vector<fs::path> files = xml_files(dir);
  std::vector<fs::path> found = matching(files, id, false);
  if (found.empty()) found = matching(files, id, true);
  const std::string who = "material '" + std::string(material) + "' (id " + id + ")";
  if (found.empty())
    throw input_error(dir.string(), who, "no HaTT model file (Models_<Material>.xml) is for this material; " +
                                             closest_names(files, id),
                      "Check the material's name, or give --hatt-models the folder of the toolkit's model files");
  if (found.size() > 1)
    throw input_error(dir.string(), who, std::to_string(found.size()) + " model files match: " + listed(found),
                      "Keep one model file per material in the folder");
  return found.front();
}

ar::PiecewiseArModel load_hatt_published(const fs::path& dir, std::string_view material) {
  const fs::path file = find_hatt_model_file(dir, material);
  ar::ModelSet set = convert::read_hatt_model(file);
  if (!set.material.empty() && material_id(set.material) != material_id(material))
    throw input_error(file.string(), "material",
                      "holds the model of '" + set.material + "', not of '" + std::string(material) + "'",
                      "Rename the file after the material it holds, or fix its <material>");
  return ar::PiecewiseArModel(std::move(set));
}

}  // namespace haptex::evaluate
