#include "render/reconstruction.hpp"

#include "core/error.hpp"

namespace haptex::render {

std::string reconstruction_name(Reconstruction reconstruction) {
  return reconstruction == Reconstruction::fgla ? "fgla" : reconstruction == Reconstruction::online ? "online" : "noise";
}

Reconstruction parse_reconstruction(const std::string& name) {
  if (name == "fgla") return Reconstruction::fgla;
  if (name == "online") return Reconstruction::online;
  if (name == "noise") return Reconstruction::noise;
  throw Error(Error::Kind::bad_input, "render: unknown reconstruction '" + name +
                                          "'. Use fgla (offline fast Griffin-Lim), online (RTISI-LA, as a live loop) or noise "
                                          "(white noise shaped to each frame)");
}

}  // namespace haptex::render
