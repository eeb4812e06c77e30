#include "tests/support/fake_sound_card.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace haptex::test {

FakeSoundCard::FakeSoundCard() {
  std::ofstream(dir_.file("asound.conf")) << "pcm.nothing { type null }\n"
                                          << "pcm.capture { type file; slave { pcm \"nothing\" } file \"" << raw()
                                          << "\" format \"raw\" }\n";
  ::setenv("ALSA_CONFIG_PATH", dir_.file("asound.conf").c_str(), 1);
}

FakeSoundCard::~FakeSoundCard() { ::unsetenv("ALSA_CONFIG_PATH"); }

std::vector<std::int16_t> FakeSoundCard::samples() const {
  std::ifstream in(raw(), std::ios::binary);
  std::vector<std::int16_t> out(std::filesystem::file_size(raw()) / 2);
  in.read(reinterpret_cast<char*>(out.data()), std::streamsize(out.size() * 2));
  return out;
}

}  // namespace haptex::test
