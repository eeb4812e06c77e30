#pragma once
// Material names as users write them ("Brick 2", "Sandpaper_100") and the ids haptex files use.
#include <string>
#include <string_view>

namespace haptex {

// Lower case; every run of characters other than letters and digits becomes one '_';
// no leading or trailing '_'. "Brick 2" -> "brick_2", "Sandpaper-100" -> "sandpaper_100".
std::string material_id(std::string_view name);

}  // namespace haptex
