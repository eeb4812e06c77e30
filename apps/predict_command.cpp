// haptex predict model.h5 (--image IMG [--reference REF] | --material ID) (--normal-force F --speed V | --csv FILE) [--json]
#include <cstdio>
#include <iostream>

#include "apps/input_file_option.hpp"
#include "apps/command.hpp"
#include "core/text/format.hpp"
#include "core/error.hpp"
#include "dataset/window.hpp"
#include "predict/model_file.hpp"
#include "predict/predictor.hpp"
#include "predict/texture_choice.hpp"
#include "predict/trajectory.hpp"

namespace haptex::apps {
namespace {

struct Query {
  std::size_t sample = 0;
  float force = 0, speed = 0;
  bool out_of_range = false;
  std::vector<float> spectrum;
};

class PredictCommand : public Command {
 public:
  std::string name() const override { return "predict"; }
  std::string summary() const override { return "Predict the vibration spectrum for a texture image and a force and speed"; }

  void declare(CLI::App& app) override {
    app.add_option("model", model_path_, "Model file (haptex train)")->required()->check(input_file());
    auto* image = app.add_option("--image", image_, "GelSight press image (PNG/JPEG), unified models")->check(input_file());
    app.add_option("--reference", reference_, "The sensor's no-contact frame for --image")->check(input_file())->needs(image);
    auto* material = app.add_option("--material", material_, "A training material's id instead of an image")->excludes(image);
    auto* force = app.add_option("--normal-force", force_, "Normal force, N")->check(CLI::Range(0.0, 1e6));
    // --force means "replace the output" in every other command: here it is refused, naming the new option.
    app.add_option("--force", old_force_)->group("");
    auto* speed = app.add_option("--speed", speed_, "Tangential speed, mm/s")->check(CLI::Range(0.0, 1e9));
    auto* csv = app.add_option("--csv", csv_, "Force/speed trajectory at 10 kHz: columns force, speed (time_s optional)")
                    ->check(input_file())->excludes(force)->excludes(speed);
    app.add_option("--hop", hop_, "Samples between predictions along --csv (the model's window step)")->capture_default_str()->check(CLI::Range(1, 100000));
    // --normal-force and --speed go together: checked in run(), after the old --force spelling is named.
    (void)material;
    (void)csv;
  }

  int run(const GlobalOptions& global) override {
    if (!old_force_.empty())
      throw input_error("--force", "", "predict takes the normal force as --normal-force (N); --force means \"replace the output\" in "
                                       "every other command",
                        "Write --normal-force " + old_force_);
    if (csv_.empty() && (force_ < 0 || speed_ < 0))
      throw Error(Error::Kind::bad_input, "predict: give --normal-force and --speed, or a trajectory with --csv");
    if (image_.empty() && material_.empty()) throw Error(Error::Kind::bad_input, "predict: give --image (and --reference) or --material");
    const predict::Model model = predict::read_model(model_path_);
    predict::Predictor predictor(model);
    const predict::TextureCode code = texture(predictor);
    std::vector<Query> queries;
    using dataset::kActionSamples, dataset::kActionValues;
    float action[kActionValues];
    if (csv_.empty()) {
      std::fill(action, action + kActionSamples, float(force_));
      std::fill(action + kActionSamples, action + kActionValues, float(speed_));
      queries.push_back(query(predictor, code, action, 0));
    } else {
      const predict::Trajectory t = predict::read_trajectory(csv_);
      for (std::size_t s = 0; s < t.force.size(); s += std::size_t(hop_)) {
        predict::action_at(t, s, action);
        queries.push_back(query(predictor, code, action, s));
      }
    }
    if (global.json)
      print_json(model, code, queries);
    else if (!csv_.empty())
      print_csv(queries);
    else
      print_table(queries.front(), global);
    return 0;
  }

 private:
  predict::TextureCode texture(const predict::Predictor& predictor) {
    return predict::choose_texture(predictor, model_path_, {material_, image_, reference_}, &descriptor_);
  }

  static Query query(predict::Predictor& predictor, const predict::TextureCode& code, const float* action, std::size_t sample) {
    using dataset::kActionSamples, dataset::kActionValues;
    Query q{sample, action[kActionSamples - 1], action[kActionValues - 1], false, std::vector<float>(dataset::kTargetBins)};
    q.out_of_range = predictor.predict(code, std::span<const float>(action, kActionValues), q.spectrum);
    return q;
  }

  void print_table(const Query& q, const GlobalOptions& global) const {
    if (q.out_of_range && !global.quiet)
      std::cerr << "note: force " << q.force << " N or speed " << q.speed
                << " mm/s lies outside the training range; the model saturated it to the nearest trained value\n";
    if (reference_.empty() && !image_.empty() && !global.quiet)
      std::cerr << "note: no --reference: the image's own blur stands in for the no-contact frame\n";
    std::cout << text::format("frequency_hz,amplitude_m_s2\n");
    for (std::size_t k = 0; k < q.spectrum.size(); ++k) std::cout << text::format("%d,%.6g\n", int(double(k + 1) * dataset::kBinHz), double(q.spectrum[k]));
  }

  static void print_csv(const std::vector<Query>& queries) {
    std::cout << text::format("sample,time_s,force_n,speed_mm_s,out_of_range");
    for (std::size_t k = 1; k <= dataset::kTargetBins; ++k) std::cout << text::format(",a_%dhz", int(double(k) * dataset::kBinHz));
    std::cout << text::format("\n");
    for (const Query& q : queries) {
      std::cout << text::format("%zu,%.4f,%.6g,%.6g,%d", q.sample, double(q.sample) * 1e-4, double(q.force), double(q.speed), q.out_of_range ? 1 : 0);
      for (float a : q.spectrum) std::cout << text::format(",%.6g", double(a));
      std::cout << text::format("\n");
    }
  }

  void print_json(const predict::Model& model, const predict::TextureCode& code, const std::vector<Query>& queries) const {
    nlohmann::json out = {{"model", model_path_}, {"variant", predict::variant_name(model.variant)},
                          {"frequencies_hz", nlohmann::json::array()}, {"queries", nlohmann::json::array()}};
    for (std::size_t k = 1; k <= dataset::kTargetBins; ++k) out["frequencies_hz"].push_back(int(double(k) * dataset::kBinHz));
    if (!material_.empty()) out["material"] = material_;
    if (!image_.empty()) out["image"] = image_, out["reference"] = reference_.empty() ? nlohmann::json(nullptr) : nlohmann::json(reference_);
    if (!descriptor_.empty()) out["descriptor"] = descriptor_;
    if (code.latent.size()) out["latent"] = std::vector<float>(code.latent.data(), code.latent.data() + code.latent.size());
    if (code.image_latent.size())
      out["image_latent"] = std::vector<float>(code.image_latent.data(), code.image_latent.data() + code.image_latent.size());
    for (const Query& q : queries)
      out["queries"].push_back({{"sample", q.sample}, {"force_n", q.force}, {"speed_mm_s", q.speed}, {"out_of_range", q.out_of_range},
                                {"spectrum", q.spectrum}});
    std::cout << out.dump(2) << "\n";
  }

  std::string model_path_, image_, reference_, material_, csv_;
  double force_ = -1, speed_ = -1;
  std::string old_force_;
  int hop_ = 100;
  std::vector<float> descriptor_;
};

}  // namespace

std::unique_ptr<Command> make_predict_command() { return std::make_unique<PredictCommand>(); }

}  // namespace haptex::apps
