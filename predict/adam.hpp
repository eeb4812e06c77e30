#pragma once
// Adam (Kingma & Ba 2015) over an Mlp's parameters.
#include "predict/mlp.hpp"

namespace haptex::predict {

struct AdamOptions {
  float learning_rate = 1e-3f, beta1 = 0.9f, beta2 = 0.999f, epsilon = 1e-8f;
};

class Adam {
 public:
  Adam(const Mlp& net, AdamOptions options);
  // One step against the mean gradient (the caller divides by the batch size).
  void step(Mlp& net, const MlpGradient& gradient);
  float learning_rate() const { return options_.learning_rate; }
  void set_learning_rate(float rate) { options_.learning_rate = rate; }

 private:
  AdamOptions options_;
  MlpGradient m_, v_;
  int t_ = 0;
};

}  // namespace haptex::predict
