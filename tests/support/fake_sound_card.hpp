#pragma once
// A sound card for `haptex play` without one: an ALSA configuration (ALSA_CONFIG_PATH, set while the
// object lives) whose device "capture" is ALSA's file plugin over its null plugin, writing the 16-bit
// samples it is given to raw().
#include <cstdint>
#include <string>
#include <vector>

#include "tests/support/temp_dir.hpp"

namespace haptex::test {

class FakeSoundCard {
 public:
  FakeSoundCard();
  ~FakeSoundCard();
  FakeSoundCard(const FakeSoundCard&) = delete;
  FakeSoundCard& operator=(const FakeSoundCard&) = delete;
  std::string raw() const { return dir_.file("played.raw"); }
  std::vector<std::int16_t> samples() const;  // what the device was given

 private:
  TempDir dir_;
};

}  // namespace haptex::test
