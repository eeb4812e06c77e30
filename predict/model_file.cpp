#include "predict/model_file.hpp"

#include <cmath>
#include <set>

#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/output_set.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "core/json/schema.hpp"
#include "core/h5/atomic_file.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/window.hpp"
#include "predict/model_probe.hpp"

namespace haptex::predict {

namespace layout = dataset::layout;
using dataset::root_path;
namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A training that diverged must not leave a model that prints NaN: the partial file is dropped.
void require_finite(const h5::Group& g, const char* name, bool finite) {
  if (!finite)
    throw failure(g.where() + "/" + name + ": holds NaN or infinity, so the training diverged and no model was written. "
                                           "Train again with a lower --learning-rate");
}

void write_vector(h5::Group g, const char* name, const Eigen::VectorXf& v) {
  require_finite(g, name, v.allFinite());
  g.write_array<float>(name, std::span<const float>(v.data(), std::size_t(v.size())), {std::size_t(v.size())});
}

// (rows, cols) in HDF5's row-major order, as numpy shows it.
void write_matrix(h5::Group g, const char* name, const Eigen::MatrixXf& m) {
  require_finite(g, name, m.allFinite());
  const RowMajor r = m;
  g.write_array<float>(name, std::span<const float>(r.data(), std::size_t(r.size())), {std::size_t(r.rows()), std::size_t(r.cols())});
}

void write_mlp(h5::Group parent, const char* name, const Mlp& net) {
  h5::Group layers = parent.create_group(name).create_group(layout::kLayers);
  for (std::size_t i = 0; i < net.layers.size(); ++i) {
    h5::Group l = layers.create_group(std::to_string(i));
    write_matrix(l, layout::kWeight, net.layers[i].weight);
    write_vector(l, layout::kBias, net.layers[i].bias);
    l.set_attr(layout::kActivation, activation_name(net.layers[i].activation));
  }
}

void write_normalisation(h5::Group root, const Model& model) {
  const Normalisation& n = model.normalisation;
  h5::Group g = root.create_group(layout::kNormalisation);
  write_vector(g, layout::kActionMean, n.action_mean);
  write_vector(g, layout::kActionScale, n.action_scale);
  write_vector(g, layout::kTargetScale, n.target_scale);
  g.set_attr(layout::kForceMin, double(n.force_min));
  g.set_attr(layout::kForceMax, double(n.force_max));
  g.set_attr(layout::kSpeedMin, double(n.speed_min));
  g.set_attr(layout::kSpeedMax, double(n.speed_max));
  if (model.variant == Variant::unified) {
    write_vector(g, layout::kDescriptorMean, n.descriptor_mean);
    write_vector(g, layout::kDescriptorScale, n.descriptor_scale);
  }
}

void write_descriptor_spec(h5::Group root, const TextureDescriptorSpec& spec) {
  h5::Group g = root.create_group(layout::kFeatureSpec);
  g.set_attr(layout::kDescriptorSpec, "texture_descriptor/1");
  g.set_attr(layout::kDescriptorSize, spec.size);
  g.set_attr(layout::kRadialBins, spec.radial_bins);
  g.set_attr(layout::kOrientations, spec.orientations);
  g.set_attr(layout::kOctaves, spec.octaves);
  g.set_attr(layout::kGradientScales, spec.gradient_scales);
  g.set_attr(layout::kDescriptorLength, std::int64_t(descriptor_length(spec)));
}

constexpr const char* kRetrain = "Train the model again (haptex train)";
constexpr std::int64_t kLargestLayer = 1 << 16;  // far beyond any haptex network; bounds what a damaged file makes us allocate

enum class Values { finite, positive };

// Readers: every array checked for its expected size and for finite values (scales: positive) so a
// damaged or diverged model fails here, naming the array, not as NaN spectra later.
struct Reader {
  std::string path;

  void check(const h5::Dataset& d, const std::vector<float>& v, Values kind) const {
    for (std::size_t i = 0; i < v.size(); ++i)
      // A subnormal scale (below 1.2e-38) divides values past float32's range.
      if (!std::isfinite(v[i]) || (kind == Values::positive && !(v[i] > 0 && std::isnormal(v[i]))))
        throw input_error(path, d.object_path(),
                          "value " + std::to_string(i) + " is " + text::format("%.9g", double(v[i])) +
                              (kind == Values::positive ? ", but a scale must be positive and finite, at least 1.2e-38 (a normal float32)" : ", not a finite number"),
                          std::string("The model is damaged or its training diverged. ") + kRetrain);
  }

