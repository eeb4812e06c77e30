// Reads a dataset's window table and predicts the spectrum of its first window with a model, as a
// program of one's own would (docs/library.md). Prints the window count, the window's material and
// the predicted spectrum, one value per line.
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "dataset/format.hpp"
#include "dataset/window_table.hpp"
#include "predict/model_file.hpp"
#include "predict/predictor.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: consumer dataset.h5 model.h5\n");
    return 2;
  }
  try {
    const haptex::dataset::WindowTable windows = haptex::dataset::read_window_table(haptex::dataset::open_checked(argv[1], haptex::dataset::Kind::dataset));
    const haptex::predict::Model model = haptex::predict::read_model(argv[2]);
    haptex::predict::Predictor predictor(model);
    const std::string& material = windows.materials.at(std::size_t(windows.material.at(0)));
    const int index = model.material_index(material);
    if (index < 0) throw haptex::Error(haptex::Error::Kind::bad_input, std::string(argv[2]) + " has no material " + material);
    std::vector<float> spectrum(haptex::dataset::kTargetBins);
    predictor.predict(predictor.material_code(index), windows.action_of(0), spectrum);
    std::printf("windows %zu\nmaterial %s\n", windows.size(), material.c_str());
    for (const float a : spectrum) std::printf("%.9g\n", double(a));
  } catch (const haptex::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
  return 0;
}
