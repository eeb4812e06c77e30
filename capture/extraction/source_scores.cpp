// Scoring a source's frames against its no-contact reference (docs/capture.md, "The no-contact
// reference"): a given image or a press file's stored reference as they are; otherwise the steady
// no-contact stretch at the start of the video, else the one at its end, else the end of least
// contact. The first case costs one reading of the source; the others read it a second time.
#include <algorithm>
#include <cmath>
#include <limits>

#include "capture/extraction/peak_frames.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "core/error.hpp"
#include "core/text/format.hpp"

namespace haptex::capture {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Usable frames (past the black start-up frames, decoded) and their scoring images.
struct Stretch {
  std::vector<cv::Mat> images;
  std::vector<std::int64_t> indices;
  std::int64_t first() const { return indices.front(); }
  std::int64_t last() const { return indices.back(); }
};

std::string frame_range(std::int64_t first, std::int64_t last) {
  return "frames " + std::to_string(first) + "-" + std::to_string(last);
}

// Why the frames of a reference are not a steady no-contact stretch, with the figure and its limit.
std::string unsteadiness(const ContactReference& contact) {
  return contact.trending()
             ? text::format("they change from the first to the last as a press coming or going does (the first "
                            "half's mean against the second half's scores %.4g, over the no-contact level %.4g)",
                            double(contact.trend()), double(contact.trend_limit()))
             : text::format("two in a row differ from the others' mean by a score of %.4g, over the trigger %.4g",
                            double(contact.worst_reference_score()), double(contact.reference_limit()));
}

// The reference frames at one end (`reference` of them, nearest the end) and, for inter-frame video,
// the calibration frames beyond them (ContactReference::from_calibration).
struct EndFrames {
  Stretch reference, calibration;
};

ContactReference reference_of(const EndFrames& end, const ScoreSettings& settings, bool inter_frame) {
  return inter_frame ? ContactReference::from_calibration(end.reference.images, end.calibration.images, settings)
                     : ContactReference::from_frames(end.reference.images, settings);
}

// The first reading: every usable frame's scoring image passes through here in order. The leading
// frames make the start's reference, which scores the frames after them as they come (the usual
// case needs no second reading); the last frames are kept for the end's reference.
class FirstReading {
 public:
  FirstReading(const ExtractSettings& settings, const ScoreSettings& score, const FrameSource& source)
      : settings_(settings), score_(score), inter_frame_(source.inter_frame()),
        calibration_(source.inter_frame() ? calibration_frames(source.fps()) : 0) {}

  void add(std::int64_t index, const cv::Mat& scoring, const cv::Mat& full, SourceScores& out) {
    ++usable_;
    if (cv::mean(scoring)[0] >= kBlackLevel) {  // a dark end (a sensor unplugged, a fade) is no gel image
      tail_.images.push_back(scoring);
      tail_.indices.push_back(index);
      if (int(tail_.images.size()) > settings_.reference_frames + calibration_) {
        tail_.images.erase(tail_.images.begin());
        tail_.indices.erase(tail_.indices.begin());
      }
    }
    if (start_) {
      out.scores[std::size_t(index)] = start_->score(scoring);
      return;
    }
    if (int(head_.reference.images.size()) < settings_.reference_frames) {
      if (sum_.empty()) sum_ = cv::Mat::zeros(full.size(), CV_16UC3);  // 255 x 250 frames fits
      cv::add(sum_, full, sum_, cv::noArray(), CV_16UC3);
      head_.reference.images.push_back(scoring);
      head_.reference.indices.push_back(index);
    } else {
      head_.calibration.images.push_back(scoring);
      head_.calibration.indices.push_back(index);
    }
    if (int(head_.reference.images.size()) == settings_.reference_frames &&
        int(head_.calibration.images.size()) == calibration_)
      finish_start(out);
  }

  // Whether the source's start is complete enough to score by (a video too short for all its
  // calibration frames uses those it has).
  void finish(const std::string& path, SourceScores& out) {
    if (!start_ && int(head_.reference.images.size()) == settings_.reference_frames) finish_start(out);
    if (start_ && inter_frame_) calibrate_start();
    if (!start_)
      throw input_error(path, "", "only " + std::to_string(usable_) + " usable frames" + unusable(out) + "; " +
                                      std::to_string(settings_.reference_frames) +
                                      " no-contact frames are needed for the reference and more for a press",
                        out.black_frames > 0 && usable_ == 0 ? "Check that the sensor's light was on while it recorded"
                                                             : "Give a longer video, or a no-contact image with --reference");
  }

