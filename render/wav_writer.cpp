#include "render/wav_writer.hpp"

#include <sndfile.h>

#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string_view>
#include <vector>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/text/utf8.hpp"
#include "core/version.hpp"

namespace haptex::render {
namespace {

constexpr const char* kFullScaleKey = "full_scale_m_s2=";

// Nine significant digits, as %.9g.
std::string number(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value, std::chars_format::general, 9).ptr);
}

struct SndfileCloser {
  void operator()(SNDFILE* file) const { sf_close(file); }
};

double peak_of(const std::string& path, std::span<const double> signal) {
  double peak = 0;
  for (std::size_t i = 0; i < signal.size(); ++i) {
    if (!std::isfinite(signal[i]))
      throw failure(path + ": sample " + std::to_string(i) + " of the signal is " + std::to_string(signal[i]) +
                    "; a WAV needs finite samples");
    peak = std::max(peak, std::abs(signal[i]));
  }
  return peak;
}

// The comment states the full scale, the rate and the peak (summary's), then what made the signal.
void write_strings(SNDFILE* file, const std::string& path, int rate, const WavOptions& options, WavSummary& summary) {
  summary.comment = kFullScaleKey + number(summary.full_scale_m_s2) +
                    "; acceleration in m/s^2 = sample (-1..1 of full scale) x " + number(summary.full_scale_m_s2) + "; " +
                    number(rate / 1000.0) + " kHz, peak " + number(summary.peak_m_s2) + " m/s^2" +
                    (options.source.empty() ? std::string() : "; " + text::printable(options.source));
  sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE);  // a rounding past 1.0 saturates, never wraps
  const std::string software = std::string("haptex ") + kVersion;
  // Names in the strings as a terminal may show them (review 6: a trajectory's path put ESC, a newline
  // and U+202E into the comment, which sox --i and mediainfo print raw).
  const std::string title = text::printable(options.title);
  if (sf_set_string(file, SF_STR_COMMENT, summary.comment.c_str()) != 0 || sf_set_string(file, SF_STR_SOFTWARE, software.c_str()) != 0 ||
      (!title.empty() && sf_set_string(file, SF_STR_TITLE, title.c_str()) != 0))
    throw failure(path + ": cannot store the WAV's strings: " + sf_strerror(file));
}

SF_INFO mono_wav(int rate, int pcm_format) {
  SF_INFO info{};
  info.samplerate = rate;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | pcm_format;
  return info;
}

// Opens out's temporary as a mono WAV and writes its strings.
std::unique_ptr<SNDFILE, SndfileCloser> open_wav(PartialFile& out, int rate, int pcm_format, const WavOptions& options,
                                                 WavSummary& summary) {
  const std::string& path = out.final_path();
  SF_INFO info = mono_wav(rate, pcm_format);
  std::unique_ptr<SNDFILE, SndfileCloser> file(out.open_by_name([&](const std::string& path) { return sf_open(path.c_str(), SFM_WRITE, &info); }));
  if (!file)
    throw failure(path + ": cannot write it: " +
                  (errno == ENOSPC ? std::string("the disk is full") : std::string(sf_strerror(nullptr)) + " (" + out.path() + ")"));
  write_strings(file.get(), path, rate, options, summary);
  return file;
}

// The summary of 16-bit samples (full scale 32767 = options.full_scale_m_s2, which must be given).
WavSummary pcm16_summary(std::span<const std::int16_t> samples, const WavOptions& options) {
  if (!(options.full_scale_m_s2 > 0)) throw failure("internal: a WAV of 16-bit samples needs its full scale");
  WavSummary summary;
  summary.samples = samples.size();
  summary.full_scale_m_s2 = options.full_scale_m_s2;
  for (const std::int16_t v : samples) summary.peak_m_s2 = std::max(summary.peak_m_s2, std::abs(double(v)) / 32767 * options.full_scale_m_s2);
  return summary;
}

// libsndfile's virtual I/O on a string, for a WAV that goes into a page rather than a file.
struct MemoryFile {
  std::string bytes;
  sf_count_t at = 0;
};
sf_count_t memory_length(void* m) { return sf_count_t(static_cast<MemoryFile*>(m)->bytes.size()); }
sf_count_t memory_seek(sf_count_t offset, int whence, void* m) {
  MemoryFile& f = *static_cast<MemoryFile*>(m);
  f.at = (whence == SEEK_SET ? 0 : whence == SEEK_CUR ? f.at : sf_count_t(f.bytes.size())) + offset;
  return f.at;
}
sf_count_t memory_read(void* to, sf_count_t count, void* m) {
  MemoryFile& f = *static_cast<MemoryFile*>(m);
  const sf_count_t n = std::max<sf_count_t>(0, std::min<sf_count_t>(count, sf_count_t(f.bytes.size()) - f.at));
  std::memcpy(to, f.bytes.data() + f.at, std::size_t(n));
  f.at += n;
  return n;
}
sf_count_t memory_write(const void* from, sf_count_t count, void* m) {
  MemoryFile& f = *static_cast<MemoryFile*>(m);
  if (f.bytes.size() < std::size_t(f.at + count)) f.bytes.resize(std::size_t(f.at + count));
  std::memcpy(f.bytes.data() + f.at, from, std::size_t(count));
  f.at += count;
  return count;
}
sf_count_t memory_tell(void* m) { return static_cast<MemoryFile*>(m)->at; }

