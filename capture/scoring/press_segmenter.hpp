#pragma once
// Cuts a stream of contact scores into presses, one frame at a time, so the recorder can use it live
// and `capture extract` afterwards with the same result.
//
// A press starts when the score stays above the trigger for two frames in a row (one odd frame is
// not a press). It ends when the score falls below the release level, or its excess over the
// no-contact level below a fifth of the press's own: fingers and indenters often lift without
// leaving the gel quite untouched, and such a valley is still the end of one press. After a press,
// the next one must also rise to twice the valley's excess, so the wobble of a lingering touch does
// not count as new presses. Scores are compared by their excess over the no-contact level
// (ContactReference::level; 0 for a reference whose frames' scores are 0 without contact).
#include <cstdint>
#include <optional>
#include <vector>

namespace haptex::capture {

struct SegmenterSettings {
  float level = 0.0f;  // the score of a no-contact frame
  float trigger = 0.25f;
  float release = 0.125f;
  float valley_ratio = 0.2f;  // end when the excess falls below this share of the press's peak excess
  float rearm_ratio = 2.0f;   // the next press must rise to this multiple of the valley before it
  int confirm_frames = 2;     // consecutive frames above the trigger that start a press
};

struct PressInterval {
  std::int64_t first = 0, last = 0;  // contact frames, inclusive
  std::int64_t peak = 0;             // highest-scoring frame
  float peak_score = 0;
};

class PressSegmenter {
 public:
  explicit PressSegmenter(const SegmenterSettings& settings) : settings_(settings) {}

  struct Event {
    enum class Kind { started, ended } kind;
    PressInterval press;  // for `started`: first frame and the peak so far
  };
  // Frames must come in increasing order. NaN scores (frames that did not decode) are skipped.
  std::optional<Event> feed(std::int64_t frame, float score);
  // Ends a press still open when the stream ends; its last frame is the last one fed.
  std::optional<PressInterval> finish();
  bool in_press() const { return state_ == State::press; }
  const PressInterval& current() const { return press_; }

 private:
  enum class State { idle, press };
  SegmenterSettings settings_;
  State state_ = State::idle;
  PressInterval press_;
  float valley_ = 0;
  int above_ = 0;
  std::int64_t last_frame_ = -1;
};

// The whole sequence at once: scores[i] is frame i.
std::vector<PressInterval> segment_presses(const std::vector<float>& scores, const SegmenterSettings& settings);

}  // namespace haptex::capture
