#pragma once
// The rule every haptex file keeps for its links: each object is reached by one hard link. A soft or
// external link points anywhere (/etc/passwd through an external link), and a second hard link makes
// one object count twice (a press read as two) or, back to a group above, a walk that never ends.
// Group::copy_from (merge, align) refuses a copy that breaks it, and qa's `layout.links` reports every
// link that does, so qa's verdict and merge's agree.
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::h5 {

// What is wrong with a link, and how to fix it.
struct LinkFault {
  std::string what, fix;
};

// The names of a group's links, in name order; throws haptex::Error (bad_input) naming `file` and
// `group_path` when they cannot be listed.
std::vector<std::string> link_names(hid_t group, const std::string& group_path, const std::string& file);

// When the link `name` in `parent` (at `path` in `file`) is soft or external, what is wrong with it.
// Every reader refuses to open one (Group::open_group, open_dataset): it may point anywhere, another
// file included, which the file's SHA-256 does not cover.
std::optional<LinkFault> soft_or_external(hid_t parent, const std::string& name, const std::string& path, const std::string& file);

// Follows the link `name` in `parent` (at `path` in `file`): its object's basic information in
// `info`, the object recorded in `seen`; or, when the link breaks the rule, what is wrong with it
// (`info` is then unset). Throws haptex::Error (bad_input) when the link cannot be read.
std::optional<LinkFault> follow_link(hid_t parent, const std::string& name, const std::string& path, const std::string& file,
                                     CopiedObjects& seen, H5O_info_t& info);

// Every link below `root`: how many, and each that breaks the rule, by path.
struct LinkReport {
  std::size_t links = 0;
  std::vector<std::pair<std::string, LinkFault>> faults;
};
LinkReport check_links(const Group& root);

}  // namespace haptex::h5
