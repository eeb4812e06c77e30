#pragma once
// What `capture extract` was given, as a list of (material, source). A source is a press file, a
// video file (`haptex synth` writes MJPG AVIs), or a folder of frame images (a PNG sequence). A
// folder holding sources is one material, named by the folder; a folder of such folders is several.
// Sources are taken in name order, numbers compared by value (press_2 before press_10), so press
// numbers are stable however the file system lists them.
#include <optional>
#include <string>
#include <vector>

namespace haptex::capture {

struct CaptureInput {
  enum class Kind { video, image_sequence, press_file };
  std::string path;
  std::string material;  // empty for press files without --material: the file names it
  Kind kind = Kind::video;
};

// Throws haptex::Error (bad_input) naming the path when it does not exist or a directory holds no
// video or press file.
std::vector<CaptureInput> expand_capture_inputs(const std::vector<std::string>& arguments,
                                                const std::optional<std::string>& material);

// "press_2" < "press_10": runs of digits compare as numbers.
bool natural_less(const std::string& a, const std::string& b);
bool is_video_name(const std::string& path);
// is_press_file_name: dataset/press_file.hpp (replay takes press files by name too).
bool is_image_name(const std::string& path);
// A folder with frame images in it (at least two).
bool is_image_sequence_dir(const std::string& path);

}  // namespace haptex::capture
