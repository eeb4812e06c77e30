// haptex capture devices | record | extract: GelSight-type sensors, from USB to the gelsight file.
#include <vector>

#include "apps/capture_subcommands.hpp"

namespace haptex::apps {
namespace {

class CaptureCommand : public Command {
 public:
  std::string name() const override { return "capture"; }
  std::string summary() const override { return "Find tactile sensors, record presses, extract peak frames"; }

  void declare(CLI::App& app) override {
    app.require_subcommand(1);
    parts_.push_back(make_capture_devices());
    parts_.push_back(make_capture_record());
    parts_.push_back(make_capture_extract());
    for (auto& part : parts_) apps_.push_back(part->declare(app));
  }

  int run(const GlobalOptions& global) override {
    for (std::size_t i = 0; i < parts_.size(); ++i)
      if (apps_[i]->parsed()) return parts_[i]->run(global);
    return 2;
  }

  bool ends_on_signals_itself() const override {
    for (std::size_t i = 0; i < parts_.size(); ++i)
      if (apps_[i]->parsed()) return parts_[i]->ends_on_signals_itself();
    return false;
  }

 private:
  std::vector<std::unique_ptr<CaptureSubcommand>> parts_;
  std::vector<CLI::App*> apps_;
};

}  // namespace

std::unique_ptr<Command> make_capture_command() { return std::make_unique<CaptureCommand>(); }

}  // namespace haptex::apps
