#include "capture/extraction/peak_frames.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>

#include "capture/scoring/scoring_image.hpp"
#include "core/error.hpp"
#include "core/image_header.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// Sensors send a few black frames right after stream start; a mean this dark is not a gel image.
constexpr double kBlackLevel = 10.0;

// Collects the leading no-contact frames into the reference, scoring them once it is complete.
class LeadingReference {
 public:
  // calibration_frames: no-contact frames after the reference that set the thresholds (inter-frame
  // video, ContactReference::from_calibration), or 0.
  LeadingReference(const ExtractSettings& settings, const ScoreSettings& score, const std::string& path, int calibration_frames)
      : settings_(settings), score_(score), path_(path), calibration_frames_(calibration_frames) {}

  bool complete() const { return done_; }

  // Were the reference frames no contact?
  void require_steady(const ContactReference& contact) const {
    if (contact.steady()) return;
    const std::string why =
        contact.trending()
            ? text::format("they change from the first to the last as a press coming or going does (the first "
                           "half's mean against the second half's scores %.4g, over the no-contact level %.4g)",
                           double(contact.trend()), double(contact.trend_limit()))
            : text::format("two in a row differ from the others' mean by a score of %.4g, over the trigger %.4g",
                           double(contact.worst_reference_score()), double(contact.reference_limit()));
    throw input_error(path_, "frames " + std::to_string(first_) + "-" + std::to_string(indices_.back()),
                      "the first " + std::to_string(settings_.reference_frames) +
                          " frames are not a steady no-contact stretch: " + why,
                      "Start the video with at least " + std::to_string(settings_.reference_frames) +
                          " frames without contact, or give a no-contact image with --reference");
  }
  bool collecting() const { return !done_; }

  void add(std::int64_t index, const cv::Mat& scoring, const cv::Mat& full, SourceScores& out) {
    if (int(small_.size()) < settings_.reference_frames) {
      if (sum_.empty()) sum_ = cv::Mat::zeros(full.size(), CV_16UC3);  // 255 x 250 frames fits
      cv::add(sum_, full, sum_, cv::noArray(), CV_16UC3);
      small_.push_back(scoring);
      indices_.push_back(index);
    } else {
      later_.push_back(scoring);
      later_indices_.push_back(index);
    }
    if (int(small_.size()) == settings_.reference_frames && int(later_.size()) == calibration_frames_) finish(out);
  }

  // At the source's end: a video too short for all its calibration frames uses those it has.
  void require_complete(SourceScores& out) {
    if (!done_ && int(small_.size()) == settings_.reference_frames) finish(out);
    if (!done_)
      throw input_error(path_, "", "only " + std::to_string(small_.size()) + " usable frames; " +
                                       std::to_string(settings_.reference_frames) +
                                       " no-contact frames are needed for the reference and more for a press",
                        "Give a longer video, or a no-contact image with --reference");
  }

 private:
  void finish(SourceScores& out) {
    done_ = true;
    const ContactReference contact = calibration_frames_ > 0 ? ContactReference::from_calibration(small_, later_, score_)
                                                             : ContactReference::from_frames(small_, score_);
    first_ = indices_.front();
    sum_.convertTo(out.reference, CV_8UC3, 1.0 / double(small_.size()));
    out.reference_note = "mean of frames " + std::to_string(indices_.front()) + "-" + std::to_string(indices_.back());
    for (std::size_t i = 0; i < small_.size(); ++i) out.scores[std::size_t(indices_[i])] = contact.score(small_[i]);
    for (std::size_t i = 0; i < later_.size(); ++i) out.scores[std::size_t(later_indices_[i])] = contact.score(later_[i]);
    out.contact = contact;
    small_.clear();
    later_.clear();
    indices_.erase(indices_.begin(), indices_.end() - 1);
  }

