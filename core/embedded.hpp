#pragma once
// Files from schemas/ compiled into the library (see cmake/embed_files.cmake).
#include <map>
#include <string>
#include <string_view>

namespace haptex::embedded {
const std::map<std::string, std::string_view, std::less<>>& files();
// The contents of schemas/NAME; throws haptex::Error when no such file was embedded.
std::string_view schema(std::string_view name);
}  // namespace haptex::embedded