  // Why the other frames were not usable: dark (a sensor whose light is off) or undecodable.
  static std::string unusable(const SourceScores& out) {
    std::string why;
    if (out.black_frames > 0)
      why += ", " + std::to_string(out.black_frames) + " are black, a mean grey under " + std::to_string(int(kBlackLevel)) + " of 255";
    if (out.unreadable_frames > 0) why += ", " + std::to_string(out.unreadable_frames) + " that do not decode";
    return why.empty() ? why : " (" + why.substr(2) + ")";
  }

  const std::optional<ContactReference>& start() const { return start_; }
  const Stretch& start_frames() const { return head_.reference; }
  const cv::Mat& start_sum() const { return sum_; }

  // The end's frames in the same roles as the start's: the last `reference_frames` usable frames,
  // and the calibration frames before them, nearest first.
  EndFrames end_frames() const {
    EndFrames end;
    const std::size_t n = tail_.images.size(), reference = std::min<std::size_t>(n, std::size_t(settings_.reference_frames));
    end.reference.images.assign(tail_.images.end() - std::ptrdiff_t(reference), tail_.images.end());
    end.reference.indices.assign(tail_.indices.end() - std::ptrdiff_t(reference), tail_.indices.end());
    for (std::size_t k = n - reference; k-- > 0;) {
      end.calibration.images.push_back(tail_.images[k]);
      end.calibration.indices.push_back(tail_.indices[k]);
    }
    return end;
  }

  ContactReference end_reference() const { return reference_of(end_frames(), score_, inter_frame_); }
  // Whether the end has a reference's worth of gel images (dark frames are none).
  bool end_usable() const { return int(tail_.images.size()) >= settings_.reference_frames; }

 private:
  void finish_start(SourceScores& out) {
    start_ = reference_of(head_, score_, inter_frame_);
    for (const Stretch* s : {&head_.reference, &head_.calibration})
      for (std::size_t i = 0; i < s->images.size(); ++i) out.scores[std::size_t(s->indices[i])] = start_->score(s->images[i]);
  }

  // Inter-frame video: the thresholds from the frames after the start's reference and the last
  // frames of the video together, the quiet ones among them (ContactReference::from_calibration): a
  // short clip pressed right after its first frames still ends untouched. The scores do not change
  // (the per-pixel threshold is 0 unless the user set one), nor does the verdict on the reference's
  // steadiness (judged by the frames right after it); only the level, the jitter and the trigger.
  void calibrate_start() {
    EndFrames pool = head_;
    const std::int64_t after = pool.calibration.indices.empty() ? pool.reference.last() : pool.calibration.last();
    for (std::size_t i = 0; i < tail_.images.size(); ++i)
      if (tail_.indices[i] > after) {
        pool.calibration.images.push_back(tail_.images[i]);
        pool.calibration.indices.push_back(tail_.indices[i]);
      }
    // A contact held over the second after the reference holds at the end too, as a rule: the
    // reference's own level stands (ContactReference::held_contact).
    if (!start_->held_contact()) start_->take_thresholds(reference_of(pool, score_, true));
  }

  const ExtractSettings& settings_;
  ScoreSettings score_;
  bool inter_frame_;
  int calibration_;
  std::int64_t usable_ = 0;
  EndFrames head_;
  Stretch tail_;
  cv::Mat sum_;
  std::optional<ContactReference> start_;
};

// The median score of the end's reference frames when they are a steady stretch, else NaN.
float settled_end_level(const FirstReading& first, const std::vector<float>& scores) {
  if (!first.end_usable() || !first.end_reference().steady()) return std::numeric_limits<float>::quiet_NaN();
  std::vector<float> end;
  for (std::int64_t i : first.end_frames().reference.indices) end.push_back(scores[std::size_t(i)]);
  std::nth_element(end.begin(), end.begin() + std::ptrdiff_t(end.size() / 2), end.end());
  return end[end.size() / 2];
}

// Drivers may hand over stale buffers when a stream starts: frames of an earlier moment (another
// grasp, another exposure), one image or several, that end in a jump to the live image. The live
// start is the last frame, within the first `within` usable frames, that
// - follows a change of more than twice any change among the `steady` frames from it on (so a
//   reference can be made there) and more than a grey level,
// - ends a jump of one or two frames (a ramp of three or more changes over half the jump is motion:
//   a press eased off), and
// - comes after frames whose image never recurs: the frame before the jump (and the one between, for
//   a jump over two frames) differs from every later frame, its mean aside (the light drifts), by more
//   than half of what it differs from the frames after the jump.
// A press coming on at the start is no such jump: the untouched gel before its onset recurs when it
// is released. One under way at the start and released within a frame or two of the first `within`
// frames would be taken for stale frames; docs/capture.md, "Stale start-up frames", says so.
class StartupJump {
 public:
  StartupJump(int within, int steady) : within_(std::size_t(std::max(within, 0))), steady_(std::size_t(std::max(steady, 1))) {}

