#pragma once
// RAII ownership of one HDF5 identifier, and the error check every C call goes through.
#include <hdf5.h>

#include "core/error.hpp"

#include <string>
#include <utility>

namespace haptex::h5 {

class Handle {
 public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
    }
    return *this;
  }
  // Copies share the object: HDF5 counts references and closes it with the last one.
  Handle(const Handle& other) : id_(other.id_) {
    if (id_ >= 0) H5Iinc_ref(id_);
  }
  Handle& operator=(const Handle& other) {
    if (this != &other) {
      reset();
      id_ = other.id_;
      if (id_ >= 0) H5Iinc_ref(id_);
    }
    return *this;
  }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset();  // closes with the function matching the identifier's type
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }  // caller closes it

 private:
  hid_t id_ = H5I_INVALID_HID;
};

// Turns HDF5's automatic error printing off (libraries never print); called by every entry point.
void silence_library_errors();
// The innermost message of HDF5's current error stack, for our own error text.
std::string last_library_error();
// The bad-input error check_input throws, for HDF5's `detail` (last_library_error) of a failure to `what`.
[[nodiscard]] Error input_failure(const std::string& what, const std::string& path, const std::string& detail);
// Throws haptex::Error (failed) naming `what` and `path` when id < 0; returns id otherwise. For
// creating and writing: a failure there is the machine's (disk full, permissions), exit code 1.
hid_t check(hid_t id, const std::string& what, const std::string& path);
void check_status(herr_t status, const std::string& what, const std::string& path);
// The same for opening and reading, where a failure means the input is truncated, damaged or not
// what haptex wrote: haptex::Error (bad input, exit code 2) saying how to get a sound copy.
hid_t check_input(hid_t id, const std::string& what, const std::string& path);
void check_input_status(herr_t status, const std::string& what, const std::string& path);

}  // namespace haptex::h5
