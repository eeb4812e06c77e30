#include "dataset/truth_file.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "core/error.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/naming.hpp"
#include "core/sha256.hpp"
#include "dataset/description.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/window.hpp"

namespace haptex::dataset {
namespace {

constexpr const char* kHattModel = "hatt-model";
constexpr const char* kSynthMaterial = "synth-material";
constexpr std::size_t kBins = dataset::kTargetBins;
constexpr const char* kRerun = "Run haptex synth again to write a new truth.h5";
// Beyond what haptex synth writes (600 s at 10 kHz per recording; 10 x 8 grid points; 60 HaTT
// materials x 2 recordings x 10 s is 12 million samples in all), small enough that a damaged file's
// extents cannot make the reader allocate gigabytes: at most 100 x 100 x 100 grid values, and 50
// million samples per channel over the whole file (400 MB as double).
constexpr hsize_t kMostSamples = 10'000'000;
constexpr hsize_t kMostGridPoints = 100;
constexpr std::size_t kMostTotalSamples = 50'000'000;
constexpr double kLargestAction = 1e6;  // mm/s or N, of a grid axis or a recording: no stroke comes near

// ---- writing

void write_grid(h5::Group g, const TruthGrid& grid) {
  describe(g.write("speeds", grid.speeds_mm_s), "mm/s", "the grid's constant speeds, ascending");
  describe(g.write("forces", grid.forces_n), "N", "the grid's constant normal forces, ascending");
  describe(g.write_array<double>("spectrum", grid.spectra, {grid.speeds_mm_s.size(), grid.forces_n.size(), kBins}), "m/s^2",
           "expected single-sided amplitude spectrum 2|X_k|/N of 1000-sample windows, bins k = 1..100 (10..1000 Hz), "
           "noise-free, at each (speed, force)");
}

// float32 like the recordings file's channels: the action is compared with float32 recordings.
void write_action(h5::Group g, const char* name, const std::vector<double>& values, const char* units, const char* what) {
  describe(g.write(name, std::vector<float>(values.begin(), values.end())), units,
           std::string("noise-free ") + what + " the vibration was rendered along, one value per sample (before the sensors' ripple)");
}

void write_recordings(h5::Group material, const MaterialTruth& m) {
  h5::Group all = material.create_group(dataset::layout::kRecordings);
  for (const TruthRecording& r : m.recordings) {
    // The reader would refuse such a file: fail here, where the caller's mistake is.
    if (r.speed_mm_s.empty() || r.speed_mm_s.size() != r.force_n.size())
      throw failure("truth.h5: recording " + std::to_string(r.index) + " of " + m.name + " has " +
                    std::to_string(r.speed_mm_s.size()) + " speed and " + std::to_string(r.force_n.size()) + " force samples");
    h5::Group g = all.create_group(std::to_string(r.index));
    g.set_attr("source_sha256", r.source_sha256);
    write_action(g, "speed", r.speed_mm_s, "mm/s", "tangential speed");
    write_action(g, "force", r.force_n, "N", "normal force");
  }
}

// What generated the material: the model itself, or the recipe (whose grid follows).
void write_generator(h5::Group g, const MaterialTruth& m) {
  g.set_attr("generator", m.generator);
  if (m.generator == kHattModel) {
    g.set_attr("model_xml", m.model_xml);
    g.set_attr("model_sha256", sha256_hex(m.model_xml));
  } else if (m.generator == kSynthMaterial) {
    g.set_attr("recipe_json", m.recipe_json);
  } else {
    throw failure("truth.h5: material " + m.name + " has the unknown generator '" + m.generator + "'");
  }
}

// ---- reading

std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

bool is_sha256(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

// "0", "1", ... as the writer names recordings: no sign, no leading zero, no overflow.
bool is_index(const std::string& s) {
  return !s.empty() && s.size() <= 6 && (s == "0" || s[0] != '0') &&
         std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Every check names the object as schemas/hdf5-layout.md does ("/materials/brick_2/@generator"),
// and the fix is the same: the file is not what haptex synth writes, so write it again.
struct Reader {
  std::string path;
  mutable std::size_t total_samples = 0;  // speed samples read so far (kMostTotalSamples)

  Error error(const std::string& object, const std::string& what) const { return input_error(path, object, what, kRerun); }

  static std::string child(const h5::Node& node, const std::string& name) {
    return (node.object_path() == "/" ? "" : node.object_path()) + "/" + name;
  }

  h5::Group group(const h5::Group& parent, const std::string& name) const {
    if (!parent.has_group(name)) throw error(child(parent, name), parent.has(name) ? "is not a group" : "is missing");
    return parent.open_group(name);
  }

  std::string text(const h5::Node& node, const char* name) const {
    if (!node.has_attr(name)) throw error(child(node, std::string("@") + name), "is missing");
    return node.attr_string(name);
  }

  // Rates, noise levels, speeds, forces and amplitudes: none can be negative, and accelerations
  // (noise, spectra) stay within dataset::kLargestAccelerationMs2.
  double magnitude(const h5::Node& node, const char* name, bool positive = false, double largest = INFINITY) const {
    const std::string where = child(node, std::string("@") + name);
    if (!node.has_attr(name)) throw error(where, "is missing");
    const double v = node.attr_double(name);
    if (!std::isfinite(v) || v < 0 || (positive && v == 0) || v > largest)
      throw error(where, "is " + number_text(v) + ", expected a finite number " + (positive ? "above 0" : "of 0 or more") +
                             (std::isfinite(largest) ? " up to " + number_text(largest) : std::string()));
    return v;
  }

  h5::Dataset dataset(const h5::Group& g, const char* name, const char* dtype) const {
    if (!g.has_dataset(name)) throw error(child(g, name), g.has(name) ? "is not a dataset" : "is missing");
    const h5::Dataset d = g.open_dataset(name);
    if (d.dtype() != dtype) throw error(d.object_path(), "holds " + d.dtype() + ", expected " + dtype);
    return d;
  }

  template <typename T>
  std::vector<double> magnitudes(const h5::Dataset& d, double largest = INFINITY) const {
    const std::vector<T> v = d.read<T>();
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]) || v[i] < 0 || v[i] > largest)
        throw error(d.object_path(), "value " + std::to_string(i) + " is " + number_text(v[i]) + ", expected a finite number of 0 or more" +
                                         (std::isfinite(largest) ? " up to " + number_text(largest) : std::string()));
    return {v.begin(), v.end()};
  }

