#include "capture/extraction/peak_frames.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/image_header.hpp"

namespace haptex::capture {
namespace {

// Sum of scores of frames [start, start + count); -inf when one of them did not decode.
double window_total(const std::vector<float>& scores, std::int64_t start, int count) {
  double total = 0;
  for (std::int64_t i = start; i < start + count; ++i) {
    if (std::isnan(scores[std::size_t(i)])) return -std::numeric_limits<double>::infinity();
    total += scores[std::size_t(i)];
  }
  return total;
}

// Whether some run of `count` frames in [lo, hi] holding the peak decoded whole.
bool decodable_window(const std::vector<float>& scores, std::int64_t peak, std::int64_t lo, std::int64_t hi, std::int64_t count) {
  for (std::int64_t s = std::max(lo, peak - count + 1); s <= std::min(peak, hi - count + 1); ++s)
    if (std::isfinite(window_total(scores, s, int(count)))) return true;
  return false;
}

// The kept frames: empty when no run of `count` decoded frames holds the peak.
std::vector<std::int64_t> choose_window(const std::vector<float>& scores, std::int64_t peak, std::int64_t lo,
                                        std::int64_t hi, int count) {
  const std::int64_t n = hi - lo + 1;
  if (n < count || !decodable_window(scores, peak, lo, hi, count)) {  // look in the whole source
    lo = 0;
    hi = std::int64_t(scores.size()) - 1;
  }
  if (!decodable_window(scores, peak, lo, hi, std::min<std::int64_t>(count, hi - lo + 1))) return {};
  count = int(std::min<std::int64_t>(count, hi - lo + 1));
  std::int64_t best = std::clamp<std::int64_t>(peak - count / 2, lo, hi - count + 1);
  double best_total = window_total(scores, best, count);
  for (std::int64_t s = std::max(lo, peak - count + 1); s <= std::min(peak, hi - count + 1); ++s) {
    const double total = window_total(scores, s, count);
    const auto off_centre = [&](std::int64_t start) { return std::abs(2 * (peak - start) - (count - 1)); };
    if (total > best_total || (total == best_total && off_centre(s) < off_centre(best))) {
      best = s;
      best_total = total;
    }
  }
  std::vector<std::int64_t> window(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) window[std::size_t(i)] = best + i;
  return window;
}

}  // namespace

namespace {

// Drops the last press when it is the video's settled end (plan_presses): it lasts to the last scored
// frame, hovers at the trigger (its peak within twice the trigger's margin over the level, and within
// one margin of the end's level), and the end is less than half as far from the level as the
// strongest press. A press a person sees stands higher, and one in the middle of a video is never
// the settled end.
std::vector<PressInterval> without_settled_end(std::vector<PressInterval> presses, const std::vector<float>& scores,
                                               const SegmenterSettings& s, float end_level) {
  if (std::isnan(end_level) || presses.empty()) return presses;
  std::int64_t last_scored = std::int64_t(scores.size()) - 1;
  while (last_scored >= 0 && std::isnan(scores[std::size_t(last_scored)])) --last_scored;
  float strongest = s.level;
  for (const auto& p : presses) strongest = std::max(strongest, p.peak_score);
  const PressInterval& last = presses.back();
  const float margin = s.trigger - s.level;
  if (last.last == last_scored && last.peak_score <= s.level + 2 * margin && last.peak_score <= end_level + margin &&
      end_level - s.level < 0.5f * (strongest - s.level))
    presses.pop_back();
  return presses;
}

}  // namespace

std::vector<PressPlan> plan_presses(const std::vector<float>& scores, const SegmenterSettings& segmenter,
                                    int frames_per_press, int margin_frames, float end_level, int* left_out) {
  if (left_out) *left_out = 0;
  const std::vector<PressInterval> presses = without_settled_end(segment_presses(scores, segmenter), scores, segmenter, end_level);
  const std::int64_t last_frame = std::int64_t(scores.size()) - 1;
  std::vector<PressPlan> plans;
  for (std::size_t k = 0; k < presses.size(); ++k) {
    PressPlan plan;
    plan.press_in_source = int(k);
    plan.contact = presses[k];
    // Frames between two presses are shared out at the midpoint, so no frame belongs to two presses.
    plan.range_first = std::max<std::int64_t>(presses[k].first - margin_frames,
                                              k ? (presses[k - 1].last + presses[k].first) / 2 + 1 : 0);
    plan.range_last = std::min<std::int64_t>(presses[k].last + margin_frames,
                                             k + 1 < presses.size() ? (presses[k].last + presses[k + 1].first) / 2 : last_frame);
    plan.frame_indices = choose_window(scores, presses[k].peak, plan.range_first, plan.range_last, frames_per_press);
    if (plan.frame_indices.empty()) {  // frames that do not decode around the peak: the press is left out, and said to be
      if (left_out) ++*left_out;
      continue;
    }
    plan.range_first = std::min(plan.range_first, plan.frame_indices.front());
    plan.range_last = std::max(plan.range_last, plan.frame_indices.back());
    plans.push_back(std::move(plan));
  }
  return plans;
}

void read_press_frames(FrameSource& source, const std::vector<PressPlan>& plans, const PressFramesHandler& handle) {
  std::vector<std::int64_t> wanted;
  for (const auto& p : plans) wanted.insert(wanted.end(), p.frame_indices.begin(), p.frame_indices.end());
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());

  std::map<std::int64_t, std::pair<cv::Mat, dataset::EncodedImage>> held;
  std::size_t next_press = 0;
  source.read(wanted, [&](std::int64_t index, const cv::Mat& frame, const dataset::EncodedImage& encoded) {
    held[index] = {frame.clone(), encoded};
    while (next_press < plans.size() && plans[next_press].frame_indices.back() <= index) {
      const PressPlan& plan = plans[next_press++];
      PressFrames press;
      // The source's bytes are kept when every frame has them, all in one encoding (a folder may mix
      // PNG and JPEG files); else the frames are stored as PNG.
      const std::string encoding = image_format(held.at(plan.frame_indices.front()).second);
      bool all_encoded = !encoding.empty();
      for (std::int64_t i : plan.frame_indices) {
        press.frames.push_back(held.at(i).first);
        press.frames_encoded.push_back(held.at(i).second);
        all_encoded = all_encoded && image_format(held.at(i).second) == encoding;
      }
      press.peak = held.at(plan.contact.peak).first;
      if (all_encoded) press.peak_encoded = held.at(plan.contact.peak).second;
      else press.frames_encoded.clear();
      handle(plan, std::move(press));
      // Frames no later press needs are released at once: memory holds about one press.
      const std::int64_t keep_from = next_press < plans.size() ? plans[next_press].frame_indices.front() : index + 1;
      held.erase(held.begin(), held.lower_bound(keep_from));
    }
  });
}

}  // namespace haptex::capture
