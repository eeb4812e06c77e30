#include "core/format_version.hpp"

#include <charconv>
#include <optional>
#include <vector>

#include "core/text/parse_number.hpp"
#include "core/version.hpp"

namespace haptex {
namespace {

std::optional<int> version_of(std::string_view name, std::string_view family) {
  if (name.size() <= family.size() + 1 || name.substr(0, family.size()) != family || name[family.size()] != '/') return std::nullopt;
  const std::string_view number = name.substr(family.size() + 1);
  // A version haptex writes: 1, 2, ... in plain decimal (review 6: "recordings/-1" and "recordings/01"
  // passed as earlier versions).
  if (!text::is_plain_decimal(number, text::Decimal::natural) || number.front() == '+' || number == "0") return std::nullopt;
  int version = 0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), version);
  if (error != std::errc() || end != number.data() + number.size()) return std::nullopt;
  return version;
}

}  // namespace

bool is_format_name(std::string_view name) {
  const std::size_t slash = name.find('/');
  return slash != std::string_view::npos && slash > 0 && version_of(name, name.substr(0, slash)).has_value();
}

bool is_newer_version(std::string_view found, std::string_view wanted) {
  const std::string_view family = wanted.substr(0, wanted.find('/'));
  const std::optional<int> have = version_of(found, family), want = version_of(wanted, family);
  return have && want && *have > *want;
}

Error newer_version_error(const std::string& file, const std::string& where, const std::string& found, const std::string& wanted) {
  return input_error(file, where, "is " + found + ", written by a newer haptex than this one (" + std::string(kVersion) + "), which reads " + wanted,
                     "Read it with the haptex that wrote it, or update this one");
}

namespace {

// "1.2.3" as numbers; empty when it is not decimal digits between dots (review 11, F4: "v2.0.0",
// "1.0.0 " and "1e9" are no haptex's version).
std::vector<long> version_parts(std::string_view v) {
  std::vector<long> out;
  for (std::size_t at = 0;;) {
    const std::size_t dot = v.find('.', at);
    const std::string_view part = v.substr(at, dot == std::string_view::npos ? std::string_view::npos : dot - at);
    long n = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), n);
    if (part.empty() || part.find_first_not_of("0123456789") != std::string_view::npos || error != std::errc()) return {};
    out.push_back(n);
    if (dot == std::string_view::npos) return out;
    at = dot + 1;
  }
}

}  // namespace

bool is_haptex_version(std::string_view version) { return !version_parts(version).empty(); }

bool is_newer_haptex(std::string_view version) {
  const std::vector<long> have = version_parts(version), ours = version_parts(kVersion);
  return !have.empty() && !ours.empty() && have > ours;
}

void require_replaceable_format(const std::string& path, const std::string& found, const std::string& wanted,
                                const std::string& written_by) {
  const std::string fix = "Choose another output name, or move the file away yourself";
  const std::string_view family = std::string_view(wanted).substr(0, wanted.find('/'));
  if (found.empty())
    throw input_error(path, "", "--force replaces only a file haptex wrote as an earlier " + wanted + " output, and this one is not", fix);
  if (!version_of(found, family))
    throw input_error(path, "", "is a " + found + " file; this command writes " + wanted +
                                    ", and --force replaces only an earlier output of the same kind", fix);
  if (is_newer_version(found, wanted))
    throw input_error(path, "", "is " + found + ", written by a newer haptex than this one (" + std::string(kVersion) +
                                    "); --force does not replace it", fix);
  if (is_newer_haptex(written_by))
    throw input_error(path, "", "was written by haptex " + written_by + ", newer than this one (" + std::string(kVersion) +
                                    "); --force does not replace it", fix);
  if (!written_by.empty() && !is_haptex_version(written_by))  // review 11, F4: "v2.0.0", "1e9" were replaced
    throw input_error(path, "", "states haptex_version '" + written_by + "', which no haptex writes; --force does not replace it", fix);
}

}  // namespace haptex
