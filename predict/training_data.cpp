#include "predict/training_data.hpp"

#include <mutex>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/parallel.hpp"
#include "dataset/press_images.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/window_table.hpp"
#include "predict/augmentation.hpp"

namespace haptex::predict {
namespace {

using namespace dataset::layout;

// The images of `name` in `press` as RGB, the order texture_descriptor takes, whatever order the
// press states (dataset/channel_order.hpp).
std::vector<cv::Mat> rgb_images(const h5::Group& press, const char* name) {
  std::vector<cv::Mat> images = dataset::read_press_images(press, name);
  for (cv::Mat& image : images) cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
  return images;
}

cv::Mat rgb_image(const h5::Group& press, const char* name) { return rgb_images(press, name).front(); }

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
  const cv::Mat reference = rgb_image(g, kReference);
  Descriptors out;
  if (!training) {
    out.push_back(texture_descriptor(rgb_image(g, kPeak), reference, spec));
    return out;
  }
  const std::vector<cv::Mat> augmented_references = all_augmentations(reference);
  for (const cv::Mat& frame : rgb_images(g, kFrames)) {
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
