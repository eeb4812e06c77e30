#include "capture/scoring/press_segmenter.hpp"

#include <algorithm>
#include <cmath>

namespace haptex::capture {

std::optional<PressSegmenter::Event> PressSegmenter::feed(std::int64_t frame, float score) {
  if (std::isnan(score)) return std::nullopt;
  const std::int64_t previous = last_frame_;
  last_frame_ = frame;
  if (state_ == State::press) {
    if (score > press_.peak_score) {
      press_.peak_score = score;
      press_.peak = frame;
    }
    const float excess = score - settings_.level, peak_excess = press_.peak_score - settings_.level;
    if (score < settings_.release || excess < settings_.valley_ratio * peak_excess) {
      state_ = State::idle;
      press_.last = previous;
      valley_ = excess;
      above_ = 0;
      return Event{Event::Kind::ended, press_};
    }
    return std::nullopt;
  }
  valley_ = std::min(valley_, score - settings_.level);
  if (score <= std::max(settings_.trigger, settings_.level + settings_.rearm_ratio * valley_)) {
    above_ = 0;
    return std::nullopt;
  }
  if (above_++ == 0) press_ = PressInterval{frame, frame, frame, score};
  if (score > press_.peak_score) {
    press_.peak_score = score;
    press_.peak = frame;
  }
  if (above_ < settings_.confirm_frames) return std::nullopt;
  state_ = State::press;
  return Event{Event::Kind::started, press_};
}

std::optional<PressInterval> PressSegmenter::finish() {
  if (state_ != State::press) return std::nullopt;
  state_ = State::idle;
  press_.last = last_frame_;
  return press_;
}

std::vector<PressInterval> segment_presses(const std::vector<float>& scores, const SegmenterSettings& settings) {
  PressSegmenter segmenter(settings);
  std::vector<PressInterval> presses;
  for (std::size_t i = 0; i < scores.size(); ++i)
    if (auto e = segmenter.feed(std::int64_t(i), scores[i]); e && e->kind == PressSegmenter::Event::Kind::ended)
      presses.push_back(e->press);
  if (auto open = segmenter.finish()) presses.push_back(*open);
  return presses;
}

}  // namespace haptex::capture