  h5::Dataset floats(const h5::Group& g, const char* name) const {
    const h5::Dataset d = g.open_dataset(name);
    if (d.dtype() != "float32") throw input_error(path, d.object_path(), "holds " + d.dtype() + ", expected float32", kRetrain);
    return d;
  }

  Eigen::VectorXf vector(const h5::Group& g, const char* name, Eigen::Index expected = -1, Values kind = Values::finite) const {
    const h5::Dataset d = floats(g, name);
    const h5::Shape shape = d.shape();
    if (shape.size() != 1 || (expected >= 0 && Eigen::Index(shape[0]) != expected) || shape[0] > hsize_t(kLargestLayer))
      throw input_error(path, d.object_path(),
                        "has shape " + h5::shape_text(shape) + ", expected " +
                            (expected >= 0 ? "(" + std::to_string(expected) + ")" : "a 1-D array of at most " + std::to_string(kLargestLayer)),
                        kRetrain);
    const std::vector<float> v = d.read<float>();
    check(d, v, kind);
    return Eigen::Map<const Eigen::VectorXf>(v.data(), Eigen::Index(v.size()));
  }

  Eigen::MatrixXf matrix(const h5::Group& g, const char* name) const {
    const h5::Dataset d = floats(g, name);
    const h5::Shape shape = d.shape();
    if (shape.size() != 2 || shape[0] > hsize_t(kLargestLayer) || shape[1] > hsize_t(kLargestLayer))
      throw input_error(path, d.object_path(),
                        "has shape " + h5::shape_text(shape) + ", expected a 2-D array of at most " + std::to_string(kLargestLayer) + " x " +
                            std::to_string(kLargestLayer),
                        kRetrain);
    const std::vector<float> v = d.read<float>();
    check(d, v, Values::finite);
    return Eigen::Map<const RowMajor>(v.data(), Eigen::Index(shape[0]), Eigen::Index(shape[1]));
  }

  nlohmann::json json(const h5::Node& node, const char* name) const {
    try {
      return json::parse_text(node.attr_string(name), path);
    } catch (const Error& e) {
      throw input_error(path, node.object_path() + " attribute '" + name + "'", "is not JSON haptex can read", kRetrain);
    }
  }

  // A training range's end. Low-passed force and speed ring slightly below zero after a stroke's
  // turn, so only finiteness is asked here; the order of the two ends is checked by the caller.
  float bound(const h5::Node& node, const char* name) const {
    const double v = node.attr_double(name);
    if (!std::isfinite(v))
      throw input_error(path, node.object_path() + " attribute '" + name + "'", "is " + std::to_string(v) + ", not a finite force or speed",
                        kRetrain);
    return float(v);
  }

  TextureDescriptorSpec spec(const h5::Group& g) const {
    const auto value = [&](const char* name) {
      const std::int64_t v = g.attr_int(name);
      return v < 0 || v > 1 << 20 ? -1 : int(v);
    };
    const TextureDescriptorSpec spec{value(layout::kDescriptorSize), value(layout::kRadialBins), value(layout::kOrientations), value(layout::kOctaves),
                                     value(layout::kGradientScales)};
    if (const std::string problem = spec_problem(spec); !problem.empty()) throw input_error(path, g.object_path(), problem, kRetrain);
    return spec;
  }

  // A layer's activation; one this haptex does not know is the file's fault, named there (review 15, R7).
  Activation activation(const h5::Group& layer) const {
    const std::string name = layer.attr_string(layout::kActivation);
    try {
      return parse_activation(name);
    } catch (const Error&) {
      throw input_error(path, layer.object_path() + "@" + layout::kActivation, "'" + name + "' is not linear, relu or softplus", kRetrain);
    }
  }

