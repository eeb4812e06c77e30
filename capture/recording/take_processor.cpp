#include "capture/recording/take_processor.hpp"

#include <linux/videodev2.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/scoring/scoring_image.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"
#include "dataset/decode_image.hpp"

namespace haptex::capture {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kBlackLevel = 10.0;      // a frame this dark is a start-up frame, not the gel
constexpr int kMaxReferenceRestarts = 20;  // about 20 x 10 frames: several seconds of a moving image

}  // namespace

TakeProcessor::TakeProcessor(const SessionDescription& session, std::string output_dir, const RecorderOptions& options,
                             Progress progress)
    : session_(session),
      output_dir_(std::move(output_dir)),
      options_(options),
      progress_(std::move(progress)),
      size_(int(session.format.width), int(session.format.height)),
      score_(score_settings_for(session.format.fourcc != V4L2_PIX_FMT_MJPEG)),
      drops_(session.format.period_ns()) {}

TakeProcessor::~TakeProcessor() = default;

std::string TakeProcessor::manifest_path() const { return (std::filesystem::path(output_dir_) / "session.json").string(); }

cv::Mat TakeProcessor::scoring(const Frame& frame) const {
  if (session_.format.fourcc == V4L2_PIX_FMT_MJPEG) return scoring_image_from_jpeg(frame.bytes, size_);
  return scoring_image_from_yuyv(frame.bytes, size_);
}

cv::Mat TakeProcessor::decode_full(const Frame& frame) const {
  cv::Mat bgr;
  if (session_.format.fourcc == V4L2_PIX_FMT_MJPEG) {
    bgr = dataset::decode_jpeg(frame.bytes);  // empty when cut off
  } else if (frame.bytes.size() == std::size_t(size_.area()) * 2) {
    const cv::Mat yuyv(size_, CV_8UC2, const_cast<std::uint8_t*>(frame.bytes.data()));
    cv::cvtColor(yuyv, bgr, cv::COLOR_YUV2BGR_YUYV);
  }
  return bgr.size() == size_ ? bgr : cv::Mat();
}

void TakeProcessor::process(TakeFrame&& frame) {
  if (enough_presses()) return;
  ++frames_;
  drops_.observe(frame.frame.sequence, frame.frame.timestamp_ns, frame.error_buffers - error_buffers_);
  error_buffers_ = frame.error_buffers;
  poll_timeouts_ = frame.poll_timeouts;
  if (frame.take_index < options_.warmup_frames) return;
  const cv::Mat small = scoring(frame.frame);
  if (small.empty()) ++corrupt_frames_;
  if (!contact_) {
    if (small.empty()) return;
    if (reference_taken_) return calibrate(small);
    return collect_reference(frame, small);
  }
  record(std::move(frame), small.empty() ? kNaN : contact_->score(small));
}

// Averages reference_frames decodable, non-black frames; if they were not steady (the user touched
// the sensor), starts again.
void TakeProcessor::collect_reference(const TakeFrame& frame, const cv::Mat& small) {
  if (cv::mean(small)[0] < kBlackLevel) return;
  const cv::Mat full = decode_full(frame.frame);
  if (full.empty()) return;
  if (reference_sum_.empty()) reference_sum_ = cv::Mat::zeros(size_, CV_16UC3);
  cv::add(reference_sum_, full, reference_sum_, cv::noArray(), CV_16UC3);
  reference_small_.push_back(small);
  if (int(reference_small_.size()) < options_.reference_frames) return;

  reference_sum_.convertTo(reference_image_, CV_8UC3, 1.0 / double(reference_small_.size()));
  reference_sum_.release();
  // With calibration frames to come, the thresholds (and steadiness) wait for them.
  reference_taken_ = true;
  if (options_.calibration_frames == 0) take_reference(ContactReference::from_frames(reference_small_, score_));
}

// Decodable frames after the reference, until there are calibration_frames of them.
void TakeProcessor::calibrate(const cv::Mat& small) {
  calibration_small_.push_back(small);
  if (int(calibration_small_.size()) == options_.calibration_frames)
    take_reference(ContactReference::from_calibration(reference_small_, calibration_small_, score_));
}

// The reference if it was steady, else (the user touched the sensor) a new one from the next frames.
void TakeProcessor::take_reference(const ContactReference& candidate) {
  reference_small_.clear();
  calibration_small_.clear();
  reference_taken_ = false;
  if (candidate.steady()) {
    contact_ = candidate;
    return start_recording();
  }
  if (++reference_restarts_ > kMaxReferenceRestarts)
    throw failure(session_.identity.path + ": the sensor image did not settle into a steady no-contact reference; "
                  "keep the sensor untouched for the first seconds of the take");
}

void TakeProcessor::start_recording() {
  segmenter_.emplace(contact_->segmenter(options_.segmenter));
  if (progress_) progress_(0, std::size_t(options_.presses), "reference taken; press the sensor");
}

void TakeProcessor::record(TakeFrame&& frame, float score) {
  const std::int64_t index = frame.take_index;
  Scored scored{std::move(frame), score};
  const auto event = segmenter_->feed(index, score);
  if (event && event->kind == PressSegmenter::Event::Kind::started) {
    if (writer_) close_press("release");  // a new press cuts the previous one's tail short
    open_press(event->press);
  }
  if (writer_) append(scored);
  if (event && event->kind == PressSegmenter::Event::Kind::ended && writer_) {
    current_.contact_last = event->press.last;
    current_.peak_frame = event->press.peak;
    post_left_ = options_.post_frames;
  } else if (writer_ && post_left_ > 0) {
    --post_left_;
  }
  if (writer_ && post_left_ == 0) close_press("release");
  ring_.push_back(std::move(scored));
  const std::size_t capacity = std::size_t(options_.pre_frames + options_.segmenter.confirm_frames);
  while (ring_.size() > capacity) ring_.pop_front();
}

