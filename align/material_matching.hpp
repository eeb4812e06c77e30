#pragma once
// Which material of the recordings file is which material of the gelsight file. Names are compared
// normalised for case, spaces, underscores and hyphens ("Sandpaper_100" = "sandpaper 100"); a JSON
// name map ({"<gelsight name>": "<recordings name>", ...}, schemas/name-map.schema.json) joins the rest.
#include <map>
#include <string>
#include <vector>

namespace haptex::align {

struct NamedMaterial {
  std::string id;    // the group name in its file (/materials/<id>)
  std::string name;  // its `name` attribute
};

struct MaterialPair {
  std::string id;  // the dataset's material id (the recordings file's)
  NamedMaterial recordings, gelsight;
};

struct MaterialMatch {
  std::vector<MaterialPair> pairs;                     // sorted by id
  std::vector<NamedMaterial> only_recordings, only_gelsight;
};

// name_map: gelsight name -> recordings name (empty: names only). Throws haptex::Error (bad_input)
// naming `map_file` when a map entry names a material that is not there, and when one material
// would be joined with two (two gelsight materials onto one recording material, or the other way).
MaterialMatch match_materials(const std::vector<NamedMaterial>& recordings, const std::vector<NamedMaterial>& gelsight,
                              const std::map<std::string, std::string>& name_map = {},
                              const std::string& map_file = "--names");

// Reads and validates a name map file.
std::map<std::string, std::string> load_name_map(const std::string& path);

}  // namespace haptex::align