  Mlp mlp(const h5::Group& parent, const char* name) const {
    Mlp net;
    const h5::Group layers = parent.open_group(name).open_group(layout::kLayers);
    for (const std::string& i : layers.children()) {
      const h5::Group l = layers.open_group(i);
      DenseLayer layer{matrix(l, layout::kWeight), vector(l, layout::kBias), activation(l)};
      const Eigen::Index in = net.layers.empty() ? layer.weight.cols() : net.layers.back().weight.rows();
      if (layer.bias.size() != layer.weight.rows() || layer.weight.cols() != in)
        throw input_error(path, l.object_path(), "weight and bias sizes do not chain", "Train the model again");
      net.layers.push_back(std::move(layer));
    }
    if (net.layers.empty()) throw input_error(path, layers.object_path(), "no layers", "Train the model again");
    return net;
  }
};

void check_nets(const Model& m, const std::string& path) {
  const std::size_t expected = m.variant == Variant::unified ? 1 : m.material_ids.size();
  if (m.nets.size() != expected)
    throw input_error(path, root_path(layout::kNets), std::to_string(m.nets.size()) + " networks for " + std::to_string(expected), "Train the model again");
  for (const SpectrumNet& n : m.nets)
    if (n.action.inputs() != kActionValues || n.predictor.outputs() != kTargetBins ||
        n.predictor.inputs() != m.latent_size() + n.action.outputs() || n.action.outputs() != m.nets[0].action.outputs() ||
        m.normalisation.target_scale.size() != kTargetBins)
      throw input_error(path, root_path(layout::kNets), "the networks' sizes do not fit together", "Train the model again");
}

// An id names one material, so --material reaches each, and it is its name's id (review 19, F2: an
// id given twice left the second material unreachable, an empty one was accepted; review 20, F2: swapped
// names were printed and used).
void require_material_ids(const std::string& path, const std::vector<std::string>& ids, const std::vector<std::string>& names) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const std::string& id = ids[i];
    const std::string where = root_path(layout::kMaterials) + "/" + layout::kMaterialIds + "[" + std::to_string(i) + "]";
    if (id.empty() || material_id(names[i]) != id)
      throw input_error(path, where,
                        "'" + text::printable(text::shortened(id)) + "' is not the id of the material's name '" +
                            text::printable(text::shortened(names[i])) + "' (" + layout::kMaterialNames + "[" + std::to_string(i) + "])",
                        kRetrain);
    if (!seen.insert(id).second)
      throw input_error(path, where, "'" + text::printable(id) + "' is given twice (each material has its own id)", kRetrain);
  }
}

}  // namespace

void write_model(const Model& model, const std::string& path, bool overwrite, const std::string& source) {
  h5::AtomicFile out(path, overwrite, dataset::format_name(dataset::Kind::model));
  write_model(model, out, source);
  out.commit();
}

void write_model(const Model& model, h5::AtomicFile& out, const std::string& source) {
  h5::Group root = out.root();
  dataset::stamp(root, dataset::Kind::model, source);
  root.set_attr(layout::kModelVariant, variant_name(model.variant));
  root.set_attr(dataset::layout::kDatasetSha256, model.dataset_sha256);
  root.set_attr(dataset::layout::kSplitSha256, model.split_sha256);
  root.set_attr(layout::kModelConfig, model.config.dump());
  root.set_attr(layout::kModelMetrics, model.metrics.dump());
  h5::Group materials = root.create_group(layout::kMaterials);
  materials.write_strings(layout::kMaterialIds, model.material_ids);
  materials.write_strings(layout::kMaterialNames, model.material_names);
  write_normalisation(root, model);
  write_descriptor_spec(root, model.descriptor);
  if (model.variant == Variant::unified) {
    write_mlp(root, layout::kTextureEncoder, model.texture);
    write_mlp(root, layout::kClassifier, model.classifier);
    write_matrix(root, layout::kMaterialLatents, model.material_latents.transpose());
  }
  h5::Group nets = root.create_group(layout::kNets);
  for (std::size_t k = 0; k < model.nets.size(); ++k) {
    h5::Group g = nets.create_group(std::to_string(k));
    write_mlp(g, layout::kActionEncoder, model.nets[k].action);
    write_mlp(g, layout::kPredictor, model.nets[k].predictor);
  }
}

