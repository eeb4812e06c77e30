#pragma once
// Counts heap allocations made on this thread while a CountAllocations object lives: operator new,
// Eigen and FFTW alike, because the test programs interpose glibc's malloc family (the interposers
// in allocation_counter.cpp pass everything straight to glibc; they only count when asked).
#include <cstddef>

namespace haptex::test {

class CountAllocations {
 public:
  CountAllocations();
  ~CountAllocations();
  CountAllocations(const CountAllocations&) = delete;
  CountAllocations& operator=(const CountAllocations&) = delete;
  std::size_t count() const;

 private:
  std::size_t start_;
  bool outer_;
};

}  // namespace haptex::test
