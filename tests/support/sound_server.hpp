#pragma once
// A sound device that keeps time, for `haptex play --device default` as on a desktop: a private
// PulseAudio server (the Debian package) with one null sink, which consumes samples at its rate by the
// system clock as a card does, and a recording of the sink's monitor. ALSA's `default` reaches it
// through the pulse plugin (libasound2-plugins), as it reaches a desktop's sound server. Lives in a
// temporary folder of its own (XDG_RUNTIME_DIR, HOME and the client configuration are set while the
// object lives, and no client starts a server of its own).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tests/support/temp_dir.hpp"

namespace haptex::test {

class SoundServer {
 public:
  SoundServer();  // starts it where it can; missing() then says why it could not
  ~SoundServer();
  SoundServer(const SoundServer&) = delete;
  SoundServer& operator=(const SoundServer&) = delete;

  const std::string& missing() const { return missing_; }  // empty when the server runs
  // Stops recording the sink and returns every 16-bit sample it played (48 kHz, mono).
  std::vector<std::int16_t> stop_and_take();

 private:
  TempDir dir_;
  std::string missing_;
  std::optional<std::string> home_;  // the user's HOME, while the server's is set
  bool changed_environment_ = false;
  int server_ = -1, recorder_ = -1;
};

}  // namespace haptex::test
