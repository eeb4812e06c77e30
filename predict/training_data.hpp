#pragma once
// What training and evaluation read from a dataset file and its split: the windows' actions and
// target spectra, which windows each set holds, and the texture descriptors of each set's press
// images (training presses: 12 frames x 8 augmentations; validation and test presses: the peak).
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "predict/texture_descriptor.hpp"
#include "split/split_windows.hpp"

namespace haptex::predict {

using Descriptors = std::vector<std::vector<float>>;

struct MaterialData {
  std::string id, name;
  std::array<std::vector<std::size_t>, 3> rows;  // columns of action/target in each set
  std::array<Descriptors, 3> images;             // descriptors of each set's press images
};

struct TrainingData {
  Eigen::MatrixXf action;  // 20 x windows: every row of the dataset's /windows
  Eigen::MatrixXf target;  // 100 x windows
  std::vector<MaterialData> materials;
  TextureDescriptorSpec descriptor;
  std::string dataset_sha256, split_sha256;
};

// Progress of the descriptor computation: (done, total) presses.
using LoadProgress = std::function<void(std::size_t, std::size_t)>;

// Throws haptex::Error (bad_input) naming the material and the file when a material has no
// training or no validation windows, or a press the split names is missing from the dataset.
// Which press images get descriptors: training (training presses: all 12 frames in all 8
// augmentations; others: the peak), or none (per-material models, which have no texture encoder).
enum class PressImages { training, none };
TrainingData load_training_data(const split::DatasetSplit& split, const TextureDescriptorSpec& spec,
                                const LoadProgress& progress = {}, PressImages images = PressImages::training);

// The descriptors of one press: training presses all frames in all 8 augmentations, other presses
// their peak frame. Images are read in the order the press states and described as RGB; an order
// other than RGB or BGR is refused (haptex::Error, bad_input, naming the dataset and the attribute).
Descriptors press_descriptors(const std::string& dataset_path, const std::string& material_id, int press,
                              bool training, const TextureDescriptorSpec& spec);

}  // namespace haptex::predict