  // A 1-D dataset of 1..most values, or of exactly `length` values when that is given.
  template <typename T>
  std::vector<double> series(const h5::Group& g, const char* name, const char* dtype, hsize_t most,
                             std::optional<std::size_t> length, const char* length_reason = "", double largest = INFINITY) const {
    const h5::Dataset d = dataset(g, name, dtype);
    const h5::Shape shape = d.shape();
    if (length && shape != h5::Shape{*length})
      throw error(d.object_path(), "has shape " + h5::shape_text(shape) + ", expected (" + std::to_string(*length) + ")" + length_reason);
    if (shape.size() != 1 || shape[0] == 0 || shape[0] > most)
      throw error(d.object_path(), "has shape " + h5::shape_text(shape) + ", expected 1 to " + std::to_string(most) + " values");
    return magnitudes<T>(d, largest);
  }

  std::vector<double> axis(const h5::Group& g, const char* name) const {
    std::vector<double> v = series<double>(g, name, "float64", kMostGridPoints, std::nullopt);
    if (v.back() > kLargestAction)
      throw error(child(g, name), "value " + std::to_string(v.size() - 1) + " is " + number_text(v.back()) + ", over " +
                                      number_text(kLargestAction) + ", beyond any speed or force of a stroke");
    const auto low = std::adjacent_find(v.begin(), v.end(), std::greater_equal<>());
    if (low != v.end()) {
      const auto i = std::size_t(low - v.begin()) + 1;
      throw error(child(g, name), "value " + std::to_string(i) + " is " + number_text(v[i]) + ", not above the one before it (" +
                                      number_text(v[i - 1]) + "): the grid's axes must ascend");
    }
    return v;
  }

  TruthGrid grid(const h5::Group& g) const {
    TruthGrid grid{axis(g, "speeds"), axis(g, "forces"), {}};
    const h5::Dataset d = dataset(g, "spectrum", "float64");
    const h5::Shape expected{grid.speeds_mm_s.size(), grid.forces_n.size(), kBins};
    if (d.shape() != expected)
      throw error(d.object_path(), "has shape " + h5::shape_text(d.shape()) + ", expected " + h5::shape_text(expected) +
                                       " (speeds, forces, 100 bins)");
    grid.spectra = magnitudes<double>(d, dataset::kLargestAccelerationMs2);
    return grid;
  }

