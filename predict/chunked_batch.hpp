#pragma once
// Data-parallel gradients that do not depend on the thread count: a mini-batch is cut into chunks
// of a fixed size, each chunk's gradient goes to its own slot, and the slots are summed in chunk
// order. Same seed, same weights, on 1 core or 16.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include "core/parallel.hpp"

namespace haptex::predict {

inline constexpr std::size_t kChunkColumns = 64;

// work(begin, end, slot) computes the loss of columns [begin, end) and adds their gradient to slot
// (zeroed before). Returns the summed loss; total receives the summed gradient.
template <typename Gradient>
double chunked_gradient(std::size_t columns, std::vector<Gradient>& slots, Gradient& total, unsigned threads,
                        const std::function<double(std::size_t, std::size_t, Gradient&)>& work) {
  const std::size_t chunks = (columns + kChunkColumns - 1) / kChunkColumns;
  while (slots.size() < chunks) slots.push_back(total);
  std::vector<double> loss(chunks, 0.0);
  parallel_for(chunks, [&](std::size_t c) {
    slots[c].zero();
    loss[c] = work(c * kChunkColumns, std::min(columns, (c + 1) * kChunkColumns), slots[c]);
  }, threads);
  total.zero();
  double sum = 0;
  for (std::size_t c = 0; c < chunks; ++c) {
    total += slots[c];
    sum += loss[c];
  }
  return sum;
}

}  // namespace haptex::predict
