#include "apps/output_options.hpp"

namespace haptex::apps {

void add_output_options(CLI::App& app, std::string& output, bool& force, const std::string& what) {
  app.add_option("-o,--output", output, what)->required();
  add_force_option(app, force);
}

void add_force_option(CLI::App& app, bool& force) {
  app.add_flag("--force", force,
               "Replace an output haptex wrote before (a file or folder that is not haptex's, or one of the inputs, is "
               "refused, never replaced)");
}

}  // namespace haptex::apps
