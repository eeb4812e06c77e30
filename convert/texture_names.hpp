#pragma once
// Names for a database's numbered textures, from the user (the Cluster database lists its textures
// in a PDF): a JSON object {"0": "Aluminium plate", ...} or a CSV with the header `id,name`.
#include <map>
#include <string>

namespace haptex::convert {

// Throws haptex::Error (bad_input) naming the file and the entry: not JSON or CSV, an id that is no
// whole number of 0 or more, an id given twice, an empty or non-UTF-8 name.
std::map<int, std::string> read_texture_names(const std::string& path);

}  // namespace haptex::convert
