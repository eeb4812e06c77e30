#include "split/sections.hpp"

namespace haptex::split {

std::int64_t section_begin(std::size_t s, std::int64_t samples, std::size_t sections) {
  return std::int64_t(s) * samples / std::int64_t(sections);
}

int section_of(std::int64_t first, std::int64_t end, std::int64_t samples, std::size_t sections) {
  if (first < 0 || end > samples || first >= end) return -1;
  // The section of the first sample, by the same rounding as section_begin.
  std::size_t s = std::size_t(first * std::int64_t(sections) / samples);
  while (s + 1 < sections && section_begin(s + 1, samples, sections) <= first) ++s;
  while (s > 0 && section_begin(s, samples, sections) > first) --s;
  return end <= section_begin(s + 1, samples, sections) ? int(s) : -1;
}

}  // namespace haptex::split