  const ExtractSettings& settings_;
  ScoreSettings score_;
  std::string path_;
  cv::Mat sum_;
  int calibration_frames_ = 0;
  std::vector<cv::Mat> small_, later_;
  std::vector<std::int64_t> indices_, later_indices_;
  std::int64_t first_ = 0;
  bool done_ = false;
};

std::optional<ContactReference> given_reference(FrameSource& source, const ExtractSettings& settings, SourceScores& out) {
  if (!settings.reference_image.empty()) {
    if (settings.reference_image.size() != source.frame_size())
      throw input_error(settings.reference_image_path, "",
                        "the reference image is " + std::to_string(settings.reference_image.cols) + "x" +
                            std::to_string(settings.reference_image.rows) + " but the frames of " + source.path() +
                            " are " + std::to_string(source.frame_size().width) + "x" +
                            std::to_string(source.frame_size().height),
                        "Give a no-contact image taken with the same sensor and size");
    out.reference = settings.reference_image;
    out.reference_note = "image " + settings.reference_image_path;
    // A single image shows no noise: the lossy floors apply unless the user set others.
    ScoreSettings floors = score_settings_for(false);
    floors.pixel_threshold = settings.pixel_threshold;
    floors.trigger = settings.trigger;
    return ContactReference::from_image(scoring_image(settings.reference_image), floors);
  }
  if (const auto stored = source.stored_reference()) {
    out.reference = stored->image;
    out.reference_note = "stored in the press file (mean of the session's no-contact frames)";
    return ContactReference(scoring_image(stored->image), stored->noise, stored->pixel_threshold, stored->trigger,
                            stored->level);
  }
  return std::nullopt;
}

// Sum of scores of frames [start, start + count); -inf when one of them did not decode.
double window_total(const std::vector<float>& scores, std::int64_t start, int count) {
  double total = 0;
  for (std::int64_t i = start; i < start + count; ++i) {
    if (std::isnan(scores[std::size_t(i)])) return -std::numeric_limits<double>::infinity();
    total += scores[std::size_t(i)];
  }
  return total;
}

std::vector<std::int64_t> choose_window(const std::vector<float>& scores, std::int64_t peak, std::int64_t lo,
                                        std::int64_t hi, int count) {
  const std::int64_t n = hi - lo + 1;
  if (n < count) {  // the press's range is too short: look in the whole source
    lo = 0;
    hi = std::int64_t(scores.size()) - 1;
  }
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

ScoreSettings score_settings(const FrameSource& source, const ExtractSettings& settings) {
  ScoreSettings s = score_settings_for(source.lossless());
  s.pixel_threshold = settings.pixel_threshold;
  s.trigger = settings.trigger;
  return s;
}

SourceScores score_source(FrameSource& source, const ExtractSettings& settings) {
  SourceScores out;
  const ScoreSettings score = score_settings(source, settings);
  out.contact = given_reference(source, settings, out);
  LeadingReference leading(settings, score, source.path(), source.inter_frame() ? settings.calibration_frames : 0);
  const bool from_leading = !out.contact;
  bool started = false;  // past the black frames sensors send after stream start
  source.scan(
      [&](std::int64_t index, const cv::Mat& scoring, const cv::Mat& full) {
        out.scores.push_back(kNaN);
        if (!scoring.empty() && !started && cv::mean(scoring)[0] < kBlackLevel) {
          ++out.black_frames;
          return;
        }
        started = started || !scoring.empty();
        if (scoring.empty()) {
          ++out.unreadable_frames;
        } else if (!from_leading || leading.complete()) {
          out.scores.back() = out.contact->score(scoring);
        } else {
          leading.add(index, scoring, full, out);
        }
      },
      [&](std::int64_t) { return from_leading && leading.collecting(); });
  if (!from_leading) return out;
  leading.require_complete(out);
  leading.require_steady(*out.contact);
  return out;
}

std::vector<PressPlan> plan_presses(const std::vector<float>& scores, const SegmenterSettings& segmenter,
                                    int frames_per_press, int margin_frames) {
  const std::vector<PressInterval> presses = segment_presses(scores, segmenter);
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
