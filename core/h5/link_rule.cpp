#include "core/h5/link_rule.hpp"

#include "core/error.hpp"
#include "core/h5/handle.hpp"

namespace haptex::h5 {
namespace {

// A callback of H5Literate (links) or H5Aiterate2 (attributes) that collects the names it is given.
template <typename Info>
herr_t add_name(hid_t, const char* name, const Info*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

// Attributes (and the values of dataset `object`) holding object references: links in all but name.
void reference_faults(hid_t object, bool dataset, const std::string& path, const std::string& file, LinkReport& report) {
  if (dataset) {
    Handle type(check_input(H5Dget_type(object), "read the type of " + path, file));
    if (std::optional<LinkFault> fault = holds_references(type.get())) report.faults.emplace_back(path, *fault);
  }
  H5O_info_t info;
  check_input_status(H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS), "read the attributes of " + path, file);
  if (info.num_attrs > kMostAttributes) {
    report.faults.emplace_back(path, LinkFault{"holds " + std::to_string(info.num_attrs) + " attributes; a haptex object holds at most " +
                                                   std::to_string(kMostAttributes) + ", and reading each by name would take minutes",
                                               "Remove the attributes haptex does not write, or make the file again with the haptex command that wrote it"});
    return;
  }
  for (const std::string& name : attribute_names(object, path, file)) {
    Handle attr(check_input(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open the attribute " + path + "@" + name, file));
    Handle type(check_input(H5Aget_type(attr.get()), "read the type of " + path + "@" + name, file));
    if (std::optional<LinkFault> fault = holds_references(type.get())) report.faults.emplace_back(path + "@" + name, *fault);
  }
}

void collect(hid_t group, const std::string& path, const std::string& file, CopiedObjects& seen, LinkReport& report, int depth = 1) {
  for (const std::string& name : link_names(group, path, file)) {
    const std::string member = member_path(path, name);
    ++report.links;
    H5O_info_t info;
    if (const std::optional<LinkFault> fault = follow_link(group, name, member, file, seen, info)) {
      report.faults.emplace_back(member, *fault);
    } else if (info.type == H5O_TYPE_GROUP) {
      if (depth > kDeepestGroups) {  // the members of collect's group at `depth` are `depth` levels deep
        report.faults.emplace_back(member, LinkFault{"is a group " + std::to_string(depth) + " levels deep; no haptex file nests groups beyond " +
                                                         std::to_string(kDeepestGroups),
                                                     "Remove the groups haptex does not write, or make the file again with the haptex command that wrote it"});
        continue;
      }
      Handle child(check_input(H5Gopen2(group, name.c_str(), H5P_DEFAULT), "open " + member, file));
      reference_faults(child.get(), false, member, file, report);
      collect(child.get(), member, file, seen, report, depth + 1);
    } else if (info.type == H5O_TYPE_DATASET) {
      const Dataset dataset(Handle(check_input(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "open " + member, file)), file, member);
      if (std::optional<LinkFault> fault = stored_outside(dataset.id(), member, file)) report.faults.emplace_back(member, *fault);
      if (std::optional<LinkFault> fault = unreadable_size(dataset)) report.faults.emplace_back(member, *fault);
      reference_faults(dataset.id(), true, member, file, report);
    } else {
      report.faults.emplace_back(member, neither_group_nor_dataset());
    }
  }
}

}  // namespace

std::string member_path(const std::string& group_path, const std::string& name) {
  return group_path == "/" ? "/" + name : group_path + "/" + name;
}

std::vector<std::string> link_names(hid_t group, const std::string& group_path, const std::string& file) {
  // One pass: looking each name up by its index (H5Lget_name_by_idx) builds the group's sorted name
  // table on every call, quadratic in its links (review 5: 40 000 groups took qa 19 s).
  std::vector<std::string> names;
  check_input_status(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, add_name<H5L_info_t>, &names), "list " + group_path, file);
  return names;
}

std::vector<std::string> attribute_names(hid_t object, const std::string& object_path, const std::string& file) {
  std::vector<std::string> names;  // in one pass, as link_names
  check_input_status(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, add_name<H5A_info_t>, &names),
                     "list the attributes of " + object_path, file);
  return names;
}

std::optional<LinkFault> soft_or_external(hid_t parent, const std::string& name, const std::string& path, const std::string& file) {
  H5L_info_t link;
  check_input_status(H5Lget_info(parent, name.c_str(), &link, H5P_DEFAULT), "read the link " + path, file);
  if (link.type == H5L_TYPE_HARD) return std::nullopt;
  return LinkFault{std::string("is ") + (link.type == H5L_TYPE_SOFT ? "a soft" : "an external") +
                       " link, which no haptex file holds and which is never followed: haptex reads only data stored in the file itself",
                   "Store the data in the file instead of linking to it (h5py: del f[path], then write it), or make the file again with "
                   "the haptex command that wrote it"};
}

std::optional<LinkFault> follow_link(hid_t parent, const std::string& name, const std::string& path, const std::string& file,
                                     CopiedObjects& seen, H5O_info_t& info) {
  if (std::optional<LinkFault> fault = soft_or_external(parent, name, path, file)) return fault;
  check_input_status(H5Oget_info_by_name2(parent, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT), "read " + path, file);
  if (const auto [first, added] = seen.emplace(info.addr, path); !added)
    return LinkFault{"is a second link to " + first->second + ", which no haptex file holds",
                     "Remove the extra link, or make the file again with the haptex command that wrote it"};
  return std::nullopt;
}

std::optional<LinkFault> stored_outside(hid_t dataset, const std::string& path, const std::string& file) {
  Handle creation(check_input(H5Dget_create_plist(dataset), "read the layout of " + path, file));
  if (H5Pget_external_count(creation.get()) <= 0 && H5Pget_layout(creation.get()) != H5D_VIRTUAL) return std::nullopt;
  return LinkFault{"keeps its values outside the file (external or virtual storage), which no haptex file does, and is never read",
                   "Store the values in the file itself (h5py: read them, del f[path], then write them), or make the file again "
                   "with the haptex command that wrote it"};
}

LinkFault neither_group_nor_dataset() {
  return {"is neither a group nor a dataset (a named datatype?), which no haptex file holds",
          "Remove it, or make the file again with the haptex command that wrote it"};
}

std::optional<LinkFault> unreadable_size(const Dataset& dataset) {
  std::string problem = dataset.size_problem();
  if (problem.empty()) problem = dataset.chunk_problem();
  if (problem.empty()) return std::nullopt;
  return LinkFault{problem, "The file is damaged or not what haptex wrote: remove the dataset, or make the file again with the haptex command "
                            "that wrote it"};
}

std::optional<LinkFault> holds_references(hid_t type) {
  if (H5Tdetect_class(type, H5T_REFERENCE) <= 0) return std::nullopt;
  return LinkFault{"holds HDF5 object references, which no haptex file holds: they point at objects of the file they were written in",
                   "Remove it, or make the file again with the haptex command that wrote it"};
}

LinkReport check_links(const Group& root) {
  CopiedObjects seen;
  H5O_info_t info;
  check_input_status(H5Oget_info2(root.id(), &info, H5O_INFO_BASIC), "read " + root.object_path(), root.file());
  seen.emplace(info.addr, root.object_path());
  LinkReport report;
  reference_faults(root.id(), false, root.object_path(), root.file(), report);
  collect(root.id(), root.object_path(), root.file(), seen, report);
  return report;
}

void require_link_rule(const Group& root) {
  const LinkReport report = check_links(root);
  if (report.faults.empty()) return;
  const auto& [path, fault] = report.faults.front();
  const std::size_t more = report.faults.size() - 1;
  throw input_error(root.file(), path, fault.what + (more ? " (and " + std::to_string(more) + " more such objects; 'haptex qa' lists them)" : ""),
                    fault.fix);
}

}  // namespace haptex::h5
