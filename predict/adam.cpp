#include "predict/adam.hpp"

#include <cmath>

namespace haptex::predict {
namespace {

template <typename Param, typename Grad>
void update(Param& p, const Grad& g, Grad& m, Grad& v, const AdamOptions& o, float step, float bias2) {
  m = o.beta1 * m + (1.0f - o.beta1) * g;
  v = o.beta2 * v + (1.0f - o.beta2) * g.cwiseAbs2();
  p.array() -= step * m.array() / ((v.array() / bias2).sqrt() + o.epsilon);
}

}  // namespace

Adam::Adam(const Mlp& net, AdamOptions options) : options_(options), m_(net), v_(net) {}

void Adam::step(Mlp& net, const MlpGradient& g) {
  ++t_;
  const float bias1 = 1.0f - std::pow(options_.beta1, float(t_)), bias2 = 1.0f - std::pow(options_.beta2, float(t_));
  const float step = options_.learning_rate / bias1;
  for (std::size_t i = 0; i < net.layers.size(); ++i) {
    update(net.layers[i].weight, g.weight[i], m_.weight[i], v_.weight[i], options_, step, bias2);
    update(net.layers[i].bias, g.bias[i], m_.bias[i], v_.bias[i], options_, step, bias2);
  }
}

}  // namespace haptex::predict
