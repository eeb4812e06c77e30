#pragma once
// What a page embeds: images and charts as data: URIs, vibration as audio players.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace haptex::page {

// A PNG's bytes as a data: URI.
std::string png_source(std::span<const std::uint8_t> png);

// Vibration (m/s^2, 10 kHz) as an embedded WAV a browser plays: 16-bit mono at 48 kHz, full scale
// `full_scale_m_s2` (louder samples clip), titled `title`. Returns the data: URI.
std::string wav_source(std::span<const double> signal_m_s2, double full_scale_m_s2, const std::string& title);

// <audio controls> of that WAV, its title attribute `title` (text).
std::string audio_player(std::span<const double> signal_m_s2, double full_scale_m_s2, const std::string& title);

// Amplitude spectra over 10..1000 Hz (any number of bins, evenly spaced) as lines of the colours given
// on a log amplitude axis: an inline SVG, labelled with its frequency ends and its highest amplitude.
// Empty when no value is above 0.
struct Line {
  std::span<const double> values;
  const char* colour;
};
std::string spectra_svg(const std::vector<Line>& lines);

}  // namespace haptex::page