void close_wav(const std::string& path, std::unique_ptr<SNDFILE, SndfileCloser> file) {
  if (const int status = sf_close(file.release()); status != 0)
    throw failure(path + ": closing the WAV failed: " + sf_error_number(status));
}

}  // namespace

double rounded_full_scale(double peak_m_s2) {
  if (!(peak_m_s2 > 0) || !std::isfinite(peak_m_s2)) return 1.0;
  const double step = std::pow(10.0, std::floor(std::log10(peak_m_s2)) - 2);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", std::ceil(peak_m_s2 / step - 1e-9) * step);
  return std::strtod(text, nullptr);  // the decimal value itself, as the comment states it
}

double full_scale_from_comment(const std::string& comment) {
  const std::size_t at = comment.find(kFullScaleKey);
  if (at == std::string::npos) return std::nan("");
  const char* start = comment.c_str() + at + std::char_traits<char>::length(kFullScaleKey);
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  return end == start ? std::nan("") : value;
}

bool is_haptex_wav(const std::string& path) {
  SF_INFO info{};
  std::unique_ptr<SNDFILE, SndfileCloser> file(sf_open(path.c_str(), SFM_READ, &info));
  if (!file) return false;
  const char* software = sf_get_string(file.get(), SF_STR_SOFTWARE);
  return software && std::string_view(software).starts_with("haptex ");
}

void check_wav_output(const std::string& path, bool overwrite) {
  check_replaceable_output(path, overwrite, "a WAV haptex rendered (its software string starts \"haptex\")", is_haptex_wav);
}

WavSummary write_wav(const std::string& path, std::span<const double> signal_m_s2, const WavOptions& options) {
  check_wav_output(path, options.overwrite);
  PartialFile partial(path, options.overwrite, [](const std::string& p) { check_wav_output(p, true); });
  const WavSummary summary = write_wav(partial, signal_m_s2, options);
  partial.commit();
  return summary;
}

WavSummary write_wav(PartialFile& out, std::span<const double> signal_m_s2, const WavOptions& options) {
  const std::string& path = out.final_path();
  WavSummary summary;
  summary.samples = signal_m_s2.size();
  summary.peak_m_s2 = peak_of(path, signal_m_s2);
  if (options.full_scale_m_s2 > 0) {
    if (summary.peak_m_s2 > options.full_scale_m_s2)
      throw input_error(path, "", "the vibration's peak " + number(summary.peak_m_s2) + " m/s^2 exceeds the full scale " +
                                      number(options.full_scale_m_s2) + " m/s^2 and would clip",
                        "Give a full scale of at least " + number(rounded_full_scale(summary.peak_m_s2)) +
                            " m/s^2, or none to scale to the peak");
    summary.full_scale_m_s2 = options.full_scale_m_s2;
  } else {
    summary.full_scale_m_s2 = rounded_full_scale(summary.peak_m_s2);
  }
  std::unique_ptr<SNDFILE, SndfileCloser> file = open_wav(out, kWavSampleRate, SF_FORMAT_PCM_24, options, summary);
  std::vector<double> scaled(signal_m_s2.size());
  for (std::size_t i = 0; i < scaled.size(); ++i) scaled[i] = signal_m_s2[i] / summary.full_scale_m_s2;
  if (sf_write_double(file.get(), scaled.data(), sf_count_t(scaled.size())) != sf_count_t(scaled.size()))
    throw failure(path + ": cannot write it: " + (errno == ENOSPC ? std::string("the disk is full") : sf_strerror(file.get())));
  close_wav(path, std::move(file));
  return summary;
}

std::string wav_bytes(std::span<const std::int16_t> samples, int rate, const WavOptions& options) {
  WavSummary summary = pcm16_summary(samples, options);
  SF_VIRTUAL_IO io{memory_length, memory_seek, memory_read, memory_write, memory_tell};
  MemoryFile memory;
  SF_INFO info = mono_wav(rate, SF_FORMAT_PCM_16);
  std::unique_ptr<SNDFILE, SndfileCloser> file(sf_open_virtual(&io, SFM_WRITE, &info, &memory));
  if (!file) throw failure(std::string("a WAV in memory: ") + sf_strerror(nullptr));
  write_strings(file.get(), "a WAV in memory", rate, options, summary);
  if (sf_write_short(file.get(), samples.data(), sf_count_t(samples.size())) != sf_count_t(samples.size()))
    throw failure(std::string("a WAV in memory: ") + sf_strerror(file.get()));
  close_wav("a WAV in memory", std::move(file));
  return memory.bytes;
}

WavSummary write_played_wav(PartialFile& out, std::span<const std::int16_t> samples, int rate, const WavOptions& options) {
  WavSummary summary = pcm16_summary(samples, options);
  std::unique_ptr<SNDFILE, SndfileCloser> file = open_wav(out, rate, SF_FORMAT_PCM_16, options, summary);
  if (sf_write_short(file.get(), samples.data(), sf_count_t(samples.size())) != sf_count_t(samples.size()))
    throw failure(out.final_path() + ": cannot write it: " + (errno == ENOSPC ? std::string("the disk is full") : sf_strerror(file.get())));
  close_wav(out.final_path(), std::move(file));
  return summary;
}

}  // namespace haptex::render
