#pragma once
// Material names as users write them ("Brick 2", "Sandpaper_100", "木材 1") and the ids haptex files
// use: lower case ASCII letters, digits and '_'.
#include <string>
#include <string_view>

namespace haptex {

// Lower case; every run of spaces, punctuation and invisible characters becomes one '_'; no leading
// or trailing '_'. "Brick 2" -> "brick_2", "Sandpaper-100" -> "sandpaper_100". A letter beyond ASCII
// keeps its place as 'u' and its code point in hex, a word of its own, after case folding where
// Latin, Greek and Cyrillic have one: "Café 1" -> "caf_u00e9_1", "CAFÉ 1" too, "Cafè 1" ->
// "caf_u00e8_1", "木材 1" -> "u6728_u6750_1". So names differ in their id whenever they differ in more
// than case, spaces and punctuation (review 5: "木材 1" and "金属 1" both became "1" and were merged).
// An id is its own id.
std::string material_id(std::string_view name);

// Whether two names are one material's: they differ only in case, spaces and punctuation. Not the
// same as one id: "Caf u00e9 1" spells out in letters the id "Café 1" gets (review 15, R9).
bool same_material_name(std::string_view a, std::string_view b);

// The longest material id haptex takes, in bytes: file names are made of it (a contact sheet
// "<id>_press_12.png", split's "<id>_points.csv"), and a file name holds at most 255 (review 10, F5:
// a 300-character name passed every reader, then split and extract failed at their end).
inline constexpr std::size_t kLongestMaterialId = 100;
// material_id(name); throws haptex::Error (bad_input) naming `file` and `where` when it is empty (no
// letter or digit) or longer than kLongestMaterialId.
std::string checked_material_id(std::string_view name, const std::string& file, const std::string& where);

}  // namespace haptex
