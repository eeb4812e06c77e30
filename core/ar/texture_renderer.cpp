#include "core/ar/texture_renderer.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace haptex::ar {

TextureRenderer::TextureRenderer(PiecewiseArModel model, std::uint64_t seed)
    : model_(std::move(model)), noise_(seed) {}

double TextureRenderer::next(double speed, double force) {
  const auto clamped = model_.clamp(speed, force);
  if (!have_blend_ || clamped[0] != blend_.speed || clamped[1] != blend_.force) {
    model_.blend_into(speed, force, blend_, work_);
    sigma_ = std::sqrt(blend_.variance);
    have_blend_ = true;
  }
  // As the toolkit: one excitation draw per tick, even where the variance is zero.
  return filter_.step(blend_.a, sigma_ * noise_.next());
}

std::vector<double> TextureRenderer::render(std::span<const double> speed, std::span<const double> force) {
  if (speed.size() != force.size())
    throw failure("render: speed has " + std::to_string(speed.size()) + " samples but force has " +
                  std::to_string(force.size()) + "; give one force per speed sample");
  std::vector<double> out(speed.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = next(speed[i], force[i]);
  return out;
}

void TextureRenderer::reset(std::uint64_t seed) {
  noise_ = GaussianNoise(seed);
  filter_.reset();
}

std::vector<double> render_texture(const PiecewiseArModel& model, std::span<const double> speed,
                                   std::span<const double> force, std::uint64_t seed) {
  TextureRenderer renderer(model, seed);
  return renderer.render(speed, force);
}

}  // namespace haptex::ar