  void add(std::int64_t index, const cv::Mat& scoring) {
    if (!indices_.empty() && indices_.size() < within_ + steady_) changes_.push_back(mean_abs(scoring, previous_, false));
    for (std::size_t q = 0; q < early_.size(); ++q)
      if (!early_[q].empty()) distances_[q].push_back(mean_abs(scoring, early_[q], true));
    if (early_.size() < within_) {
      early_.push_back(scoring);
      distances_.emplace_back();
    }
    indices_.push_back(index);
    previous_ = scoring;
    // A frame matters only before a jump into the next frame or the one after it.
    if (const std::size_t n = indices_.size(); n >= 3 && n - 3 < early_.size() &&
                                               std::max(changes_[n - 3], changes_[n - 2]) <= kFactor * kLeast)
      early_[n - 3].release();
  }

  // The index of the first live frame, or -1 when there is no such jump.
  std::int64_t first_live() const {
    std::int64_t live = -1;
    for (std::size_t s = 1; decidable(s); ++s)
      if (steady_after(s) && never_recurs_before(s)) live = indices_[s];
    return live;
  }

 private:
  static constexpr float kFactor = 2.0f, kLeast = 0.5f;
  static constexpr std::size_t kLongestJump = 2;  // changes

  // Mean |a - b| in grey levels; `offset_free`: less the mean of a - b.
  static float mean_abs(const cv::Mat& a, const cv::Mat& b, bool offset_free) {
    if (!offset_free) return float(cv::norm(a, b, cv::NORM_L1) / double(a.total()));
    cv::Mat d;
    cv::subtract(a, b, d, cv::noArray(), CV_32F);
    d -= cv::mean(d)[0];
    return float(cv::norm(d, cv::NORM_L1) / double(d.total()));
  }
  // Short videos judge a jump by the frames they have after it.
  std::size_t window_end(std::size_t s) const { return std::min(s + steady_, indices_.size()); }
  bool decidable(std::size_t s) const { return s < within_ && s + 1 < indices_.size(); }
  // changes_[k] is between usable frames k and k + 1; the jump into frame s is changes_[s - 1].
  bool steady_after(std::size_t s) const {
    const float jump = changes_[s - 1];
    const auto from = changes_.begin() + std::ptrdiff_t(s), to = changes_.begin() + std::ptrdiff_t(window_end(s) - 1);
    return jump > kFactor * std::max(kLeast, *std::max_element(from, to)) && s - ramp_start(s) <= kLongestJump;
  }
  // The first frame of the ramp the jump into frame s ends (s - 1 for a jump alone).
  std::size_t ramp_start(std::size_t s) const {
    std::size_t first = s - 1;
    while (first > 0 && changes_[first - 1] >= changes_[s - 1] / kFactor) --first;
    return first;
  }
  bool never_recurs_before(std::size_t s) const {
    for (std::size_t q = ramp_start(s); q < s; ++q) {
      // distances_[q][p - q - 1] is between usable frames q and p
      const auto after = distances_[q].begin() + std::ptrdiff_t(s - q - 1);
      const float apart = *std::max_element(after, distances_[q].begin() + std::ptrdiff_t(window_end(s) - q - 1));
      if (*std::min_element(after, distances_[q].end()) <= apart / kFactor) return false;
    }
    return true;
  }

