#pragma once
// Each recording is cut into equal contiguous sections (docs/split.md); a window belongs to a
// section only when every sample it uses (action and target) lies inside it.
#include <cstddef>
#include <cstdint>

namespace haptex::split {

// First sample of section s of a recording of n samples cut into `sections`: floor(s n / sections).
std::int64_t section_begin(std::size_t s, std::int64_t samples, std::size_t sections);

// The section holding samples [first, end), or -1 when they cross a section boundary.
int section_of(std::int64_t first, std::int64_t end, std::int64_t samples, std::size_t sections);

}  // namespace haptex::split
