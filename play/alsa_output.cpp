#include "play/alsa_output.hpp"

#include <algorithm>
#include <cerrno>
#include <thread>

#include "core/error.hpp"

namespace haptex::play {
namespace {

constexpr unsigned kRates[] = {48000, 44100};  // what every card and every browser plays

// libasound prints its own errors to stderr; haptex says what went wrong itself (the library never prints).
extern "C" void quiet(const char*, int, const char*, int, const char*, ...) {}

std::string alsa_text(int error) { return snd_strerror(error); }

}  // namespace

AlsaOutput::AlsaOutput(const std::string& device, unsigned buffer_periods) : device_(device) {
  snd_lib_error_set_handler(quiet);
  if (const int e = snd_pcm_open(&pcm_, device_.c_str(), SND_PCM_STREAM_PLAYBACK, 0); e < 0) {
    pcm_ = nullptr;
    throw input_error(device_, "", "cannot open this ALSA playback device: " + alsa_text(e),
                      "Name a playback device with --device: default, plughw:CARD,DEVICE (aplay -L lists them)");
  }
  try {
    configure(buffer_periods);
  } catch (...) {
    snd_pcm_close(pcm_);
    throw;
  }
}

AlsaOutput::~AlsaOutput() {
  if (pcm_) snd_pcm_close(pcm_);
}

void AlsaOutput::configure(unsigned buffer_periods) {
  const auto refuse = [&](const std::string& what, const std::string& fix) { throw input_error(device_, "", what, fix); };
  snd_pcm_hw_params_t* hw = nullptr;
  snd_pcm_hw_params_alloca(&hw);
  snd_pcm_hw_params_any(pcm_, hw);
  snd_pcm_hw_params_set_rate_resample(pcm_, hw, 0);  // no hidden rate conversion: haptex resamples itself
  if (snd_pcm_hw_params_set_access(pcm_, hw, SND_PCM_ACCESS_RW_INTERLEAVED) < 0 ||
      snd_pcm_hw_params_set_format(pcm_, hw, SND_PCM_FORMAT_S16_LE) < 0)
    refuse("takes no interleaved 16-bit samples", "Use the device through ALSA's plug layer: plughw:CARD,DEVICE");
  channels_ = snd_pcm_hw_params_test_channels(pcm_, hw, 1) == 0 ? 1 : 2;  // some cards play only stereo
  if (snd_pcm_hw_params_set_channels(pcm_, hw, channels_) < 0) refuse("plays neither one nor two channels", "Use plughw:CARD,DEVICE");
  for (const unsigned r : kRates)
    if (rate_ == 0 && snd_pcm_hw_params_test_rate(pcm_, hw, r, 0) == 0) rate_ = r;
  if (rate_ == 0 || snd_pcm_hw_params_set_rate(pcm_, hw, rate_, 0) < 0)
    refuse("runs at neither 48000 nor 44100 Hz", "Use plughw:CARD,DEVICE, whose rate haptex sets exactly");
  period_ = rate_ / 100;
  snd_pcm_uframes_t period = period_, buffer = period_ * buffer_periods;
  snd_pcm_hw_params_set_period_size_near(pcm_, hw, &period, nullptr);
  snd_pcm_hw_params_set_buffer_size_near(pcm_, hw, &buffer);
  if (const int e = snd_pcm_hw_params(pcm_, hw); e < 0) refuse("refuses the settings: " + alsa_text(e), "Try plughw:CARD,DEVICE");
  buffer_ = buffer;
  snd_pcm_sw_params_t* sw = nullptr;
  snd_pcm_sw_params_alloca(&sw);
  snd_pcm_sw_params_current(pcm_, sw);
  snd_pcm_sw_params_set_start_threshold(pcm_, sw, buffer);  // starts once the buffer is full
  snd_pcm_sw_params_set_avail_min(pcm_, sw, period_);
  if (const int e = snd_pcm_sw_params(pcm_, sw); e < 0) refuse("refuses the start settings: " + alsa_text(e), "Try plughw:CARD,DEVICE");
}

// A full buffer of silence starts the device; one that then reports nothing queued keeps no time.
void AlsaOutput::start() {
  const std::vector<std::int16_t> silence(buffer_, 0);
  write(silence);
  snd_pcm_sframes_t delay = 0;
  clocked_ = snd_pcm_delay(pcm_, &delay) == 0 && delay > 0;
  start_ = std::chrono::steady_clock::now();
}

std::string AlsaOutput::description() const {
  return device_ + " (16-bit, " + std::to_string(channels_) + (channels_ == 1 ? " channel, " : " channels, ") +
         std::to_string(rate_) + " Hz, buffer " + std::to_string(buffer_ * 1000 / rate_) + " ms)";
}

void AlsaOutput::recover(int error) {
  if (error == -EPIPE) ++underruns_;
  if (const int e = snd_pcm_recover(pcm_, error, 1); e < 0)
    throw failure(device_ + ": the ALSA device failed: " + alsa_text(e) + " (was it unplugged?)");
  // Restart with the buffer's latency, as at the start.
  const std::vector<std::int16_t> silence(buffer_ - std::min(buffer_, period_), 0);
  write(silence);
}

void AlsaOutput::write(std::span<const std::int16_t> samples) {
  std::span<const std::int16_t> frames = samples;
  if (channels_ == 2) {
    interleaved_.resize(samples.size() * 2);
    for (std::size_t i = 0; i < samples.size(); ++i) interleaved_[2 * i] = interleaved_[2 * i + 1] = samples[i];
    frames = interleaved_;
  }
  std::size_t done = 0;
  while (done < samples.size()) {
    const snd_pcm_sframes_t n = snd_pcm_writei(pcm_, frames.data() + done * channels_, samples.size() - done);
    if (n == -EAGAIN || n == -EINTR) continue;
    if (n < 0) {
      recover(int(n));
      continue;
    }
    done += std::size_t(n);
  }
}

void AlsaOutput::play(std::span<const std::int16_t> samples) {
  const auto frame = std::chrono::nanoseconds(1000000000LL * std::int64_t(period_) / rate_);
  if (clocked_) {
    // Room for more than one and a half periods: the device played on while this one was computed.
    if (const snd_pcm_sframes_t room = snd_pcm_avail_update(pcm_); room > snd_pcm_sframes_t(period_ + period_ / 2)) ++late_;
  } else {
    const auto due = start_ + frame * std::int64_t(periods_);
    const auto now = std::chrono::steady_clock::now();
    const auto buffered = std::chrono::nanoseconds(1000000000LL * std::int64_t(buffer_) / rate_);
    if (now < due)
      std::this_thread::sleep_until(due);
    else if (now > due + buffered) {
      ++underruns_;  // a card with this buffer would have played silence, and started again from now
      start_ = now - frame * std::int64_t(periods_);
    }
    else if (now > due + frame / 2)
      ++late_;
  }
  ++periods_;
  write(samples);
}

void AlsaOutput::drain() {
  if (!clocked_) std::this_thread::sleep_until(start_ + std::chrono::nanoseconds(1000000000LL * std::int64_t(period_ * periods_ + buffer_) / rate_));
  snd_pcm_drain(pcm_);
}

}  // namespace haptex::play
