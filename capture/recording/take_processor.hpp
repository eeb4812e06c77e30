#pragma once
// Everything the recorder does with a frame after the capture thread handed it over: drop the
// warm-up frames, average the no-contact reference, score each frame (reduced-size decoding), cut
// the take into presses live, and write one press file per press, starting pre_frames before the
// contact (a ring buffer holds them) and ending post_frames after the release.
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "capture/device/drop_counter.hpp"
#include "capture/device/frame.hpp"
#include "capture/recording/press_file_writer.hpp"
#include "capture/recording/session_manifest.hpp"
#include "capture/scoring/contact_score.hpp"
#include "capture/scoring/press_segmenter.hpp"
#include "core/progress.hpp"

namespace haptex::capture {

struct RecorderOptions {
  std::string material;
  int presses = 5;             // the take ends after this many presses
  double seconds = 0;          // and after this long (0: no limit)
  int warmup_frames = 10;      // discarded after stream start (black and settling frames)
  int reference_frames = 10;   // averaged into the no-contact reference
  int calibration_frames = 0;  // then set the thresholds (ContactReference::from_calibration; 0: the reference's own)
  int pre_frames = 10;         // kept before each contact
  int post_frames = 10;        // kept after each release
  double stall_seconds = 2.0;  // no frame for this long ends the take
  SegmenterSettings segmenter;  // trigger and release come from the reference
};

// A frame as the processing thread gets it, with the stream's counters when it was dequeued.
struct TakeFrame {
  Frame frame;
  std::int64_t take_index = 0;      // 0 = the first frame after stream start
  std::uint64_t error_buffers = 0;  // so far in the take
  std::uint64_t poll_timeouts = 0;
};

class TakeProcessor {
 public:
  TakeProcessor(const SessionDescription& session, std::string output_dir, const RecorderOptions& options,
                Progress progress);
  ~TakeProcessor();
  void process(TakeFrame&& frame);  // ignores frames once enough presses are saved
  // Closes an open press file (its ended_by says why) and writes the final manifest.
  void end_of_take(const std::string& ended_by, const TakeTotals& totals, const std::string& error = {});
  bool enough_presses() const { return int(presses_.size()) >= options_.presses; }

  const std::vector<RecordedPress>& presses() const { return presses_; }
  ReferenceSummary reference_summary() const;
  std::uint64_t corrupt_frames() const { return corrupt_frames_; }
  std::string manifest_path() const;

 private:
  struct Scored {
    TakeFrame frame;
    float score;
  };
  cv::Mat scoring(const Frame& frame) const;
  cv::Mat decode_full(const Frame& frame) const;
  void collect_reference(const TakeFrame& frame, const cv::Mat& small);
  void calibrate(const cv::Mat& small);
  void take_reference(const ContactReference& candidate);
  void start_recording();
  void record(TakeFrame&& frame, float score);
  void open_press(const PressInterval& contact);
  void append(const Scored& s);
  void close_press(const std::string& ended_by);
  void write_manifest(const std::string& ended_by, const std::string& error = {});
  TakeTotals running_totals() const;

  SessionDescription session_;
  std::string output_dir_;
  RecorderOptions options_;
  Progress progress_;
  cv::Size size_;
  ScoreSettings score_;  // MJPG is lossy, raw YUYV lossless (score_settings_for)

  // Reference collection.
  std::vector<cv::Mat> reference_small_;
  cv::Mat reference_sum_;  // CV_16UC3: 255 x 250 frames fits
  int reference_restarts_ = 0;
  std::optional<ContactReference> contact_;
  bool reference_taken_ = false;         // the reference frames are in; calibration frames follow
  std::vector<cv::Mat> calibration_small_;
  cv::Mat reference_image_;

  // Recording.
  std::optional<PressSegmenter> segmenter_;
  std::deque<Scored> ring_;
  std::unique_ptr<PressFileWriter> writer_;
  RecordedPress current_;
  int post_left_ = -1;  // frames still to write after the release; -1: in contact or no press open
  std::vector<RecordedPress> presses_;

  std::uint64_t last_errors_ = 0;  // the stream's error count at the last frame written

  DropCounter drops_;
  std::uint64_t frames_ = 0, corrupt_frames_ = 0, error_buffers_ = 0, poll_timeouts_ = 0;
  std::optional<TakeTotals> final_totals_;  // the capture thread's counts, once the take is over
};

}  // namespace haptex::capture
