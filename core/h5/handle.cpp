#include "core/h5/handle.hpp"

#include "core/error.hpp"

namespace haptex::h5 {

void Handle::reset() {
  if (id_ < 0) return;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: H5Fclose(id_); break;
    case H5I_GROUP: H5Gclose(id_); break;
    case H5I_DATASET: H5Dclose(id_); break;
    case H5I_ATTR: H5Aclose(id_); break;
    case H5I_DATATYPE: H5Tclose(id_); break;
    case H5I_DATASPACE: H5Sclose(id_); break;
    case H5I_GENPROP_LST: H5Pclose(id_); break;
    default: break;
  }
  id_ = H5I_INVALID_HID;
}

// Per thread: in HDF5's thread-safe build (Debian's) the error stack and its printing are each
// thread's own.
void silence_library_errors() {
  thread_local const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

std::string last_library_error() {
  std::string message;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* error, void* out) -> herr_t {
        auto* text = static_cast<std::string*>(out);
        if (error->desc && *error->desc) *text = error->desc;  // keep the innermost
        return 0;
      },
      &message);
  H5Eclear2(H5E_DEFAULT);
  return message;
}

hid_t check(hid_t id, const std::string& what, const std::string& path) {
  if (id < 0) {
    std::string detail = last_library_error();
    throw failure(path + ": HDF5 could not " + what + (detail.empty() ? "" : " (" + detail + ")"));
  }
  return id;
}

void check_status(herr_t status, const std::string& what, const std::string& path) {
  if (status < 0) check(H5I_INVALID_HID, what, path);
}

hid_t check_input(hid_t id, const std::string& what, const std::string& path) {
  if (id < 0) {
    const std::string detail = last_library_error();
    throw input_error(path, "", "HDF5 could not " + what + (detail.empty() ? "" : " (" + detail + ")"),
                      "The file is truncated, damaged or not what haptex wrote there: copy it again, or make it again with "
                      "the haptex command that wrote it (h5clear does not repair a truncated file)");
  }
  return id;
}

void check_input_status(herr_t status, const std::string& what, const std::string& path) {
  if (status < 0) check_input(H5I_INVALID_HID, what, path);
}

}  // namespace haptex::h5
