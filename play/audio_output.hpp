#pragma once
// Where `haptex play` hands its samples: a sound card through ALSA (play/alsa_output.hpp), or in the
// tests the same code on ALSA's file and null plugins. The player computes 10 ms frames and knows
// nothing of devices; the output paces it (docs/play.md, "Timing").
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace haptex::play {

class AudioOutput {
 public:
  virtual ~AudioOutput() = default;
  virtual unsigned rate() const = 0;                  // samples per second, exactly what the device runs at
  virtual std::size_t period_samples() const = 0;     // one 10 ms frame at rate()
  virtual std::size_t buffer_samples() const = 0;     // queued ahead of what sounds: the buffer's latency
  virtual std::string description() const = 0;       // the device and its format
  // Fills the buffer with silence and starts the device: period 0 is due now. Then clocked() tells
  // whose clock paces the periods: the device's, or haptex's where the device keeps no time.
  virtual void start() = 0;
  virtual bool clocked() const = 0;
  // Hands one period (16-bit, mono, full scale 32767) to the device once it is due, waiting for it.
  virtual void play(std::span<const std::int16_t> samples) = 0;
  // Waits until everything handed over has sounded.
  virtual void drain() = 0;
  // Periods the device ran out of samples before (each one silence), and periods handed over after
  // they were due (the buffer then held less than it should: the next delay may be an underrun).
  virtual std::uint64_t underruns() const = 0;
  virtual std::uint64_t late_periods() const = 0;
};

}  // namespace haptex::play
