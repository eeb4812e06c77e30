#pragma once
// The one way haptex drives gnuplot (split's plots, evaluate's charts). No data ever becomes
// gnuplot commands: a label enters a script only through text(), which leaves nothing gnuplot
// could expand (no quote, back-quote, backslash or control character), and scripts name their
// files relative to the folder gnuplot runs in, which it gets as its working directory.
#include <string>
#include <string_view>

namespace haptex::gnuplot {

// A gnuplot single-quoted string holding label, readable and inert: ' " ` become ’ ” ‘, a backslash
// becomes '/', control characters and bytes that are not UTF-8 become spaces and U+FFFD, and text
// past max_characters is cut with "…". Single quotes also stop gnuplot's back-quote and @ macro
// substitution, so even a missed character could not run anything.
std::string text(std::string_view label, std::size_t max_characters = 100);
// A file name for a script, through text() without the length limit a title has.
std::string file(std::string_view name);

// "pngcairo" or "png", whichever gnuplot on PATH has (pngcairo preferred); "" when gnuplot is not installed.
std::string png_terminal();

// Runs `gnuplot SCRIPT` with directory as its working directory (an argv, no shell) and reports
// whether it succeeded and left a PNG at directory/png; a failed chart's PNG is removed.
bool draw(const std::string& directory, const std::string& script, const std::string& png);

}  // namespace haptex::gnuplot
