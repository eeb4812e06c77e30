#include "apps/texture_options.hpp"

#include "apps/input_file_option.hpp"

#include "core/error.hpp"

namespace haptex::apps {

void add_texture_options(CLI::App& app, predict::TextureChoice& texture) {
  auto* image = app.add_option("--image", texture.image, "GelSight press image (PNG/JPEG), unified models")->check(input_file());
  app.add_option("--reference", texture.reference, "The sensor's no-contact frame for --image")->check(input_file())->needs(image);
  app.add_option("--material", texture.material, "A training material's id instead of an image")->excludes(image);
}

void require_texture(const predict::TextureChoice& texture, const std::string& command) {
  if (texture.image.empty() && texture.material.empty())
    throw Error(Error::Kind::bad_input, command + ": give --image (and --reference) or --material");
}

}  // namespace haptex::apps
