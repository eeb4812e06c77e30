#include "predict/model_file.hpp"

#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"

namespace haptex::predict {
namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void write_vector(h5::Group g, const char* name, const Eigen::VectorXf& v) {
  g.write_array<float>(name, std::span<const float>(v.data(), std::size_t(v.size())), {std::size_t(v.size())});
}

// (rows, cols) in HDF5's row-major order, as numpy shows it.
void write_matrix(h5::Group g, const char* name, const Eigen::MatrixXf& m) {
  const RowMajor r = m;
  g.write_array<float>(name, std::span<const float>(r.data(), std::size_t(r.size())), {std::size_t(r.rows()), std::size_t(r.cols())});
}

void write_mlp(h5::Group parent, const char* name, const Mlp& net) {
  h5::Group layers = parent.create_group(name).create_group("layers");
  for (std::size_t i = 0; i < net.layers.size(); ++i) {
    h5::Group l = layers.create_group(std::to_string(i));
    write_matrix(l, "weight", net.layers[i].weight);
    write_vector(l, "bias", net.layers[i].bias);
    l.set_attr("activation", activation_name(net.layers[i].activation));
  }
}

void write_normalisation(h5::Group root, const Model& model) {
  const Normalisation& n = model.normalisation;
  h5::Group g = root.create_group("normalisation");
  write_vector(g, "action_mean", n.action_mean);
  write_vector(g, "action_scale", n.action_scale);
  write_vector(g, "target_scale", n.target_scale);
  g.set_attr("force_min", double(n.force_min));
  g.set_attr("force_max", double(n.force_max));
  g.set_attr("speed_min", double(n.speed_min));
  g.set_attr("speed_max", double(n.speed_max));
  if (model.variant == Variant::unified) {
    write_vector(g, "descriptor_mean", n.descriptor_mean);
    write_vector(g, "descriptor_scale", n.descriptor_scale);
  }
}

void write_descriptor_spec(h5::Group root, const TextureDescriptorSpec& spec) {
  h5::Group g = root.create_group("feature_spec");
  g.set_attr("descriptor", "texture_descriptor/1");
  g.set_attr("size", spec.size);
  g.set_attr("radial_bins", spec.radial_bins);
  g.set_attr("orientations", spec.orientations);
  g.set_attr("octaves", spec.octaves);
  g.set_attr("gradient_scales", spec.gradient_scales);
  g.set_attr("length", std::int64_t(descriptor_length(spec)));
}

// Readers: every array checked for its expected size so a damaged file fails here, not in a product.
struct Reader {
  std::string path;

  Eigen::VectorXf vector(const h5::Group& g, const char* name, Eigen::Index expected = -1) const {
    const h5::Dataset d = g.open_dataset(name);
    const std::vector<float> v = d.read<float>();
    if (d.shape().size() != 1 || (expected >= 0 && Eigen::Index(v.size()) != expected))
      throw input_error(path, d.object_path(), "expected " + std::to_string(expected) + " values", "Train the model again");
    return Eigen::Map<const Eigen::VectorXf>(v.data(), Eigen::Index(v.size()));
  }

  Eigen::MatrixXf matrix(const h5::Group& g, const char* name) const {
    const h5::Dataset d = g.open_dataset(name);
    const h5::Shape shape = d.shape();
    if (shape.size() != 2) throw input_error(path, d.object_path(), "expected a 2-D array", "Train the model again");
    const std::vector<float> v = d.read<float>();
    return Eigen::Map<const RowMajor>(v.data(), Eigen::Index(shape[0]), Eigen::Index(shape[1]));
  }

