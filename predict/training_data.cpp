#include "predict/training_data.hpp"

#include <mutex>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/parallel.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/window_table.hpp"
#include "predict/augmentation.hpp"

namespace haptex::predict {
namespace {

using namespace dataset::layout;

cv::Mat image_at(const h5::Dataset& d, std::size_t first_axis_index = 0) {
  const h5::Shape shape = d.shape();
  const bool stack = shape.size() == 4;
  const int h = int(shape[stack ? 1 : 0]), w = int(shape[stack ? 2 : 1]);
  const std::vector<std::uint8_t> all = d.read<std::uint8_t>();
  const std::size_t one = std::size_t(h) * std::size_t(w) * 3;
  if (all.size() < (first_axis_index + 1) * one) throw failure(d.where() + ": image " + std::to_string(first_axis_index) + " missing");
  return cv::Mat(h, w, CV_8UC3, const_cast<std::uint8_t*>(all.data()) + first_axis_index * one).clone();
}

std::vector<cv::Mat> images(const h5::Dataset& d) {
  const h5::Shape shape = d.shape();
  if (shape.size() != 4 || shape[3] != 3) throw failure(d.where() + ": expected (frames, H, W, 3) uint8");
  const std::vector<std::uint8_t> all = d.read<std::uint8_t>();
  const int h = int(shape[1]), w = int(shape[2]);
  const std::size_t one = std::size_t(h) * std::size_t(w) * 3;
  std::vector<cv::Mat> out;
  for (std::size_t i = 0; i < shape[0]; ++i)
    out.push_back(cv::Mat(h, w, CV_8UC3, const_cast<std::uint8_t*>(all.data()) + i * one).clone());
  return out;
}

// Row-major (windows x width) in the file is column-major (width x windows) here: one window per column.
Eigen::MatrixXf columns(const std::vector<float>& values, std::size_t width) {
  return Eigen::Map<const Eigen::MatrixXf>(values.data(), Eigen::Index(width), Eigen::Index(values.size() / width));
}

void check_sets(const split::MaterialSets& m, const std::string& manifest) {
  static constexpr const char* kWhat[] = {"training", "validation"};
  for (std::size_t set : {split::kTrain, split::kVal})
    if (m.rows[set].empty())
      throw input_error(manifest, "materials/" + m.id, "material '" + m.name + "' has no " + kWhat[set] + " windows",
                        "Give it longer recordings or make the split with fewer sections per set (haptex split --val/--test)");
}

}  // namespace

Descriptors press_descriptors(const std::string& dataset_path, const std::string& material_id, int press, bool training,
                              const TextureDescriptorSpec& spec) {
  const h5::File file = dataset::open_checked(dataset_path, dataset::Kind::dataset);
  const std::string path = std::string(kMaterials) + "/" + material_id + "/" + kPresses + "/" + std::to_string(press);
  const h5::Group root = file.root();
  if (!root.has_group(path))
    throw input_error(dataset_path, "/" + path, "the split names this press but the dataset has none", "Run haptex split on this dataset");
  const h5::Group g = root.open_group(path);
  const cv::Mat reference = image_at(g.open_dataset(kReference));
  Descriptors out;
  if (!training) {
    out.push_back(texture_descriptor(image_at(g.open_dataset(kPeak)), reference, spec));
    return out;
  }
  const std::vector<cv::Mat> augmented_references = all_augmentations(reference);
  for (const cv::Mat& frame : images(g.open_dataset(kFrames))) {
    const std::vector<cv::Mat> augmented = all_augmentations(frame);
    for (std::size_t v = 0; v < augmented.size(); ++v)
      out.push_back(texture_descriptor(augmented[v], augmented_references[v], spec));
  }
  return out;
}

TrainingData load_training_data(const split::DatasetSplit& split, const TextureDescriptorSpec& spec, const LoadProgress& progress,
                                PressImages images) {
  TrainingData data;
  data.dataset_sha256 = split.dataset_sha256;
  data.split_sha256 = split.manifest_sha256;
  data.descriptor = spec;
  {
    const dataset::WindowTable windows = dataset::read_window_table(dataset::open_checked(split.dataset_path, dataset::Kind::dataset));
    data.action = columns(windows.action, dataset::kActionValues);
    data.target = columns(windows.target, dataset::kTargetBins);
  }
  struct Job {
    std::size_t material, set;
    int press;
  };
  std::vector<Job> jobs;
  for (std::size_t m = 0; m < split.materials.size(); ++m) {
    const split::MaterialSets& sets = split.materials[m];
    check_sets(sets, split.manifest_path);
    data.materials.push_back({sets.id, sets.name, sets.rows, {}});
    if (images == PressImages::none) continue;
    for (std::size_t s = 0; s < 3; ++s)
      for (int press : sets.presses[s]) jobs.push_back({m, s, press});
  }
  std::vector<Descriptors> results(jobs.size());
  std::mutex mutex;
  std::size_t done = 0;
  parallel_for(jobs.size(), [&](std::size_t j) {
    const Job& job = jobs[j];
    results[j] = press_descriptors(split.dataset_path, split.materials[job.material].id, job.press,
                                   job.set == split::kTrain, spec);
    std::lock_guard lock(mutex);
    if (progress) progress(++done, jobs.size());
  });
  // Appended in job order, whichever thread finished first.
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    Descriptors& into = data.materials[jobs[j].material].images[jobs[j].set];
    into.insert(into.end(), results[j].begin(), results[j].end());
  }
  return data;
}

}  // namespace haptex::predict
