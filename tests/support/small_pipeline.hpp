#pragma once
// Good files from the real pipeline, made once per test program: haptex synth materials (2
// materials, 5 presses, 3 s recordings, 160 x 120 frames), convert, capture extract, align and split.
// Tests read them or copy a file and break one thing in the copy.
#include <string>
#include <vector>

#include "tests/support/temp_dir.hpp"

namespace haptex::test {

struct SmallPipeline {
  std::string recordings, gelsight, dataset, split;
  std::string truth;  // synth materials' truth.h5 (every material, the dropped ones too)
};

// Builds the files on first use (each step through the haptex binary, as a user runs it).
const SmallPipeline& small_pipeline();

// The id of the small pipeline's first material (for --material).
std::string small_material();

// A copy of `file` in a fresh folder owned by `dir`, named `name`.
std::string copy_into(const TempDir& dir, const std::string& file, const std::string& name);

// The ids under /materials of a haptex file.
std::vector<std::string> material_ids(const std::string& file);
// A copy of `file` (copy_into) holding only the materials `keep`: one machine's shard of it.
std::string copy_with_materials(const TempDir& dir, const std::string& file, const std::string& name,
                                const std::vector<std::string>& keep);

}  // namespace haptex::test
