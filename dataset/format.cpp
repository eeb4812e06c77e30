#include "dataset/format.hpp"

#include <array>
#include <filesystem>

#include "core/error.hpp"
#include "core/format_version.hpp"
#include "core/h5/link_rule.hpp"
#include "core/h5/structure_probe.hpp"
#include "core/text/parse_number.hpp"
#include "core/text/utf8.hpp"

namespace haptex::dataset {
namespace {

constexpr std::array kFormats{
    Format{Kind::recordings, "recordings", 1, "haptex convert", ""},
    Format{Kind::gelsight, "gelsight", 2, "haptex capture extract",
           "it stores its images as pixels (gelsight/2 keeps them encoded, the sensor's JPEG bytes as they came)"},
    Format{Kind::dataset, "dataset", 4, "haptex align",
           "dataset/1 took the windows' action before the window, dataset/2 stored the press images as pixels, and "
           "dataset/3 took the 1 ms at the window's middle (dataset/4 takes the 45 ms up to the middle, 5 ms apart, and keeps the images encoded)"},
    Format{Kind::model, "model", 3, "haptex train",
           "it was trained on another action (model/3 takes the 45 ms up to the window's middle, 5 ms apart)"},
    Format{Kind::truth, "truth", 2, "haptex synth", "it does not record what generated each recording"},
    Format{Kind::press, "press", 1, "haptex capture record", ""},
    Format{Kind::windows, "windows", 2, "haptex windows", "its windows carry the 1 ms at the middle (windows/2: the 45 ms up to it)"},
};

std::string_view family_of(std::string_view name) { return name.substr(0, name.find('/')); }

}  // namespace

std::span<const Format> formats() { return kFormats; }

const Format& format_of(Kind kind) {
  for (const Format& f : kFormats)
    if (f.kind == kind) return f;
  throw failure("format_of: unknown kind");
}

std::string format_name(Kind kind) {
  const Format& f = format_of(kind);
  return std::string(f.family) + "/" + std::to_string(f.version);
}

std::string format_list(std::span<const Kind> kinds, std::string_view last_joint) {
  std::string list;
  for (std::size_t i = 0; i < kinds.size(); ++i)
    list += (i == 0 ? "" : i + 1 == kinds.size() ? std::string(last_joint) : ", ") + format_name(kinds[i]);
  return list;
}

std::string format_remark(std::string_view found) {
  const auto digits = [](std::string_view t) { return !t.empty() && t.find_first_not_of("0123456789") == std::string_view::npos; };
  for (const Format& f : kFormats) {
    const std::string current = format_name(f.kind);
    if (found == current) return "";
    if (family_of(found) != f.family) {
      // " recordings/1" or "Recordings/1": one of haptex's kinds, edited (review 16, F7).
      std::string family(text::trim(family_of(found)));
      for (char& c : family) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
      if (family == f.family)
        return "no version haptex writes: the attribute was edited or damaged";
      continue;
    }
    const std::string_view version = found.size() > f.family.size() ? found.substr(f.family.size() + 1) : std::string_view();
    if (!is_format_name(found) && !(digits(version) && version.front() != '0'))
      return "no version haptex writes: the attribute was edited or damaged";
    // Any version above this one, 2^31 and beyond too (F7), came from a newer haptex.
    if (version.size() > 9 || is_newer_version(found, current)) return "written by a newer haptex: this one reads " + current;
    return "an older version: this haptex reads " + current + ", which " + std::string(f.written_by) + " writes";
  }
  return "no kind of file haptex writes";
}

namespace {

std::string format_attribute(const h5::File& file, std::string (h5::Node::*read)(std::string_view) const) {
  const h5::Group root = file.root();
  if (!root.has_attr(h5::kFormatAttribute))
    throw input_error(file.path(), "/", "no haptex_format attribute: the file was not written by haptex",
                      "Give a file haptex wrote (haptex info FILE tells what a file is)");
  return (root.*read)(h5::kFormatAttribute);
}

}  // namespace

std::string read_format(const h5::File& file) { return format_attribute(file, &h5::Node::attr_string); }

std::string read_format_bytes(const h5::File& file) { return format_attribute(file, &h5::Node::attr_bytes); }

namespace {

// Throws unless the open file is of `kind` at this haptex's version.
void require_kind(const h5::File& file, Kind kind) {
  const std::string& path = file.path();
  const Format& want = format_of(kind);
  const std::string wanted = format_name(kind);
  const std::string give = "Give the file " + std::string(want.written_by) + " wrote";
  if (!file.root().has_attr(h5::kFormatAttribute))
    throw input_error(path, "/", "no haptex_format attribute: not a " + wanted + " file haptex wrote", give);
  const std::string found = read_format(file), shown = text::shortened(found);
  if (found == wanted) return;
  if (family_of(found) == want.family) {
    if (!is_format_name(found))
      throw input_error(path, "/@haptex_format",
                        "is '" + shown + "', which is no version haptex writes (" + std::string(want.family) +
                            "/N, N a plain decimal from 1): the attribute was edited or damaged",
                        "Make the file again with " + std::string(want.written_by));
    if (is_newer_version(found, wanted)) throw newer_version_error(path, "/@haptex_format", shown, wanted);
    if (!want.older.empty())
      throw input_error(path, "/@haptex_format", "is " + shown + ", written by an older haptex: " + std::string(want.older),
                        "Run " + std::string(want.written_by) + " again to write " + wanted);
  }
  for (const Format& other : kFormats)  // another kind of haptex file: say which, and what writes each
    if (family_of(found) == other.family)
      throw input_error(path, "/@haptex_format",
                        "is '" + shown + "': a " + std::string(other.family) + " file (" + std::string(other.written_by) + " writes those), not a " +
                            std::string(want.family) + " file (" + wanted + ")",
                        give);
  throw input_error(path, "/@haptex_format", "is '" + shown + "', not " + wanted, give);
}

}  // namespace

namespace {

// The kinds whose every reader reads their encoded images (or frames): their variable-length values
// are probed when the file is opened (core/h5/structure_probe.hpp), so damage there is the file's
// refusal, not a finding on whichever press is read first. A dataset's are probed when the first is
// read, since most of its readers (trajectory, windows, split) read none.
void probe_images(const h5::File& file, Kind kind) {
  if (kind == Kind::press || kind == Kind::gelsight) h5::probe_values(file.root().id(), file.path());
}

}  // namespace

h5::File open_checked(const std::string& path, Kind kind) {
  h5::File file = h5::File::open(path);
  require_kind(file, kind);
  h5::require_link_rule(file.root());
  probe_images(file, kind);
  return file;
}

OpenedFile open_any(const std::string& path, std::span<const Kind> kinds, const std::string& who, const std::string& fix,
                    Links links) {
  h5::File file = h5::File::open(path);
  const std::string found = read_format(file);
  for (const Kind kind : kinds)
    if (family_of(found) == format_of(kind).family) {
      require_kind(file, kind);
      if (links == Links::refuse) h5::require_link_rule(file.root());
      probe_images(file, kind);
      return {std::move(file), kind};
    }
  throw input_error(path, "/@" + std::string(h5::kFormatAttribute), "is '" + text::shortened(found) + "': " + who + " " + format_list(kinds) + " files", fix);
}

void stamp(h5::Group root, Kind kind, const std::string& source) { h5::stamp_root(root, format_name(kind), source); }

}  // namespace haptex::dataset
