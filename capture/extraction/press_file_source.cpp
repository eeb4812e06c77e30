// Press files written by `haptex capture record`, read back for extraction.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/extraction/frame_source.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "capture/storage/image_datasets.hpp"
#include "capture/storage/vlen_bytes.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/sha256.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {

namespace layout = dataset::layout;
namespace {

class PressFileSource : public FrameSource {
 public:
  explicit PressFileSource(std::string path) : path_(std::move(path)), file_(dataset::open_checked(path_, dataset::Kind::press)) {
    const h5::Group root = file_.root();
    frames_ = root.open_dataset(layout::kFrames);
    if (!is_vlen_bytes(frames_))
      throw input_error(path_, "/frames", "expected variable-length uint8 frames", "Record the press again");
    encoding_ = root.attr_string("encoding");
    if (encoding_ != "jpeg" && encoding_ != "png")
      throw input_error(path_, "/", "unknown frame encoding '" + encoding_ + "'", "Expected jpeg or png");
    size_ = cv::Size(int(root.attr_int("width")), int(root.attr_int("height")));
    fps_ = root.attr_double("fps");
    material_ = root.attr_string("material");
    count_ = frames_.shape().at(0);
    // The press's order covers its decoded frames too: a file whose frames hold B, G, R says BGR.
    order_ = dataset::read_channel_order(root, layout::kReference);
    reference_.image = read_image(root, layout::kReference);
    if (reference_.image.size() != size_)
      throw input_error(path_, "/reference", "the reference is not the frame size", "Record the press again");
    reference_.noise = float(root.attr_double("noise"));
    reference_.pixel_threshold = float(root.attr_double("pixel_threshold"));
    reference_.trigger = float(root.attr_double("trigger"));
  }

  const std::string& path() const override { return path_; }
  std::string sha256() const override { return sha256_file(path_); }
  bool lossless() const override { return encoding_ == "png"; }
  cv::Size frame_size() const override { return size_; }
  double fps() const override { return fps_; }
  std::optional<StoredReference> stored_reference() const override { return reference_; }
  std::string material() const override { return material_; }

  void scan(const Visitor& visit, const std::function<bool(std::int64_t)>& need_full) override {
    for (std::size_t i = 0; i < count_; ++i) {
      const std::vector<std::uint8_t> bytes = read_vlen_bytes(frames_, i);
      const std::int64_t index = std::int64_t(i);
      if (need_full && need_full(index)) {
        const cv::Mat full = decode(bytes);
        visit(index, full.empty() ? cv::Mat() : scoring_image(full), full);
      } else if (encoding_ == "jpeg") {
        visit(index, scoring_image_from_jpeg(bytes, size_), cv::Mat());  // reduced-size decoding: the fast path
      } else {
        const cv::Mat full = decode(bytes);
        visit(index, full.empty() ? cv::Mat() : scoring_image(full), cv::Mat());
      }
    }
  }

  void read(const std::vector<std::int64_t>& indices,
            const std::function<void(std::int64_t, const cv::Mat&)>& deliver) override {
    for (std::int64_t i : indices) {
      const cv::Mat full = decode(read_vlen_bytes(frames_, std::size_t(i)));
      if (full.empty())
        throw input_error(path_, "/frames[" + std::to_string(i) + "]", "the frame does not decode",
                          "The sensor sent a corrupt frame here; record the press again");
      deliver(i, full);
    }
  }

 private:
  cv::Mat decode(const std::vector<std::uint8_t>& bytes) const {
    if (bytes.empty() || (encoding_ == "jpeg" && !is_complete_jpeg(bytes))) return {};
    cv::Mat image;
    try {
      image = cv::imdecode(bytes, cv::IMREAD_COLOR);
    } catch (const cv::Exception&) {
      return {};
    }
    if (image.size() != size_) return {};
    // imdecode hands the codec's R, G, B over as B, G, R; frames stored swapped are swapped back.
    if (order_ == dataset::ChannelOrder::bgr) cv::cvtColor(image, image, cv::COLOR_RGB2BGR);
    return image;
  }

  std::string path_;
  h5::File file_;
  h5::Dataset frames_{h5::Handle(), "", ""};
  std::string encoding_, material_;
  cv::Size size_;
  double fps_ = 0;
  std::size_t count_ = 0;
  dataset::ChannelOrder order_ = dataset::kWrittenChannelOrder;
  StoredReference reference_;
};

}  // namespace

std::unique_ptr<FrameSource> open_press_file(const std::string& path) { return std::make_unique<PressFileSource>(path); }

}  // namespace haptex::capture
