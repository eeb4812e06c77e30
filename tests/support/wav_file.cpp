#include "tests/support/wav_file.hpp"

#include <cmath>
#include <stdexcept>

namespace haptex::test {

double WavFile::full_scale() const {
  const std::string key = "full_scale_m_s2=";
  const auto at = comment.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(comment.substr(at + key.size()));
}

WavFile read_wav_file(const std::string& path) {
  WavFile w;
  SNDFILE* f = sf_open(path.c_str(), SFM_READ, &w.info);
  if (!f) throw std::runtime_error(path + ": " + sf_strerror(nullptr));
  std::vector<double> frames(std::size_t(w.info.frames) * std::size_t(w.info.channels));
  sf_readf_double(f, frames.data(), w.info.frames);
  for (std::size_t i = 0; i < frames.size(); i += std::size_t(w.info.channels)) w.samples.push_back(frames[i]);
  if (const char* c = sf_get_string(f, SF_STR_COMMENT)) w.comment = c;
  sf_close(f);
  return w;
}

}  // namespace haptex::test