  std::size_t within_, steady_;
  std::vector<cv::Mat> early_;                 // the first `within` usable frames (released when no jump follows)
  std::vector<std::vector<float>> distances_;  // from each of them to every later frame, offset-free
  std::vector<float> changes_;                 // between consecutive frames, over the first within + steady
  std::vector<std::int64_t> indices_;
  cv::Mat previous_;
};

// Reads the source again, scoring every usable frame against each reference, and hands over the full
// frames `wanted` asks for.
std::vector<std::vector<float>> score_again(FrameSource& source, const std::vector<float>& first_scores,
                                            const std::vector<const ContactReference*>& references,
                                            const std::function<bool(std::int64_t)>& wanted,
                                            const std::function<void(std::int64_t, const cv::Mat&)>& take) {
  std::vector<std::vector<float>> scores(references.size(), std::vector<float>(first_scores.size(), kNaN));
  source.scan(
      [&](std::int64_t index, const cv::Mat& scoring, const cv::Mat& full) {
        if (std::size_t(index) >= first_scores.size() || std::isnan(first_scores[std::size_t(index)]) || scoring.empty()) return;
        for (std::size_t r = 0; r < references.size(); ++r) scores[r][std::size_t(index)] = references[r]->score(scoring);
        if (wanted(index)) take(index, full);
      },
      wanted);
  return scores;
}

// A single given image shows no noise: the lossy floors apply unless the user set others.
ScoreSettings image_floors(const ExtractSettings& settings) {
  ScoreSettings floors = score_settings_for(false);
  floors.pixel_threshold = settings.pixel_threshold;
  floors.trigger = settings.trigger;
  return floors;
}

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
    out.reference_kind = ReferenceKind::image;
    out.reference_note = "image " + settings.reference_image_path;
    return ContactReference::from_image(scoring_image(settings.reference_image), image_floors(settings));
  }
  if (const auto stored = source.stored_reference()) {
    out.reference = stored->image;
    out.reference_kind = ReferenceKind::press_file;
    out.reference_note = "stored in the press file (mean of the session's no-contact frames)";
    return ContactReference(scoring_image(stored->image), stored->noise, stored->pixel_threshold, stored->trigger,
                            stored->level);
  }
  return std::nullopt;
}

// The end's stretch, when the start is not steady: the source is read again against it.
// The full frames of a stretch summed on the second reading, into its mean. Every one of them decoded on
// the first reading; one that does not on the second (a file changed or damaged meanwhile) is refused.
class StretchSum {
 public:
  StretchSum(const std::string& path, const Stretch& stretch) : path_(path), stretch_(stretch) {}
  bool wanted(std::int64_t i) const {
    return std::find(stretch_.indices.begin(), stretch_.indices.end(), i) != stretch_.indices.end();
  }
  void add(const cv::Mat& full) {
    if (full.empty()) return;
    if (sum_.empty()) sum_ = cv::Mat::zeros(full.size(), CV_16UC3);
    cv::add(sum_, full, sum_, cv::noArray(), CV_16UC3);
    ++added_;
  }
  cv::Mat mean() const {
    if (added_ != stretch_.indices.size())
      throw input_error(path_, frame_range(stretch_.first(), stretch_.last()),
                        "decoded differently on the second reading (" + std::to_string(added_) + " of " +
                            std::to_string(stretch_.indices.size()) + " reference frames)",
                        "The file may have changed or be damaged; copy it again, or give a no-contact image with --reference");
    cv::Mat mean;
    sum_.convertTo(mean, CV_8UC3, 1.0 / double(added_));
    return mean;
  }

 private:
  std::string path_;
  const Stretch& stretch_;
  cv::Mat sum_;
  std::size_t added_ = 0;
};

void use_end(FrameSource& source, const FirstReading& first, ContactReference end, const std::string& why_not_start,
             SourceScores& out) {
  const Stretch stretch = first.end_frames().reference;
  StretchSum sum(source.path(), stretch);
  out.scores = score_again(source, out.scores, {&end}, [&](std::int64_t i) { return sum.wanted(i); },
                           [&](std::int64_t, const cv::Mat& full) { sum.add(full); })[0];
  out.reference = sum.mean();
  out.contact = std::move(end);
  out.reference_kind = ReferenceKind::end;
  out.reference_first = stretch.first(), out.reference_last = stretch.last();
  out.reference_note = "mean of " + frame_range(stretch.first(), stretch.last()) + ", the video's end (its start, " +
                       frame_range(first.start_frames().first(), first.start_frames().last()) +
                       ", is not a steady no-contact stretch: " + why_not_start + ")";
}

