#pragma once
// Writes a recording in the default HaTT recorded-data XML form (DESIGN.md section 4,
// schemas/hatt-recording-map.json), the form `haptex convert hatt` reads.
#include <string>

#include "convert/recording.hpp"

namespace haptex::synth {

// Atomic: written to PATH.partial, synced, renamed. Values with 6 decimals, as the HaTT files.
void write_recorded_data_xml(const std::string& path, const convert::Recording& recording);

}  // namespace haptex::synth