void TakeProcessor::open_press(const PressInterval& contact) {
  const int j = int(presses_.size());
  current_ = RecordedPress{};
  current_.index = j;
  current_.file = "press_" + std::to_string(j) + ".h5";
  current_.contact_first = contact.first;
  current_.peak_frame = contact.peak;
  post_left_ = -1;
  dataset::PressFileHeader info = press_file_header(session_.format.fourcc, size_.width, size_.height);
  info.material = session_.material;
  info.press_index = j;
  info.device = session_.identity.path;
  info.card = session_.identity.card;
  info.driver = session_.identity.driver;
  info.bus_info = session_.identity.bus_info;
  info.serial = session_.serial;
  info.fps = session_.format.fps();
  info.requested_fps = session_.format.requested_fps;
  info.locked_controls = locked_controls_json(session_.controls);
  info.missing_controls = missing_controls_json(session_.controls);
  info.noise = contact_->noise();
  info.pixel_threshold = contact_->pixel_threshold();
  info.trigger = contact_->trigger();
  info.level = contact_->level();
  info.provenance = session_.command;
  writer_ = std::make_unique<PressFileWriter>((std::filesystem::path(output_dir_) / current_.file).string(), info,
                                              reference_image_);
  // The frames before the contact: the ring buffer's (pre_frames before the first contact frame,
  // and the contact frames that confirmed the press).
  const std::int64_t from = contact.first - options_.pre_frames;
  for (const Scored& s : ring_)
    if (s.frame.take_index >= from) append(s);
  if (progress_) progress_(std::size_t(j), std::size_t(options_.presses), "press " + std::to_string(j) + ": contact");
}

void TakeProcessor::append(const Scored& s) {
  if (writer_->frames() == 0) {
    current_.take_first_frame = s.frame.take_index;
    current_.first_sequence = s.frame.frame.sequence;
  } else if (s.frame.take_index <= current_.take_last_frame) {
    return;  // already in the file
  }
  const std::uint64_t errors = s.frame.error_buffers - (writer_->frames() ? last_errors_ : s.frame.error_buffers);
  writer_->append(s.frame.frame, s.score, errors);
  last_errors_ = s.frame.error_buffers;
  current_.take_last_frame = s.frame.take_index;
  current_.last_sequence = s.frame.frame.sequence;
}

void TakeProcessor::close_press(const std::string& ended_by) {
  const std::int64_t base = current_.take_first_frame;
  const auto relative = [&](std::int64_t take_frame) { return take_frame < 0 ? -1 : take_frame - base; };
  if (current_.contact_last < 0 && segmenter_->in_press()) {  // the take ended during contact
    current_.contact_last = current_.take_last_frame;
    current_.peak_frame = segmenter_->current().peak;
  }
  writer_->mark_contact(relative(current_.contact_first), relative(current_.contact_last), relative(current_.peak_frame));
  const PressFileSummary summary = writer_->finish(ended_by);
  writer_.reset();
  post_left_ = -1;
  current_.frames = summary.frames;
  current_.dropped_frames = summary.dropped_frames;
  current_.error_frames = summary.error_frames;
  current_.corrupt_frames = summary.corrupt_frames;
  current_.ended_by = ended_by;
  current_.sha256 = sha256_file((std::filesystem::path(output_dir_) / current_.file).string());
  presses_.push_back(current_);
  write_manifest("recording");
  if (progress_)
    progress_(presses_.size(), std::size_t(options_.presses), "press " + std::to_string(current_.index) + " saved");
}

TakeTotals TakeProcessor::running_totals() const {
  TakeTotals t;
  t.frames = frames_;
  t.dropped_frames = drops_.dropped();
  t.error_buffers = error_buffers_;
  t.corrupt_frames = corrupt_frames_;
  t.poll_timeouts = poll_timeouts_;
  return t;
}

void TakeProcessor::write_manifest(const std::string& ended_by, const std::string& error) {
  const TakeTotals totals = final_totals_ ? *final_totals_ : running_totals();
  write_session_manifest(manifest_path(), session_manifest(session_, reference_summary(), presses_, totals, ended_by, error));
}

ReferenceSummary TakeProcessor::reference_summary() const {
  if (!contact_) return {.restarts = reference_restarts_};
  return {contact_->noise(), contact_->pixel_threshold(), contact_->level(), contact_->trigger(), contact_->release(),
          reference_restarts_};
}

void TakeProcessor::end_of_take(const std::string& ended_by, const TakeTotals& totals, const std::string& error) {
  if (writer_ && ended_by == "error") {
    // The fault that ended the take (a full disk) may fail this press too: its partial file then goes,
    // and the space with it, so the manifest can still say what ended the take (review 4, #14).
    try {
      close_press("end of take");
    } catch (const std::exception&) {
      writer_.reset();
    }
  } else if (writer_) {
    // A press cut off by the end of the take keeps every frame taken; its ended_by says why.
    const bool released = post_left_ >= 0;
    close_press(released ? "release" : ended_by == "presses" ? "end of take" : ended_by);
  }
  final_totals_ = totals;
  final_totals_->corrupt_frames = corrupt_frames_;
  if (ended_by == "error" && presses_.empty()) return;  // nothing saved: the folder goes (record_session)
  write_manifest(ended_by, error);
}

}  // namespace haptex::capture
