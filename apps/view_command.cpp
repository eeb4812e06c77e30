// haptex view dataset.h5 [--split split.json] -o SITE [--force]
// The dataset as one page to look at and listen to before any model exists (docs/view.md).
#include <filesystem>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "apps/output_options.hpp"
#include "core/durable_file.hpp"
#include "core/output_is_input.hpp"
#include "core/partial_directory.hpp"
#include "core/text/utf8.hpp"
#include "split/manifest_reader.hpp"
#include "view/dataset_page.hpp"

namespace haptex::apps {
namespace {

class ViewCommand : public Command {
 public:
  std::string name() const override { return "view"; }
  std::string summary() const override {
    return "Write a dataset as one page: per material its presses, force-speed coverage, mean spectrum and recordings to listen to";
  }

  void declare(CLI::App& app) override {
    app.add_option("dataset", dataset_, "Dataset file (haptex align)")->required();
    app.add_option("--split", split_, "Split manifest (haptex split) of this dataset: colours the coverage by set");
    add_output_options(app, output_, force_, "Folder to write the page into (index.html)");
  }

  int run(const GlobalOptions& global) override {
    refuse_output_among_inputs(output_, {dataset_, split_});
    PartialDirectory site(output_, {force_, "page folder", "-o", "haptex view"});
    std::optional<split::DatasetSplit> split;
    if (!split_.empty()) split = split::read_dataset_split(dataset_, split::read_split_manifest(split_));
    const std::string html = view::dataset_page(dataset_, split);
    site.fill([&](const std::string& folder) { write_whole_file((std::filesystem::path(folder) / "index.html").string(), html); });
    site.commit();
    const std::string page = (std::filesystem::path(site.final_path()) / "index.html").string();
    if (global.json)
      std::cout << nlohmann::json{{"page", page}, {"bytes", html.size()}}.dump(2) << "\n";
    else if (!global.quiet)
      std::cout << "wrote " << text::printable(page) << " (" << html.size() / 1000 << " kB): open it in a browser\n";
    return 0;
  }

 private:
  std::string dataset_, split_, output_;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> make_view_command() { return std::make_unique<ViewCommand>(); }

}  // namespace haptex::apps
