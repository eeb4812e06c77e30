// filter.*: the low-passed force and speed hold (almost) nothing above 40 Hz; the raw ones still do;
// the recording states the format's low-pass and reduction.
#include <cmath>
#include <optional>
#include <sstream>

#include "core/signal/dft321.hpp"
#include "dataset/layout.hpp"
#include "dataset/recordings_file.hpp"
#include "qa/band_power.hpp"
#include "qa/recording_checks.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

std::string scientific(double value) {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific << value;
  return out.str();
}

// The share of a signal's power above 40 Hz; nullopt, and a skip on the tally, when it has none.
std::optional<double> share_above_filter_band(const LoadedRecording& r, const std::string& name, CheckTally& tally) {
  const Signal& s = r.signals.at(name);
  if (!s.ok()) {
    tally.skip(r.path + "/" + name + " " + s.problem);
    return std::nullopt;
  }
  const double rate = r.analysis_rate();
  const BandPower p = band_power(s.values, rate, kFilterCheckHz, rate / 2);
  if (!std::isfinite(p.total)) {
    tally.skip(r.path + "/" + name + " is not finite");
    return std::nullopt;
  }
  return p.share();
}

}  // namespace

void check_filter_lowpass(const LoadedRecording& r, CheckTally& tally, Seen& share_above) {
  for (const std::string name : {layout::kForceNormalLp, layout::kSpeedLp}) {
    const std::optional<double> share = share_above_filter_band(r, name, tally);
    if (!share) continue;
    share_above.add(*share);
    if (*share > kLowpassMaxShare)
      tally.fail(r.path + "/" + name, scientific(*share) + " of its power lies above 40 Hz (at most " +
                                          scientific(kLowpassMaxShare) + " after a 20 Hz low-pass)");
    else tally.pass();
  }
  tally.set_pass_message("at most " + scientific(share_above.high) + " of a low-passed signal's power above 40 Hz");
}

void check_filter_raw(const LoadedRecording& r, CheckTally& tally, Seen& share_above) {
  for (const std::string name : {layout::kForceNormal, layout::kSpeed}) {
    const std::optional<double> share = share_above_filter_band(r, name, tally);
    if (!share) continue;
    share_above.add(*share);
    if (*share < kRawMinShare)
      tally.fail(r.path + "/" + name, "only " + scientific(*share) +
                                          " of its power lies above 40 Hz: it looks low-passed (a measured signal "
                                          "keeps at least " + scientific(kRawMinShare) + ")");
    else tally.pass();
  }
  tally.set_pass_message("at least " + scientific(share_above.low) + " of a raw signal's power above 40 Hz");
}

// The attributes saying how the signals were made state the format's low-pass and reduction: a file
// that states another cut-off (review 8: 1e300 Hz) holds signals no model of haptex's was made for.
void check_filter_stated(const LoadedRecording& r, CheckTally& tally) {
  std::string wrong, missing;
  const auto compare = [&](const char* name, const auto& stated, double format) {
    if (!stated) missing += std::string(missing.empty() ? "" : ", ") + name;
    else if (!(double(*stated) == format))
      wrong += std::string(wrong.empty() ? "" : "; ") + name + " is " + number(double(*stated), 8) + ", not " + number(format, 8);
  };
  compare(layout::kLowpassOrderAttr, r.lowpass_order, dataset::kLowpassOrder);
  compare(layout::kLowpassCutoffAttr, r.lowpass_cutoff_hz, dataset::kLowpassCutoffHz);
  compare(layout::kAccelReductionWindow, r.reduction_window, double(signal::kDft321Frames.window));
  compare(layout::kAccelReductionHop, r.reduction_hop, double(signal::kDft321Frames.hop));
  if (!wrong.empty()) tally.fail(r.path, wrong);
  else if (!missing.empty()) tally.skip(r.path + ": no readable " + missing);  // layout.required and layout.dtype say why
  else tally.pass();
}

}  // namespace haptex::qa
