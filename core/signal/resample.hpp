#pragma once
// Resampling onto haptex's 10 kHz grid without aliasing, as scipy does it (docs/convert.md,
// "Sources at other rates"):
//   - a uniform source: scipy.signal.resample_poly(x, up, down, padtype='mean'), a polyphase FIR
//     whose Kaiser-windowed sinc (beta 5, 10 zero crossings each side) cuts at the lower Nyquist;
//   - an irregular one (time stamps that wander, as the Cluster database's accelerometer logs):
//     numpy.interp onto a uniform grid at the source's nominal rate, then the above.
// padtype 'mean': the signal's mean is taken out before the zero padding and put back after, so a
// force of 2 N does not sag towards 0 over the first and last filter length.
#include <span>
#include <vector>

namespace haptex::signal {

// scipy.signal.firwin(taps, cutoff, window=('kaiser', beta)): a low-pass, cutoff as a fraction of
// Nyquist, scaled to unit gain at 0 Hz; taps odd.
std::vector<double> kaiser_lowpass(int taps, double cutoff, double beta);

// The polyphase filter of scipy.signal.resample_poly: the ratio in lowest terms, and a Kaiser-windowed
// sinc (beta 5, 10 zero crossings a side, 20 max(up, down) + 1 taps) that cuts at the lower Nyquist,
// times up.
struct PolyphaseFilter {
  PolyphaseFilter(int up, int down);  // up, down >= 1
  bool identity() const { return up == 1 && down == 1; }
  // Output k, which lies at input time k down / up: the sum over inputs i of taps[k down + half - i up]
  // (x[i - first] - offset), for the inputs x holds (from index `first` on); the others are 0.
  double output(std::size_t k, std::span<const double> x, std::size_t first, double offset = 0) const;
  std::size_t up = 1, down = 1, half = 0;
  std::vector<double> taps;
};

// scipy.signal.resample_poly(x, up, down, padtype='mean') for every channel at one rate: the filter
// (20 million taps from a 999983 Hz source) is designed once, not per channel.
class PolyResampler {
 public:
  PolyResampler(int up, int down);  // up, down >= 1
  // The output has ceil(x.size() * up / down) samples; the first is at the time of x's first.
  std::vector<double> operator()(std::span<const double> x) const;

 private:
  PolyphaseFilter filter_;
};

// The same filter on a stream that arrives in blocks (a live player's 10 ms frames): output k is
// returned once the input reaches past the filter's right half (half / up input samples later).
// Zeros stand before the stream and, at flush(), after it: on a signal of mean 0 the outputs equal
// PolyResampler's (padtype 'mean' only takes the mean out first).
class StreamResampler {
 public:
  StreamResampler(int up, int down);
  // Appends x; `out` receives the outputs that became complete (cleared first).
  void push(std::span<const double> x, std::vector<double>& out);
  // Ends the stream: the outputs up to ceil(inputs * up / down), as PolyResampler gives them.
  void flush(std::vector<double>& out);
  // Input samples between an input and the first output that can be returned at its time.
  std::size_t delay_inputs() const { return filter_.half / filter_.up + 1; }

 private:
  PolyphaseFilter filter_;
  std::vector<double> input_;  // the inputs from index first_ on (older ones are no longer needed)
  std::size_t first_ = 0, inputs_ = 0, next_ = 0;  // index of input_[0]; inputs seen; next output
};

// PolyResampler(up, down)(x), for one channel.
std::vector<double> resample_poly(std::span<const double> x, int up, int down);

// numpy.interp(start_s + k / grid_hz, times, values) for k = 0 .. count - 1: samples at strictly
// increasing times (seconds) onto a uniform grid (held at the end values outside them, as numpy does).
std::vector<double> interpolate_uniform(std::span<const double> times, std::span<const double> values, double start_s,
                                        double grid_hz, std::size_t count);

}  // namespace haptex::signal
