#include "tests/support/quick_models.hpp"

#include <stdexcept>

#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"

namespace haptex::test {

const std::vector<std::string>& quick_train_options() {
  static const std::vector<std::string> options = {"--epochs", "4", "--latent", "8", "--hidden", "16"};
  return options;
}

std::vector<std::string> quick_train_args(const std::string& dataset, const std::string& split, const std::string& model,
                                          bool per_material) {
  std::vector<std::string> args = {"train", dataset, "--split", split, "-o", model};
  args.insert(args.end(), quick_train_options().begin(), quick_train_options().end());
  if (per_material) args.push_back("--per-material");
  return args;
}

const std::string& quick_model(bool per_material) {
  static const TempDir dir;
  auto train = [](const std::string& path, bool per) {
    const CommandResult r = run_haptex(quick_train_args(small_pipeline().dataset, small_pipeline().split, path, per));
    if (r.exit_code != 0) throw std::runtime_error("haptex train failed: " + r.err);
    return path;
  };
  if (!per_material) {
    static const std::string unified = train(dir.file("unified.h5"), false);
    return unified;
  }
  static const std::string per = train(dir.file("per_material.h5"), true);
  return per;
}

}  // namespace haptex::test
