#include "dataset/windows_file.hpp"

#include "core/h5/atomic_file.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {

void write_windows_file(const WindowsFile& file, const std::string& path, bool overwrite, const std::string& source) {
  h5::AtomicFile out(path, overwrite, format_name(Kind::windows));
  h5::Group root = out.root();
  stamp(root, Kind::windows, source);
  root.set_attr(layout::kDatasetFile, file.dataset_file);
  root.set_attr(layout::kDatasetSha256, file.dataset_sha256);
  root.set_attr(layout::kSplitFile, file.split_file);
  root.set_attr(layout::kSplitSha256, file.split_sha256);
  write_window_table(root, file.windows);
  h5::Group windows = root.open_group(layout::kWindows);
  windows.write(layout::kWindowSection, file.section)
      .set_attr("description", "the window's test section of its recording (the split's section number)");
  windows.write(layout::kWindowPress, file.press)
      .set_attr("description", "the material's test press: /materials/{material}/presses/{press} of the dataset file");
  out.commit();
}

}  // namespace haptex::dataset
