#pragma once
// The rule every haptex file keeps for its links: each object is reached by one hard link and is a
// group or a dataset, each dataset keeps its values in the file in a size haptex reads, and no value
// is an object reference. A soft or external link
// points anywhere (/etc/passwd through an external link); a second hard link makes one object count
// twice (a press read as two) or, back to a group above, a walk that never ends; external raw
// storage or a virtual dataset reads whatever it names, a FIFO (a read that never returns) or
// /dev/zero among them; a reference points at an object of the file it was written in. Every reader
// opening a file through dataset::open_checked or open_any refuses a file that breaks it before
// reading any value; Group::open_dataset and Group::copy_from (merge, align) refuse such an object;
// qa's `layout.links` reports every one, so qa's verdict and every reader's agree.
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::h5 {

// Far more than any object haptex writes holds (about 30): HDF5 finds an attribute stored in the
// object's header by reading every one before it, so 40 000 of them took info minutes (review 5).
inline constexpr hsize_t kMostAttributes = 1000;

// haptex's files nest groups 5 deep (/nets/0/action_encoder/layers/0), plus 2 for each round of
// merging merged files (/shards/<s>/shards/<s>/...; review 25, F4: a bound of 32 refused the 16th
// round). A chain of 30 000 (a 4.8 MB file) overflowed the stack of check_links (review 23, F8); 1024
// levels, 500 rounds of merging, take under 1 MB of it. Below that depth the walk stops, with a fault
// naming the place.
inline constexpr int kDeepestGroups = 1024;

// What is wrong with a link, and how to fix it.
struct LinkFault {
  std::string what, fix;
};

// The path of member `name` of the group at `group_path` ("/name" at the root), for messages.
std::string member_path(const std::string& group_path, const std::string& name);

// The names of a group's links, in name order; throws haptex::Error (bad_input) naming `file` and
// `group_path` when they cannot be listed.
std::vector<std::string> link_names(hid_t group, const std::string& group_path, const std::string& file);
// The names of an object's attributes, in name order, the same way.
std::vector<std::string> attribute_names(hid_t object, const std::string& object_path, const std::string& file);

// When the link `name` in `parent` (at `path` in `file`) is soft or external, what is wrong with it.
// Every reader refuses to open one (Group::open_group, open_dataset): it may point anywhere, another
// file included, which the file's SHA-256 does not cover.
std::optional<LinkFault> soft_or_external(hid_t parent, const std::string& name, const std::string& path, const std::string& file);

// Follows the link `name` in `parent` (at `path` in `file`): its object's basic information in
// `info`, the object recorded in `seen`; or, when the link breaks the rule, what is wrong with it
// (`info` is then unset). Throws haptex::Error (bad_input) when the link cannot be read.
std::optional<LinkFault> follow_link(hid_t parent, const std::string& name, const std::string& path, const std::string& file,
                                     CopiedObjects& seen, H5O_info_t& info);

// An object that is neither a group nor a dataset (a named datatype): no haptex file holds one.
LinkFault neither_group_nor_dataset();

// When `dataset` declares more than haptex reads at once, or chunks that would inflate far more than
// it holds (Dataset::size_problem, chunk_problem), what is wrong (review 10: qa called clean a file
// with a never-written 4 TiB dataset that merge refused).
std::optional<LinkFault> unreadable_size(const Dataset& dataset);

// When values of HDF5 type `type` hold object references (links in all but name), what is wrong with them.
std::optional<LinkFault> holds_references(hid_t type);

// When the open dataset `dataset` (at `path`) keeps its values outside the file, what is wrong with
// it. Reads only its creation properties, never a value.
std::optional<LinkFault> stored_outside(hid_t dataset, const std::string& path, const std::string& file);

// Every link below `root`: how many, and each that breaks the rule (a link, or the storage of the
// dataset it reaches), by path.
struct LinkReport {
  std::size_t links = 0;
  std::vector<std::pair<std::string, LinkFault>> faults;
};
LinkReport check_links(const Group& root);

// Throws haptex::Error (bad_input) naming the file, the first path that breaks the rule, what is
// wrong and the fix (and how many more there are).
void require_link_rule(const Group& root);

}  // namespace haptex::h5
