#pragma once
// The presses of a gelsight or dataset file (/materials/{material}/presses/{j}), read once for the
// gelsight.* checks (qa/gelsight_checks.hpp). A dataset that is missing or misshapen leaves its
// part of the summary empty: the layout checks report it, the others skip it.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/h5/node.hpp"

namespace haptex::qa {

// What the checks need of one press, measured as it is read: its images are not kept, so a file of
// thousands of full-size frames is checked in the memory of one press.
struct Press {
  std::string path, material;
  std::optional<double> trigger, pixel_threshold;
  bool has_reference = false, has_peak = false;
  cv::Size reference_size, peak_size, frames_size;
  bool sizes_agree = false;
  cv::Mat reference_scoring;            // CV_32F scoring image of the reference
  double reference_sharpness = 0;       // variance of its Laplacian
  std::optional<double> peak_score;     // the peak against the reference, recomputed
  struct Image {
    std::string where;
    cv::Size size;
    double sharpness = 0, saturated = 0;
  };
  std::vector<Image> images;            // the peak and every frame
  // capture extract records how many frames of the press's source did not decode.
  std::int64_t source_frames_unreadable = 0;
  std::string source_frames_problem;    // why that count is unknown; empty when it was read
  std::string channel_order_problem;    // why the images' channel order is unknown (they were not read)
};

struct GelsightPresses {
  std::vector<Press> presses;                       // in file order
  std::map<std::string, std::size_t> per_material;  // presses per material group (0: none)
};
GelsightPresses read_presses(const h5::Group& root);
// "/materials/{material}/presses/{j}" of every press group, in file order.
std::vector<std::string> press_paths(const h5::Group& root);

}  // namespace haptex::qa
