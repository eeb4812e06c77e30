#include "core/h5/stored_type.hpp"

#include <hdf5.h>

#include "core/error.hpp"
#include "core/h5/handle.hpp"

namespace haptex::h5 {
namespace {

bool whole_bytes(std::size_t size, std::size_t precision, std::size_t offset) { return precision == 8 * size && offset == 0; }

}  // namespace

std::string number_type_fault(hid_t type) {
  const H5T_class_t kind = H5Tget_class(type);
  if (kind == H5T_VLEN || kind == H5T_ARRAY || kind == H5T_ENUM) {
    const Handle element(H5Tget_super(type));
    return element.valid() ? number_type_fault(element.get()) : "an element type HDF5 cannot read";
  }
  if (kind != H5T_INTEGER && kind != H5T_FLOAT) return "";
  const std::size_t size = H5Tget_size(type), precision = H5Tget_precision(type);
  const int offset = H5Tget_offset(type);
  const bool integer = kind == H5T_INTEGER;
  const bool sized = integer ? (size == 1 || size == 2 || size == 4 || size == 8) : (size == 2 || size == 4 || size == 8);
  if (sized && offset >= 0 && whole_bytes(size, precision, std::size_t(offset))) return "";
  return std::string(integer ? "an integer" : "a float") + " of " + std::to_string(size) + " bytes holding " + std::to_string(precision) +
         " bits at bit " + std::to_string(offset);
}

void require_sound_number_type(hid_t type, const std::string& file, const std::string& where) {
  if (const std::string fault = number_type_fault(type); !fault.empty())
    throw input_error(file, where, "its datatype is damaged: " + fault + ", which no HDF5 writer makes (HDF5 would read past its buffers)",
                      "The file is damaged: copy it again, or make it again with the haptex command that wrote it");
}

}  // namespace haptex::h5