Model read_model(const std::string& path) {
  const h5::File file = dataset::open_checked(path, dataset::Kind::model);
  const h5::Group root = file.root();
  const Reader r{path};
  Model m;
  const std::string variant = root.attr_string(layout::kModelVariant);
  if (variant != variant_name(Variant::unified) && variant != variant_name(Variant::per_material))
    throw input_error(path, "/ attribute 'variant'", "is '" + variant + "', neither " + variant_name(Variant::unified) + " nor " + variant_name(Variant::per_material), kRetrain);
  m.variant = variant == variant_name(Variant::unified) ? Variant::unified : Variant::per_material;
  m.dataset_sha256 = root.attr_string(dataset::layout::kDatasetSha256);
  m.split_sha256 = root.attr_string(dataset::layout::kSplitSha256);
  m.config = r.json(root, layout::kModelConfig);
  m.metrics = r.json(root, layout::kModelMetrics);
  m.material_ids = root.open_group(layout::kMaterials).open_dataset(layout::kMaterialIds).read_strings();
  m.material_names = root.open_group(layout::kMaterials).open_dataset(layout::kMaterialNames).read_strings();
  if (m.material_ids.empty() || m.material_names.size() != m.material_ids.size())
    throw input_error(path, root_path(layout::kMaterials), std::to_string(m.material_ids.size()) + " ids and " + std::to_string(m.material_names.size()) +
                                              " names", kRetrain);
  require_material_ids(path, m.material_ids, m.material_names);
  m.descriptor = r.spec(root.open_group(layout::kFeatureSpec));
  const h5::Group g = root.open_group(layout::kNormalisation);
  Normalisation& n = m.normalisation;
  n.action_mean = r.vector(g, layout::kActionMean, kActionValues);
  n.action_scale = r.vector(g, layout::kActionScale, kActionValues, Values::positive);
  n.target_scale = r.vector(g, layout::kTargetScale, kTargetBins, Values::positive);
  n.force_min = r.bound(g, layout::kForceMin), n.force_max = r.bound(g, layout::kForceMax);
  n.speed_min = r.bound(g, layout::kSpeedMin), n.speed_max = r.bound(g, layout::kSpeedMax);
  if (n.force_min > n.force_max || n.speed_min > n.speed_max)
    throw input_error(path, root_path(layout::kNormalisation), "the force or speed range is reversed (minimum above maximum)", kRetrain);
  if (m.variant == Variant::unified) {
    const auto length = Eigen::Index(descriptor_length(m.descriptor));
    n.descriptor_mean = r.vector(g, layout::kDescriptorMean, length);
    n.descriptor_scale = r.vector(g, layout::kDescriptorScale, length, Values::positive);
    m.texture = r.mlp(root, layout::kTextureEncoder);
    m.classifier = r.mlp(root, layout::kClassifier);
    m.material_latents = r.matrix(root, layout::kMaterialLatents).transpose();
    if (m.texture.inputs() != length || m.material_latents.rows() != m.texture.outputs() ||
        m.material_latents.cols() != Eigen::Index(m.material_ids.size()))
      throw input_error(path, root_path(layout::kTextureEncoder), "the texture encoder does not fit the descriptor or the materials", "Train the model again");
    if (m.classifier.inputs() != m.texture.outputs() || m.classifier.outputs() != Eigen::Index(m.material_ids.size()))
      throw input_error(path, root_path(layout::kClassifier), "takes " + std::to_string(m.classifier.inputs()) + " values to " +
                                                 std::to_string(m.classifier.outputs()) + " materials; the latent has " +
                                                 std::to_string(m.texture.outputs()) + " and the model " +
                                                 std::to_string(m.material_ids.size()) + " materials",
                        "Train the model again");
  }
  const h5::Group nets = root.open_group(layout::kNets);
  for (const std::string& k : nets.children())
    m.nets.push_back({r.mlp(nets.open_group(k), layout::kActionEncoder), r.mlp(nets.open_group(k), layout::kPredictor)});
  check_nets(m, path);
  m.file = path;
  require_finite_outputs(m, path);
  return m;
}

void record_training_log(h5::AtomicFile& out, const std::string& model_path, const TrainingLogRecord& record) {
  out.root().set_attr(layout::kTrainingLogAttribute, relative_to_folder_of(record.log, model_path));
  out.root().set_attr(layout::kTrainingLogSha256Attribute, record.sha256);
}

std::optional<TrainingLogRecord> recorded_training_log(const std::string& path) {
  try {
    const h5::File file = dataset::open_checked(path, dataset::Kind::model);
    const h5::Group root = file.root();
    const auto log = root.try_attr<std::string>(layout::kTrainingLogAttribute);
    const auto sha256 = root.try_attr<std::string>(layout::kTrainingLogSha256Attribute);
    if (!log || !sha256) return std::nullopt;
    return TrainingLogRecord{resolved_beside(*log, path), *sha256};
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace haptex::predict