  Mlp mlp(const h5::Group& parent, const char* name) const {
    Mlp net;
    const h5::Group layers = parent.open_group(name).open_group("layers");
    for (const std::string& i : layers.children()) {
      const h5::Group l = layers.open_group(i);
      DenseLayer layer{matrix(l, "weight"), vector(l, "bias"), parse_activation(l.attr_string("activation"))};
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
    throw input_error(path, "/nets", std::to_string(m.nets.size()) + " networks for " + std::to_string(expected), "Train the model again");
  for (const SpectrumNet& n : m.nets)
    if (n.action.inputs() != kActionValues || n.predictor.outputs() != kSpectrumBins ||
        n.predictor.inputs() != m.latent_size() + n.action.outputs() || n.action.outputs() != m.nets[0].action.outputs() ||
        m.normalisation.target_scale.size() != kSpectrumBins)
      throw input_error(path, "/nets", "the networks' sizes do not fit together", "Train the model again");
}

}  // namespace

void write_model(const Model& model, const std::string& path, bool overwrite, const std::string& source) {
  h5::AtomicFile out(path, overwrite);
  h5::Group root = out.root();
  h5::stamp_root(root, kModelFormat, source);
  root.set_attr("variant", variant_name(model.variant));
  root.set_attr("dataset_sha256", model.dataset_sha256);
  root.set_attr("split_sha256", model.split_sha256);
  root.set_attr("config", model.config.dump());
  root.set_attr("metrics", model.metrics.dump());
  h5::Group materials = root.create_group("materials");
  materials.write_strings("ids", model.material_ids);
  materials.write_strings("names", model.material_names);
  write_normalisation(root, model);
  write_descriptor_spec(root, model.descriptor);
  if (model.variant == Variant::unified) {
    write_mlp(root, "texture_encoder", model.texture);
    write_mlp(root, "classifier", model.classifier);
    write_matrix(root, "material_latents", model.material_latents.transpose());
  }
  h5::Group nets = root.create_group("nets");
  for (std::size_t k = 0; k < model.nets.size(); ++k) {
    h5::Group g = nets.create_group(std::to_string(k));
    write_mlp(g, "action_encoder", model.nets[k].action);
    write_mlp(g, "predictor", model.nets[k].predictor);
  }
  out.commit();
}

Model read_model(const std::string& path) {
  const h5::File file = h5::File::open(path);
  const h5::Group root = file.root();
  if (!root.has_attr("haptex_format") || root.attr_string("haptex_format") != kModelFormat)
    throw input_error(path, "/", "not a model file (model/1)", "Give the file haptex train wrote");
  const Reader r{path};
  Model m;
  m.variant = root.attr_string("variant") == "unified" ? Variant::unified : Variant::per_material;
  m.dataset_sha256 = root.attr_string("dataset_sha256");
  m.split_sha256 = root.attr_string("split_sha256");
  m.config = nlohmann::json::parse(root.attr_string("config"));
  m.metrics = nlohmann::json::parse(root.attr_string("metrics"));
  m.material_ids = root.open_dataset("materials/ids").read_strings();
  m.material_names = root.open_dataset("materials/names").read_strings();
  const h5::Group spec = root.open_group("feature_spec");
  m.descriptor = {int(spec.attr_int("size")), int(spec.attr_int("radial_bins")), int(spec.attr_int("orientations")),
                  int(spec.attr_int("octaves")), int(spec.attr_int("gradient_scales"))};
  const h5::Group g = root.open_group("normalisation");
  Normalisation& n = m.normalisation;
  n.action_mean = r.vector(g, "action_mean", kActionValues);
  n.action_scale = r.vector(g, "action_scale", kActionValues);
  n.target_scale = r.vector(g, "target_scale", kSpectrumBins);
  n.force_min = float(g.attr_double("force_min")), n.force_max = float(g.attr_double("force_max"));
  n.speed_min = float(g.attr_double("speed_min")), n.speed_max = float(g.attr_double("speed_max"));
  if (m.variant == Variant::unified) {
    const auto length = Eigen::Index(descriptor_length(m.descriptor));
    n.descriptor_mean = r.vector(g, "descriptor_mean", length);
    n.descriptor_scale = r.vector(g, "descriptor_scale", length);
    m.texture = r.mlp(root, "texture_encoder");
    m.classifier = r.mlp(root, "classifier");
    m.material_latents = r.matrix(root, "material_latents").transpose();
    if (m.texture.inputs() != length || m.material_latents.rows() != m.texture.outputs() ||
        m.material_latents.cols() != Eigen::Index(m.material_ids.size()))
      throw input_error(path, "/texture_encoder", "the texture encoder does not fit the descriptor or the materials", "Train the model again");
  }
  const h5::Group nets = root.open_group("nets");
  for (const std::string& k : nets.children())
    m.nets.push_back({r.mlp(nets.open_group(k), "action_encoder"), r.mlp(nets.open_group(k), "predictor")});
  check_nets(m, path);
  return m;
}

}  // namespace haptex::predict
