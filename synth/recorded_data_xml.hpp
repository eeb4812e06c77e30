#pragma once
// Writes a recording in the default HaTT recorded-data XML form (docs/convert.md,
// schemas/hatt-recording-map.json), the form `haptex convert hatt` reads.
#include <string>

#include "convert/recording.hpp"

namespace haptex::synth {

// The document's text; values with 6 decimals, as the HaTT files have them.
std::string recorded_data_xml(const convert::Recording& recording);
// The document gzip-compressed (PATH is <name>.xml.gz); atomic: written to PATH.partial, synced,
// renamed. Returns the SHA-256 of the document's text, which `haptex convert` stamps on the recording.
std::string write_recorded_data_xml(const std::string& path, const convert::Recording& recording);

}  // namespace haptex::synth
