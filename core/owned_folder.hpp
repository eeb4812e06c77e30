#pragma once
// Folders haptex writes whole (synth's output, evaluate's report, extract's contact sheets) end with a
// list of every file in them, so that --force replaces such a folder only while it holds nothing
// but what haptex wrote there: a file of the user's in it is never deleted.
#include <string>
#include <string_view>

namespace haptex {

inline constexpr std::string_view kFileListName = "haptex-files.json";

// Writes dir/haptex-files.json naming every file and folder now under dir (paths relative to it),
// with each file's SHA-256, and `owner`, when given: the output the folder belongs to, relative to the
// folder (a gelsight file's contact sheets: "../g.h5"). Call it last, just before the folder is synced
// and renamed into place.
void write_file_list(const std::string& dir, std::string_view written_by, std::string_view owner = {});

// The output folder's haptex-files.json names as its owner (resolved from the folder's place), or
// empty when it names none or cannot be read.
std::string folder_owner(const std::string& folder);

// For --force on a folder about to be replaced: throws haptex::Error (bad input) when folder holds
// anything its haptex-files.json does not list (naming the first such file), a listed file whose
// bytes are no longer those haptex wrote (its SHA-256 differs: the user's own file of that name, or
// one edited since), a link, has no readable list, or was written by another command than
// `written_by` ("haptex split"). Lists of haptex before the hashes are judged by names alone. An
// empty or missing folder passes.
void check_only_haptex_files(const std::string& folder, std::string_view written_by);

// Whether `folder` is a folder `written_by` wrote that holds only its files (check_only_haptex_files,
// a file list present): one --force may retire when the new run writes none (core/output_set.hpp).
bool is_haptex_folder(const std::string& folder, std::string_view written_by);

}  // namespace haptex
