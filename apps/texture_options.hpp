#pragma once
// --image, --reference and --material: the texture a command predicts for, declared one way by
// render and play (issue 33: one home per option).
#include <CLI/CLI.hpp>

#include "predict/texture_choice.hpp"

namespace haptex::apps {

void add_texture_options(CLI::App& app, predict::TextureChoice& texture);
// Throws haptex::Error (bad_input) naming `command` when neither an image nor a material is given.
void require_texture(const predict::TextureChoice& texture, const std::string& command);

}  // namespace haptex::apps
