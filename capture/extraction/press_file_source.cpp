// Press files written by `haptex capture record`, read back for extraction.
#include <opencv2/imgproc.hpp>

#include "capture/extraction/frame_source.hpp"
#include "capture/extraction/gel_image.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "dataset/press_file.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/sha256.hpp"
#include "core/text/format.hpp"
#include "core/text/parse_number.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/decode_image.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {

namespace layout = dataset::layout;
namespace {

// A recorder figure stored in the press file, in grey levels (capture/scoring/contact_score.hpp):
// finite, from 0 to 255, and the trigger above 0 (a 32-bit float's least normal value). A damaged one
// is refused by name rather than changing which frames count as contact (review 9, F1).
float stored_grey_levels(const std::string& file, const h5::Group& root, const char* name, bool above_zero) {
  const double value = root.attr_double(name);
  const bool fits = value >= (above_zero ? text::kSmallestStored : 0.0) && value <= 255;  // NaN fails
  if (!fits)
    throw input_error(file, std::string("/@") + name,
                      text::format("is %g, not a score of %s to 255 grey levels", value, above_zero ? "above 0" : "0"),
                      "Record the press again; the file is damaged or was not written by haptex capture record");
  return float(value);
}

class PressFileSource : public FrameSource {
 public:
  explicit PressFileSource(const std::string& path) : frames_(path) {
    const h5::Group root = frames_.root();
    material_ = root.attr_string(layout::kPressMaterial);
    // The press's order covers its decoded frames too: a file whose frames hold B, G, R says BGR.
    order_ = dataset::read_channel_order(root, layout::kReference);
    reference_.image = frames_.reference();
    require_gel_image(reference_.image, path, "/reference", "Record the press again; the file is damaged or was not written by haptex capture record");
    reference_.noise = stored_grey_levels(path, root, layout::kNoise, false);
    reference_.pixel_threshold = stored_grey_levels(path, root, layout::kPixelThreshold, false);
    reference_.trigger = stored_grey_levels(path, root, layout::kTrigger, true);
    if (root.has_attr(layout::kNoContactLevel)) reference_.level = stored_grey_levels(path, root, layout::kNoContactLevel, false);
  }

  const std::string& path() const override { return frames_.path(); }
  std::string sha256() const override { return sha256_file(frames_.path()); }
  bool lossless() const override { return frames_.encoding() == "png"; }
  cv::Size frame_size() const override { return frames_.size(); }
  double fps() const override { return frames_.fps(); }
  std::optional<StoredReference> stored_reference() const override { return reference_; }
  std::string material() const override { return material_; }

  // Frames are read a block at a time (HDF5, one thread), their scoring images made on every core,
  // then visited in order. A frame the visitor needs whole (the reference's) is decoded in full and
  // scored from that, as one at a time would: need_full depends on the frames visited before it.
  void scan(const Visitor& visit, const std::function<bool(std::int64_t)>& need_full) override {
    constexpr std::size_t kBlock = 64;
    std::vector<std::vector<std::uint8_t>> bytes(kBlock);
    std::vector<cv::Mat> scoring(kBlock);
    for (std::size_t first = 0; first < frames_.count(); first += kBlock) {
      const std::size_t n = std::min(kBlock, frames_.count() - first);
      for (std::size_t k = 0; k < n; ++k) bytes[k] = frames_.bytes(first + k);
      parallel_for(n, [&](std::size_t k) { scoring[k] = scoring_of(bytes[k]); });
      for (std::size_t k = 0; k < n; ++k) {
        const std::int64_t index = std::int64_t(first + k);
        if (need_full && need_full(index)) {
          const cv::Mat full = decode(bytes[k]);
          visit(index, full.empty() ? cv::Mat() : scoring_image(full), full);
        } else {
          visit(index, scoring[k], cv::Mat());
        }
      }
    }
  }

  // The frames' bytes are stored as the sensor sent them, unless they decode to swapped colours.
  void read(const std::vector<std::int64_t>& indices, const Delivery& deliver) override {
    for (std::int64_t i : indices) {
      std::vector<std::uint8_t> bytes = frames_.bytes(std::size_t(i));
      const cv::Mat full = decode(bytes);
      if (full.empty())
        throw input_error(frames_.path(), "/frames[" + std::to_string(i) + "]", "the frame does not decode",
                          "The sensor sent a corrupt frame here; record the press again");
      if (order_ != dataset::ChannelOrder::rgb) bytes.clear();
      deliver(i, full, bytes);
    }
  }

 private:
  cv::Mat scoring_of(const std::vector<std::uint8_t>& bytes) const {
    if (frames_.encoding() == "jpeg") return scoring_image_from_jpeg(bytes, frames_.size());  // reduced-size decoding
    const cv::Mat full = decode(bytes);
    return full.empty() ? cv::Mat() : scoring_image(full);
  }

  cv::Mat decode(const std::vector<std::uint8_t>& bytes) const {
    cv::Mat image = dataset::decode_image(bytes);  // empty when cut off or neither JPEG nor PNG
    if (image.empty() || image.size() != frames_.size()) return {};
    // The decoder hands the codec's R, G, B over as B, G, R; frames stored swapped are swapped back.
    if (order_ == dataset::ChannelOrder::bgr) cv::cvtColor(image, image, cv::COLOR_RGB2BGR);
    return image;
  }

  dataset::PressFile frames_;
  std::string material_;
  dataset::ChannelOrder order_ = dataset::kWrittenChannelOrder;
  StoredReference reference_;
};

}  // namespace

std::unique_ptr<FrameSource> open_press_file(const std::string& path) { return std::make_unique<PressFileSource>(path); }

}  // namespace haptex::capture
