#pragma once
// Reads a WAV file back with libsndfile, for the tests of what haptex render writes.
#include <sndfile.h>

#include <string>
#include <vector>

namespace haptex::test {

struct WavFile {
  SF_INFO info{};
  std::vector<double> samples;  // first channel, -1..1 of full scale
  std::string comment;          // SF_STR_COMMENT (RIFF LIST/INFO ICMT)
  // The m/s^2 per full scale the comment states ("full_scale_m_s2=<value>"); NaN when absent.
  double full_scale() const;
};

// Throws std::runtime_error when libsndfile cannot open the file.
WavFile read_wav_file(const std::string& path);

}  // namespace haptex::test
