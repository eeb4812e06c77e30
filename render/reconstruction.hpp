#pragma once
// How predicted magnitudes become a signal: the one choice haptex render (--reconstruct) and the
// stitched-signal experiment of haptex evaluate share (docs/render.md, "What it computes").
#include <string>

namespace haptex::render {

// fgla: offline fast Griffin-Lim (render/griffin_lim.hpp); online: RTISI-LA, frame by frame
// (render/online_reconstruction.hpp); noise: white noise shaped to each frame, no phase
// (render/shaped_noise.hpp).
enum class Reconstruction { fgla, online, noise };

std::string reconstruction_name(Reconstruction reconstruction);  // "fgla", "online", "noise"
// Throws haptex::Error (bad_input) for another name.
Reconstruction parse_reconstruction(const std::string& name);

}  // namespace haptex::render
