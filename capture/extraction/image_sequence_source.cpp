// A folder of frame images read as a video: how `haptex synth` wrote press videos (press_<j>/frame_0000.png ...)
// until it wrote MJPG AVIs, and how many tactile datasets are published.
#include <algorithm>
#include <charconv>
#include <optional>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "capture/extraction/capture_inputs.hpp"
#include "capture/extraction/frame_source.hpp"
#include "capture/scoring/scoring_image.hpp"
#include "core/input_file.hpp"
#include "core/error.hpp"
#include "core/image_header.hpp"
#include "core/sha256.hpp"
#include "dataset/decode_image.hpp"
#include "media/codecs.hpp"

namespace haptex::capture {
namespace {

namespace fs = std::filesystem;

const std::string kFrameNamesFix = "Name the frames by their numbers, one file each, none missing (frame_0000.png, frame_0001.png, ...)";

class ImageSequenceSource : public FrameSource {
 public:
  explicit ImageSequenceSource(std::string folder) : path_(std::move(folder)) {
    for (const auto& entry : fs::directory_iterator(path_))
      if (is_image_name(entry.path().string()) && !entry.is_directory()) {
        require_regular_file(entry.path().string());  // a FIFO frame would block the reader: refused by name
        files_.push_back(entry.path().string());
      }
    std::sort(files_.begin(), files_.end(), [](const std::string& a, const std::string& b) {
      return natural_less(fs::path(a).filename().string(), fs::path(b).filename().string());
    });
    if (files_.empty())
      throw input_error(path_, "", "the folder holds no frame images", "Give a folder of PNG or JPEG frames, or a video file");
    require_consecutive_numbers();
    size_ = load(0).size();
  }

  // The runs of digits in a file name's stem ("frame_0007_cam2" -> 0007, 2).
  static std::vector<std::string> digit_runs(const std::string& stem) {
    std::vector<std::string> runs;
    for (std::size_t i = 0; i < stem.size();) {
      if (!std::isdigit(static_cast<unsigned char>(stem[i]))) {
        ++i;
        continue;
      }
      const std::size_t from = i;
      while (i < stem.size() && std::isdigit(static_cast<unsigned char>(stem[i]))) ++i;
      runs.push_back(stem.substr(from, i - from));
    }
    return runs;
  }

  // Which run of digits is the frame number: the one that differs between the files (a camera's number
  // or a date the same in every name is not: review 21, F2); the last when none does (one file). Names
  // holding two numbers that change (a frame number and a time stamp or save counter) are refused: which
  // one counts the frames cannot be told (review 22, F1).
  std::size_t frame_number_run(const std::vector<std::vector<std::string>>& runs) const {
    const std::size_t count = runs.front().size();
    std::vector<std::size_t> varying;
    for (std::size_t r = 0; r < count; ++r)
      for (std::size_t k = 0; k < runs.size(); ++k)
        if (runs[k].size() != count)
          throw input_error(path_, fs::path(files_[k]).filename().string(),
                            "holds " + std::to_string(runs[k].size()) + " numbers where " + fs::path(files_[0]).filename().string() +
                                " holds " + std::to_string(count),
                            kFrameNamesFix);
        else if (runs[k][r] != runs[0][r]) {
          varying.push_back(r);
          break;
        }
    if (varying.size() > 1)
      throw input_error(path_, fs::path(files_[0]).filename().string(),
                        "and the other frames' names hold " + std::to_string(varying.size()) +
                            " numbers that change from frame to frame, so which one counts the frames cannot be told",
                        kFrameNamesFix);
    return varying.empty() ? count - 1 : varying.front();
  }

