#pragma once
// The predictor's per-query work, y = activation(W x + b), for one column x: the haptic loop's call
// (docs/predict.md, "Speed"). On a CPU with AVX2 and FMA it runs kernels for them, chosen at run time,
// since the build targets plain x86-64; elsewhere Eigen's. Training does not use them: a model trains to
// the same weights on any x86-64.
#include <Eigen/Core>

#include "predict/mlp.hpp"

namespace haptex::predict {

// out = activation(weight x in + bias); `weight` may be a block of a layer's weight matrix (its
// columns contiguous). Allocation-free when out has weight.rows() values already (it is resized
// otherwise). Throws haptex::Error when in or bias do not fit the weights.
void dense_column(const Eigen::Ref<const Eigen::MatrixXf>& weight, const Eigen::VectorXf& in, const Eigen::VectorXf& bias,
                  Activation activation, Eigen::VectorXf& out);

// activate(activation, values), softplus with an AVX2 kernel where there is one: within 3e-7 relative
// of max(z, 0) + log1p(e^-|z|) in double (tests/predict/dense_kernel_test.cpp), so a prediction
// differs between CPUs with and without AVX2 by a few units in the last place.
void activate_fast(Activation activation, Eigen::Ref<Eigen::MatrixXf> values);

// Whether dense_column uses the AVX2 and FMA kernel on this CPU.
bool dense_kernel_uses_avx2();

}  // namespace haptex::predict
