#include "core/h5/handle.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"

namespace haptex::h5 {
namespace {

// HDF5 closes the files still open at exit from an exit handler, and after a failed flush (a full
// disk) HDF5 1.10 crashes doing so. haptex closes every file it writes, or abandons it and removes
// its temporary, before exit, so the handler has nothing to do: it is not installed. This must run
// before the library's first call, hence a static initialiser.
[[maybe_unused]] const herr_t kNoExitHandler = H5dont_atexit();

}  // namespace

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

namespace {

// The failed system call's reason, when HDF5's innermost message carries one ("... errno = 28, error
// message = 'No space left on device', ..."): a full disk in plain words, not the driver's report.
std::string plain_reason(const std::string& detail) {
  const std::size_t at = detail.find("errno = ");
  if (at == std::string::npos) return detail;
  const int code = std::atoi(detail.c_str() + at + 8);
  if (code == ENOSPC) return "the disk is full: no space left on the device";
  if (code == EDQUOT) return "the disk quota is used up";
  return std::strerror(code);
}

}  // namespace

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
  return plain_reason(message);
}

hid_t check(hid_t id, const std::string& what, const std::string& path) {
  silence_library_errors();  // this thread's next failure is not printed either
  if (id < 0) {
    std::string detail = last_library_error();
    throw failure(path + ": HDF5 could not " + what + (detail.empty() ? "" : " (" + detail + ")"));
  }
  return id;
}

void check_status(herr_t status, const std::string& what, const std::string& path) {
  if (status < 0) check(H5I_INVALID_HID, what, path);
}

Error input_failure(const std::string& what, const std::string& path, const std::string& detail) {
  return input_error(path, "", "HDF5 could not " + what + (detail.empty() ? "" : " (" + detail + ")"),
                     "The file is truncated, damaged or not what haptex wrote there: copy it again, or make it again with "
                     "the haptex command that wrote it (h5clear does not repair a truncated file)");
}

hid_t check_input(hid_t id, const std::string& what, const std::string& path) {
  if (id < 0) throw input_failure(what, path, last_library_error());
  return id;
}

void check_input_status(herr_t status, const std::string& what, const std::string& path) {
  if (status < 0) check_input(H5I_INVALID_HID, what, path);
}

}  // namespace haptex::h5
