// filter.*: the low-passed force and speed hold (almost) nothing above 40 Hz; the raw ones still do.
#include <cmath>
#include <sstream>

#include "qa/band_power.hpp"
#include "qa/checkers.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {
namespace {

std::string scientific(double value) {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific << value;
  return out.str();
}

}  // namespace

FilterChecks::FilterChecks() : lowpass_("filter.lowpass", "low-passed signals"), raw_("filter.raw", "raw signals") {}

void FilterChecks::add(const LoadedRecording& r) {
  const double rate = r.analysis_rate();
  const double nyquist = rate / 2;
  for (const auto& [raw_name, lp_name] : {std::pair{"force_normal", "force_normal_lp"}, std::pair{"speed", "speed_lp"}}) {
    const Signal& raw = r.signals.at(raw_name);
    const Signal& lp = r.signals.at(lp_name);
    if (lp.ok()) {
      const BandPower p = band_power(lp.values, rate, kFilterCheckHz, nyquist);
      if (std::isfinite(p.total)) highest_lowpass_share_ = std::max(highest_lowpass_share_, p.share());
      if (!std::isfinite(p.total)) lowpass_.skip(r.path + "/" + lp_name + " is not finite");
      else if (p.total > 0 && p.share() > kLowpassMaxShare)
        lowpass_.fail(r.path + "/" + lp_name, scientific(p.share()) + " of its power lies above 40 Hz (at most " +
                                                  scientific(kLowpassMaxShare) + " after a 20 Hz low-pass)");
      else lowpass_.pass();
    } else {
      lowpass_.skip(r.path + "/" + lp_name + " " + lp.problem);
    }
    if (raw.ok()) {
      const BandPower p = band_power(raw.values, rate, kFilterCheckHz, nyquist);
      if (std::isfinite(p.total)) lowest_raw_share_ = std::min(lowest_raw_share_, p.share());
      if (!std::isfinite(p.total)) raw_.skip(r.path + "/" + raw_name + " is not finite");
      else if (p.share() < kRawMinShare)
        raw_.fail(r.path + "/" + raw_name, "only " + scientific(p.share()) +
                                               " of its power lies above 40 Hz: it looks low-passed (a measured signal "
                                               "keeps at least " + scientific(kRawMinShare) + ")");
      else raw_.pass();
    } else {
      raw_.skip(r.path + "/" + raw_name + " " + raw.problem);
    }
  }
}

std::vector<CheckResult> FilterChecks::results() const {
  CheckTally lowpass = lowpass_, raw = raw_;
  lowpass.set_pass_message("at most " + scientific(highest_lowpass_share_) + " of a low-passed signal's power above 40 Hz");
  raw.set_pass_message("at least " + scientific(lowest_raw_share_) + " of a raw signal's power above 40 Hz");
  return {lowpass.result(), raw.result()};
}

}  // namespace haptex::qa
