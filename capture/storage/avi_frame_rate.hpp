#pragma once
// The frame rate an AVI file's own headers state. FFmpeg reports 25 fps for an AVI that states none
// (its guess), which a replay would then play at and extraction would store as the source's rate.
#include <optional>
#include <string>

namespace haptex::capture {

// nullopt when path is not an AVI (no "RIFF....AVI " at its start): its container is another's to
// read. Otherwise the rate the first video stream header states (dwRate / dwScale), else the main
// header's (1e6 / dwMicroSecPerFrame), else 0: the file does not say.
std::optional<double> avi_frame_rate(const std::string& path);

}  // namespace haptex::capture