  TruthRecording recording(const h5::Group& recordings, const std::string& k) const {
    if (!is_index(k)) throw error(child(recordings, k), "is not a recording number (0, 1, 2, ...)");
    const h5::Group g = group(recordings, k);
    TruthRecording r;
    r.index = std::stoi(k);
    r.source_sha256 = text(g, "source_sha256");
    if (!is_sha256(r.source_sha256))
      throw error(child(g, "@source_sha256"), "is '" + r.source_sha256 + "', not a SHA-256 (64 lower-case hex digits)");
    // Review 9, F4: a speed of 3e38 mm/s moved the oracle floor fivefold, unremarked.
    r.speed_mm_s = series<float>(g, "speed", "float32", kMostSamples, std::nullopt, "", kLargestAction);
    total_samples += r.speed_mm_s.size();
    if (total_samples > kMostTotalSamples)
      throw error(child(g, "speed"), "brings the file past " + std::to_string(kMostTotalSamples) + " samples in all");
    r.force_n = series<float>(g, "force", "float32", kMostSamples, r.speed_mm_s.size(), ": one value per speed sample", kLargestAction);
    return r;
  }

  // The generator's own members: the model (checked against its hash), or the recipe.
  void generator(const h5::Group& g, MaterialTruth& m) const {
    m.generator = text(g, "generator");
    if (m.generator == kHattModel) {
      m.model_xml = text(g, "model_xml");
      if (text(g, "model_sha256") != sha256_hex(m.model_xml))
        throw error(child(g, "@model_sha256"), "is not the SHA-256 of @model_xml: the model text is damaged");
    } else if (m.generator == kSynthMaterial) {
      m.recipe_json = text(g, "recipe_json");
    } else {
      throw error(child(g, "@generator"), "is '" + m.generator + "', expected " + kHattModel + " or " + kSynthMaterial);
    }
  }

  MaterialTruth material(const h5::Group& materials, const std::string& id) const {
    const h5::Group g = group(materials, id);
    MaterialTruth m;
    m.name = text(g, "name");
    if (material_id(m.name) != id)
      throw error(child(g, "@name"), "is '" + m.name + "', whose id " + material_id(m.name) + " is not the group's name");
    generator(g, m);
    // A synthetic material's grid is required; a model's is optional (the model itself is its truth).
    if (m.generator == kSynthMaterial || g.has("speeds") || g.has("forces") || g.has("spectrum")) m.grid = grid(g);
    const h5::Group recordings = group(g, dataset::layout::kRecordings);
    for (const std::string& k : recordings.children()) m.recordings.push_back(recording(recordings, k));
    return m;
  }
};

}  // namespace

const MaterialTruth* Truth::find(const std::string& id) const {
  const auto it = std::find_if(materials.begin(), materials.end(), [&](const MaterialTruth& m) { return material_id(m.name) == id; });
  return it == materials.end() ? nullptr : &*it;
}

void write_truth_file(const std::string& path, const Truth& truth, const std::string& source) {
  h5::AtomicFile out(path, true, dataset::format_name(dataset::Kind::truth));
  h5::Group root = out.root();
  dataset::stamp(root, dataset::Kind::truth, source);
  root.set_attr("sample_rate_hz", truth.sample_rate_hz);
  root.set_attr("accel_noise_m_s2", truth.accel_noise_m_s2);
  h5::Group all = root.create_group(dataset::layout::kMaterials);
  for (const MaterialTruth& m : truth.materials) {
    h5::Group g = all.create_group(material_id(m.name));
    g.set_attr("name", m.name);
    write_generator(g, m);
    if (m.grid) write_grid(g, *m.grid);
    write_recordings(g, m);
  }
  out.commit();
}

Truth read_truth_file(const std::string& path) {
  const h5::File file = dataset::open_checked(path, dataset::Kind::truth);
  const h5::Group root = file.root();
  const Reader r{path};
  Truth truth;
  truth.sample_rate_hz = r.magnitude(root, "sample_rate_hz", true);
  truth.accel_noise_m_s2 = r.magnitude(root, "accel_noise_m_s2", false, dataset::kLargestAccelerationMs2);
  const h5::Group materials = r.group(root, dataset::layout::kMaterials);
  for (const std::string& id : materials.children()) truth.materials.push_back(r.material(materials, id));
  if (truth.materials.empty()) throw r.error("/materials", "holds no material");
  return truth;
}

}  // namespace haptex::dataset
