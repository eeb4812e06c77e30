#pragma once
// An ALSA playback device (libasound2): mono 16-bit at 48 or 44.1 kHz exactly, the rate set with
// ALSA's own resampling off, so haptex's polyphase filter is the only one (docs/play.md).
//
// Pacing. A sound card has its own clock: a write waits until the buffer has room for a period, so
// the card sets the pace and any drift between clocks is the card's. A device that keeps no time
// (ALSA's null and file plugins, as the tests use) says so by reporting nothing queued once its
// buffer is full; haptex's monotonic clock then paces the periods as the card would, and counts an
// underrun where a card with the same buffer would have run dry.
#include <alsa/asoundlib.h>

#include <chrono>
#include <memory>
#include <vector>

#include "play/audio_output.hpp"

namespace haptex::play {

class AlsaOutput : public AudioOutput {
 public:
  // Opens `device` (an ALSA name: default, plughw:1,0, or one an ALSA configuration defines) with a
  // buffer of `buffer_periods` 10 ms periods. Throws haptex::Error (bad_input) naming the device when
  // it cannot be opened or takes neither rate exactly.
  AlsaOutput(const std::string& device, unsigned buffer_periods);
  ~AlsaOutput() override;

  unsigned rate() const override { return rate_; }
  std::size_t period_samples() const override { return period_; }
  std::size_t buffer_samples() const override { return buffer_; }
  std::string description() const override;
  void start() override;
  bool clocked() const override { return clocked_; }
  void play(std::span<const std::int16_t> samples) override;
  void drain() override;
  std::uint64_t underruns() const override { return underruns_; }
  std::uint64_t late_periods() const override { return late_; }

 private:
  void configure(unsigned buffer_periods);
  void write(std::span<const std::int16_t> samples);
  void recover(int error);
  std::string device_;
  snd_pcm_t* pcm_ = nullptr;
  unsigned rate_ = 0, channels_ = 1;
  std::size_t period_ = 0, buffer_ = 0;
  bool clocked_ = true;
  std::chrono::steady_clock::time_point start_;  // without a clock: when period 0 was due
  std::uint64_t periods_ = 0, underruns_ = 0, late_ = 0;
  std::vector<std::int16_t> interleaved_;  // a period on every channel, for a device that takes no mono
};

}  // namespace haptex::play
