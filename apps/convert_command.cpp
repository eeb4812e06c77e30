// haptex convert hatt <files or directories> -o recordings.h5 [--map FILE] [--max-bytes N] [--force]
// haptex convert cluster <database folder> -o recordings.h5 [--names FILE] [--max-bytes N] [--force]
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>

#include "apps/output_options.hpp"
#include "apps/command.hpp"
#include "apps/number_checks.hpp"
#include "core/output_is_input.hpp"
#include "apps/terminal_progress.hpp"
#include "convert/convert_recordings.hpp"
#include "core/text/utf8.hpp"

namespace haptex::apps {
namespace {

class ConvertCommand : public Command {
 public:
  std::string name() const override { return "convert"; }
  std::string summary() const override { return "Turn vibration recordings into a haptex recordings file"; }

  void declare(CLI::App& app) override {
    app.require_subcommand(1);
    hatt_ = app.add_subcommand("hatt", "HaTT recorded-data XML and CSV recordings -> recordings.h5");
    hatt_->add_option("inputs", inputs_, "Recording files, or directories searched for *.xml, *.xml.gz and *.csv")->required();
    hatt_->add_option("--map", map_, "Field map JSON naming your files' elements (default: schemas/hatt-recording-map.json)");
    add_shared_options(*hatt_);

    cluster_ = app.add_subcommand("cluster", "Cluster Haptic Texture Database (sensor_data/ CSV takes) -> recordings.h5");
    cluster_->add_option("database", database_, "The database's folder (holding sensor_data/), or sensor_data itself")
        ->required();
    cluster_->add_option("--names", names_, "Texture names: JSON {\"0\": \"name\", ...} or CSV id,name (default: cluster N)");
    add_shared_options(*cluster_);
  }

  int run(const GlobalOptions& global) override {
    if (!map_.empty()) options_.map_path = map_;
    std::vector<std::string> inputs = cluster_->parsed() ? std::vector<std::string>{database_, names_} : inputs_;
    inputs.push_back(map_);
    refuse_output_among_inputs(output_, inputs);
    options_.provenance = global.command_line;
    const auto start = std::chrono::steady_clock::now();
    const auto result =
        cluster_->parsed()
            ? convert::convert_cluster(database_, output_, options_,
                                       names_.empty() ? std::nullopt : std::optional<std::string>(names_),
                                       terminal_progress(global, "convert"))
            : convert::convert_recordings(inputs_, output_, options_, terminal_progress(global, "convert"));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print(result, seconds, global);
    if (!global.quiet)
      for (const std::string& note : result.notes) std::cerr << "note: " << text::printable(note) << "\n";
    return 0;
  }

 private:
  // What every reader shares: the output, --force and the input size limit.
  void add_shared_options(CLI::App& sub) {
    add_output_options(sub, output_, options_.overwrite, "Recordings file to write (HDF5)");
    sub.add_option("--max-bytes", options_.max_bytes, "Refuse input files larger than this, or gzip files that expand to more")
        ->capture_default_str()
        ->check(positive_number());
  }

  void print(const convert::ConvertResult& result, double seconds, const GlobalOptions& global) const {
    std::size_t samples = 0;
    for (const auto& r : result.recordings) samples += r.samples;
    if (global.json) {
      nlohmann::json recordings = nlohmann::json::array();
      for (const auto& r : result.recordings)
        recordings.push_back({{"source", r.source}, {"material", r.material}, {"material_id", r.material_id},
                              {"recording", r.index}, {"samples", r.samples}});
      std::cout << nlohmann::json{{"output", output_}, {"recordings", recordings}, {"samples", samples},
                                  {"input_bytes", result.input_bytes}, {"seconds", seconds}}
                       .dump(2)
                << "\n";
      return;
    }
    if (global.quiet) return;
    if (global.verbose)
      for (const auto& r : result.recordings)
        std::cerr << text::printable(r.source) << " -> /materials/" << r.material_id << "/recordings/" << r.index << "\n";
    std::cout << "wrote " << text::printable(output_) << ": " << result.recordings.size() << " recordings, " << samples
              << " samples, in " << seconds << " s\n";
  }

  CLI::App *hatt_ = nullptr, *cluster_ = nullptr;
  std::vector<std::string> inputs_;
  std::string output_, map_, database_, names_;
  convert::ConvertOptions options_;
};

}  // namespace

std::unique_ptr<Command> make_convert_command() { return std::make_unique<ConvertCommand>(); }

}  // namespace haptex::apps