  // Frame k is the k-th file, so the numbers in the names must run on by one: a missing file would join
  // frames apart in time as neighbours, and two files of one number would be two frames (review 20, F3).
  void require_consecutive_numbers() const {
    std::vector<std::vector<std::string>> runs;
    for (const std::string& file : files_) {
      runs.push_back(digit_runs(fs::path(file).stem().string()));
      if (runs.back().empty()) throw input_error(path_, fs::path(file).filename().string(), "holds no frame number", kFrameNamesFix);
    }
    const std::size_t run = frame_number_run(runs);
    std::optional<unsigned long long> before;
    for (std::size_t k = 0; k < files_.size(); ++k) {
      const std::string& digits = runs[k][run];  // frame_number_run: every name holds as many numbers
      unsigned long long number = 0;
      if (std::from_chars(digits.data(), digits.data() + digits.size(), number).ec != std::errc() || number > (1ULL << 62))
        throw input_error(path_, fs::path(files_[k]).filename().string(), "holds the frame number " + digits + ", beyond any video's", kFrameNamesFix);
      if (before && number != *before + 1)
        throw input_error(path_, fs::path(files_[k]).filename().string(),
                          "is frame " + std::to_string(number) + ", after " + fs::path(files_[k - 1]).filename().string() + " (frame " +
                              std::to_string(*before) + ")" + (number == *before ? ": two files give one frame" : ": frames are missing between them"),
                          kFrameNamesFix);
      before = number;
    }
  }

  const std::string& path() const override { return path_; }
  cv::Size frame_size() const override { return size_; }
  double fps() const override { return 0.0; }  // images carry no frame rate
  bool lossless() const override {
    for (const auto& f : files_) {
      std::string ext = fs::path(f).extension().string();
      for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
      if (ext == ".jpg" || ext == ".jpeg") return false;
    }
    return true;
  }

  std::string sha256() const override {
    Sha256 hash;
    for (const auto& f : files_) {
      std::ifstream in(f, std::ios::binary);
      std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
      hash.update(std::string_view(bytes.data(), bytes.size()));
    }
    return hash.hex_digest();
  }

  void scan(const Visitor& visit, const std::function<bool(std::int64_t)>&) override {
    for (std::size_t i = 0; i < files_.size(); ++i) {
      const cv::Mat frame = load(i);
      visit(std::int64_t(i), scoring_image(frame), frame);
    }
  }

  // An 8-bit RGB PNG frame file is stored as it is: any reader decodes it to these pixels. A JPEG file
  // may carry an orientation tag, which haptex ignores (dataset/decode_image.hpp) and other readers
  // may apply, and other PNGs decode differently in OpenCV and PIL (core/image_header.hpp): those are
  // stored as the PNG of the decoded frame.
  void read(const std::vector<std::int64_t>& indices, const Delivery& deliver) override {
    for (std::int64_t i : indices) {
      dataset::EncodedImage bytes = file_bytes(std::size_t(i));
      const cv::Mat frame = load(std::size_t(i), bytes);
      const bool plain_png = is_plain_rgb_png(bytes);
      if (!plain_png) bytes.clear();
      deliver(i, frame, bytes);
    }
  }

 private:
  dataset::EncodedImage file_bytes(std::size_t i) const {
    std::ifstream in(files_[i], std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  cv::Mat load(std::size_t i) const { return load(i, file_bytes(i)); }

  cv::Mat load(std::size_t i, const dataset::EncodedImage& bytes) const {
    const std::optional<ImageSize> stated = image_header_size(bytes);
    if (stated && std::uint64_t(stated->width) * stated->height > kMaxImagePixels)
      throw input_error(files_[i], "frame " + std::to_string(i), "its header states " + std::to_string(stated->width) + " x " +
                                                                     std::to_string(stated->height) + " pixels, over 64 megapixels",
                        "Give the sensor's frames");
    cv::Mat image;
    try {
      if (!image_format(bytes).empty()) image = dataset::decode_image(bytes);  // empty when cut off, before libjpeg conceals it
      else if (!bytes.empty()) image = media::decode_image(bytes, cv::IMREAD_COLOR);  // another format OpenCV reads
    } catch (const cv::Exception&) {
    }
    if (image.empty())
      throw input_error(files_[i], "frame " + std::to_string(i), "cannot read the image", "Replace the damaged frame file");
    if (!size_.empty() && image.size() != size_)
      throw input_error(files_[i], "frame " + std::to_string(i), "the frame size differs from the first frame's",
                        "Every frame of a press must have one size");
    return image;
  }

  std::string path_;
  std::vector<std::string> files_;
  cv::Size size_;
};

}  // namespace

std::unique_ptr<FrameSource> open_image_sequence(const std::string& folder) {
  return std::make_unique<ImageSequenceSource>(folder);
}

}  // namespace haptex::capture
