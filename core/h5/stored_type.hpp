#pragma once
// A stored number type as HDF5 can convert it. libhdf5 1.10 trusts a datatype message's element size:
// one flipped bit (a float32 whose size reads 20 or 255 bytes) makes H5Dread copy past its buffers
// (review 31, F4: SIGSEGV in qa, merge, view and align). The numbers haptex reads are integers of 1, 2,
// 4 or 8 bytes and floats of 2, 4 or 8, every bit of them used; anything else is damage.
#include <string>

#include <H5Ipublic.h>

namespace haptex::h5 {

// Empty when `type` (and the element type of a variable-length sequence or an array) is such a number,
// or no number at all; else what is wrong with it ("a float of 20 bytes holding 32 bits").
std::string number_type_fault(hid_t type);

// Throws haptex::Error (bad_input) naming `where` in `file` when number_type_fault finds a fault.
void require_sound_number_type(hid_t type, const std::string& file, const std::string& where);

}  // namespace haptex::h5
