#include "dataset/recording_signals.hpp"

#include <cmath>

#include "core/error.hpp"
#include "dataset/layout.hpp"
#include "dataset/window.hpp"

namespace haptex::dataset {
namespace {

constexpr const char* kConvertAgain = "Convert the recordings again with haptex convert, then align again";

std::vector<float> read_signal(const h5::Group& recording, const char* name, const char* units) {
  if (!recording.has_dataset(name)) throw input_error(recording.file(), recording.object_path() + "/" + name, "is missing", kConvertAgain);
  const h5::Dataset d = recording.open_dataset(name);
  const std::string found = d.has_attr(layout::kUnits) ? d.attr_string(layout::kUnits) : "";
  if (found != units) throw input_error(d.file(), d.object_path(), "units are '" + found + "', expected '" + units + "'", kConvertAgain);
  if (d.shape().size() != 1) throw input_error(d.file(), d.object_path(), "is not a 1-D signal", kConvertAgain);
  // float32 as the layout says (schemas/hdf5-layout.md): a float64 value beyond its range would be read as inf.
  if (d.dtype() != "float32") throw input_error(d.file(), d.object_path(), "holds " + d.dtype() + ", expected float32", kConvertAgain);
  std::vector<float> values = d.read<float>();
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw input_error(d.file(), d.object_path() + "[" + std::to_string(i) + "]", "is not a finite number", kConvertAgain);
  return values;
}

}  // namespace

RecordingSignals read_recording_signals(const h5::Group& recording) {
  const double rate = recording.has_attr(layout::kSampleRate) ? recording.attr_double(layout::kSampleRate) : 0.0;
  if (std::abs(rate - kSampleRateHz) > 1e-6)
    throw input_error(recording.file(), recording.object_path(), "sample rate " + std::to_string(rate) + " Hz, not 10000",
                      "Resample to 10 kHz and convert again");
  RecordingSignals s{read_signal(recording, layout::kAccel, "m/s^2"), read_signal(recording, layout::kForceNormalLp, "N"),
                     read_signal(recording, layout::kSpeedLp, "mm/s"),
                     recording.has_attr(layout::kSourceSha256) ? recording.attr_string(layout::kSourceSha256) : std::string()};
  if (s.accel.size() != s.force_lp.size() || s.accel.size() != s.speed_lp.size())
    throw input_error(recording.file(), recording.object_path(),
                      std::string(layout::kAccel) + ", " + layout::kForceNormalLp + " and " + layout::kSpeedLp + " differ in length",
                      kConvertAgain);
  return s;
}

}  // namespace haptex::dataset
