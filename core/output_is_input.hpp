#pragma once
// No command may write over what it reads: an output that is one of the inputs (the same file by
// device and inode, so another spelling, a symbolic or a hard link counts too) is refused with or
// without --force, and so is an output folder that would be replaced while it holds an input.
#include <string>
#include <vector>

namespace haptex {

// Throws haptex::Error (bad input) naming output and the input it is, or holds. Inputs and outputs
// that do not exist yet are skipped; empty strings (options not given) are ignored.
// kStandardInput among the inputs stands for what a command reads on standard input (play --actions -:
// a CSV redirected from a file is an input too; review 14, F5).
inline constexpr const char* kStandardInput = "/dev/stdin";
void refuse_output_among_inputs(const std::string& output, const std::vector<std::string>& inputs);

// Whether two output names (which may not exist yet) are one path: "x.wav", "./x.wav" and "d/../x.wav"
// are, and so is a name through a symbolic link to a folder. For outputs of one command that must differ.
bool same_output_path(const std::string& a, const std::string& b);

}  // namespace haptex
