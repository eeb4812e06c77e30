#pragma once
// Rendered vibration as a WAV file, to drive a voice-coil actuator through a sound card.
//
// Format: RIFF WAV, mono, 10 kHz, 24-bit signed PCM (libsndfile). PCM because every sound card
// driver, player and ALSA's plug layer takes it (float WAV is not played everywhere, and a
// player that does not know it may play it as noise at full scale, which an actuator should never
// get); 24 bits because the quantisation floor (-144 dB of full scale) lies far below any
// amplifier's noise, so one peak-normalised file keeps the quietest strokes.
//
// Scaling: a sample s in [-1, 1] (full scale) stands for s * full_scale_m_s2 of acceleration. By
// default the full scale is the signal's peak |a| rounded up to three significant digits (so the
// loudest sample sits within 1 % of full scale and the gain is a readable number); a fixed full
// scale keeps several renderings on one scale, as an actuator chain calibrated once needs, and a
// signal louder than it is refused rather than clipped. The gain is written into the file as its
// comment (RIFF LIST/INFO ICMT, libsndfile's SF_STR_COMMENT), starting "full_scale_m_s2=<value>;".
//
// The file is written to PATH.partial, synced and renamed (core/durable_file.hpp).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "core/durable_file.hpp"
#include "dataset/window.hpp"

namespace haptex::render {

inline constexpr int kWavSampleRate = int(dataset::kSampleRateHz);

struct WavOptions {
  double full_scale_m_s2 = 0;  // m/s^2 at full scale; 0: the peak rounded up to 3 significant digits
  bool overwrite = false;
  std::string title;   // the file's title string (e.g. the material)
  std::string source;  // appended to the comment: what made the signal
};

struct WavSummary {
  std::size_t samples = 0;
  double peak_m_s2 = 0, full_scale_m_s2 = 0;
  std::string comment;  // as written
};

// signal: acceleration in m/s^2 at 10 kHz. Throws haptex::Error: bad_input naming the file when it
// exists and overwrite is false, its directory is missing or unwritable, or the signal's peak
// exceeds a given full scale; failed for a non-finite sample or a write error. Nothing is left
// under PATH or PATH.partial when it throws.
WavSummary write_wav(const std::string& path, std::span<const double> signal_m_s2, const WavOptions& options = {});
// The same into out's temporary file, leaving the commit to the caller (so a WAV and its CSV appear
// together) and the checks of the path (check_wav_output) too.
WavSummary write_wav(PartialFile& out, std::span<const double> signal_m_s2, const WavOptions& options = {});

// What a sound card played (`haptex play --record`): 16-bit samples at its rate, full scale 32767 =
// options.full_scale_m_s2 (> 0), written as they were played (PCM 16), the comment as write_wav's.
WavSummary write_played_wav(PartialFile& out, std::span<const std::int16_t> samples, int rate, const WavOptions& options);

// The same WAV's bytes, for a page that embeds it (evaluate's report.html).
std::string wav_bytes(std::span<const std::int16_t> samples, int rate, const WavOptions& options);

// Whether path is a WAV write_wav wrote (its software string starts "haptex "): what --force replaces.
bool is_haptex_wav(const std::string& path);
// check_replaceable_output for a WAV.
void check_wav_output(const std::string& path, bool overwrite);

// The full scale for a peak: rounded up to three significant digits; 1 m/s^2 for silence.
double rounded_full_scale(double peak_m_s2);

// The m/s^2 per full scale a comment written by write_wav states; NaN when it states none.
double full_scale_from_comment(const std::string& comment);

}  // namespace haptex::render