// Neither end is steady: of the start's and the end's reference frames, those farther from the
// source's strongest contact (its highest score against them is the larger) are the no-contact
// reference, with the thresholds their own scores give (raised by their unsteadiness: a cautious
// trigger). The source is read again to score against both.
void use_least_contact(FrameSource& source, const FirstReading& first, ContactReference end, SourceScores& out) {
  const Stretch& start_frames = first.start_frames();
  const Stretch end_frames = first.end_frames().reference;
  const ContactReference& start = *first.start();
  StretchSum end_sum(source.path(), end_frames);
  auto scores = score_again(source, out.scores, {&start, &end}, [&](std::int64_t i) { return end_sum.wanted(i); },
                            [&](std::int64_t, const cv::Mat& full) { end_sum.add(full); });
  const auto highest = [](const std::vector<float>& v) {
    float h = 0;
    for (float x : v) h = std::isnan(x) ? h : std::max(h, x);
    return h;
  };
  const bool at_end = highest(scores[1]) > highest(scores[0]);
  const Stretch& chosen = at_end ? end_frames : start_frames;
  if (at_end) out.reference = end_sum.mean();
  else first.start_sum().convertTo(out.reference, CV_8UC3, 1.0 / double(chosen.indices.size()));
  out.scores = std::move(scores[at_end ? 1 : 0]);
  out.contact = at_end ? std::move(end) : start;
  out.reference_kind = ReferenceKind::least_contact;
  out.reference_first = chosen.first(), out.reference_last = chosen.last();
  out.reference_note = "mean of " + frame_range(chosen.first(), chosen.last()) + ", the video's " +
                       (at_end ? "end" : "start") +
                       ", the end of least contact (neither end is a steady no-contact stretch)";
}

}  // namespace

const char* reference_kind_name(ReferenceKind kind) {
  switch (kind) {
    case ReferenceKind::start: return "start";
    case ReferenceKind::end: return "end";
    case ReferenceKind::least_contact: return "least contact";
    case ReferenceKind::image: return "image";
    case ReferenceKind::press_file: return "press file";
  }
  return "";
}

ScoreSettings score_settings(const FrameSource& source, const ExtractSettings& settings) {
  ScoreSettings s = score_settings_for(source.lossless());
  s.pixel_threshold = settings.pixel_threshold;
  s.trigger = settings.trigger;
  return s;
}

namespace {

// score_source with the frames before `first_live` taken as start-up frames.
SourceScores score_from(FrameSource& source, const ExtractSettings& settings, std::int64_t first_live) {
  SourceScores out;
  const ScoreSettings score = score_settings(source, settings);
  out.contact = given_reference(source, settings, out);
  FirstReading first(settings, score, source);
  StartupJump jump(settings.reference_frames, settings.reference_frames);
  bool started = false;  // past the black frames sensors send after stream start
  source.scan(
      [&](std::int64_t index, const cv::Mat& scoring, const cv::Mat& full) {
        out.scores.push_back(kNaN);
        if (index < first_live) {
          ++out.stale_frames;
          return;
        }
        if (!scoring.empty() && !started && cv::mean(scoring)[0] < kBlackLevel) {
          ++out.black_frames;
          return;
        }
        started = started || !scoring.empty();
        if (scoring.empty()) {
          ++out.unreadable_frames;
        } else if (out.contact) {
          out.scores.back() = out.contact->score(scoring);
        } else {
          jump.add(index, scoring);
          first.add(index, scoring, full, out);
        }
      },
      [&](std::int64_t) { return !out.contact && !first.start(); });
  if (out.contact) return out;
  if (first_live == 0)
    if (const std::int64_t live = jump.first_live(); live > 0) return score_from(source, settings, live);
  first.finish(source.path(), out);
  const ContactReference& start = *first.start();
  if (start.steady() || !first.end_usable()) {
    const Stretch& s = first.start_frames();
    first.start_sum().convertTo(out.reference, CV_8UC3, 1.0 / double(s.indices.size()));
    out.contact = start;
    out.reference_kind = ReferenceKind::start;
    out.reference_first = s.first(), out.reference_last = s.last();
    out.reference_note = "mean of " + frame_range(s.first(), s.last());
    if (!start.steady())
      out.reference_note += " (not a steady no-contact stretch: " + unsteadiness(start) +
                            "; the end has too few frames bright enough to be gel images to take instead)";
    out.end_level = settled_end_level(first, out.scores);
  } else {
    ContactReference end = first.end_reference();
    if (end.steady()) use_end(source, first, std::move(end), unsteadiness(start), out);
    else use_least_contact(source, first, std::move(end), out);
  }
  if (out.contact->held_contact())
    out.reference_note += "; the frames after it hold a steady contact (a grasp from the first second), so the "
                          "level is the reference frames' own";
  if (first_live > 0)
    out.reference_note += first_live == 1 ? "; frame 0 is a stale start-up frame (a jump to a steady image follows it, and "
                                            "its image never recurs)"
                                          : "; frames 0-" + std::to_string(first_live - 1) +
                                                " are stale start-up frames (a jump to a steady image follows them, and their "
                                                "images never recur)";
  return out;
}

}  // namespace

SourceScores score_source(FrameSource& source, const ExtractSettings& settings) { return score_from(source, settings, 0); }

}  // namespace haptex::capture
