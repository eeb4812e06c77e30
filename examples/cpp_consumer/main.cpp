// Reads a dataset's window table and predicts the spectrum of its first window with a model, as a
// program of one's own would (docs/library.md). Prints the window count, the window's material, the
// size of its first press's peak image as PNG (through media/'s codecs plugin) and the predicted
// spectrum, one value per line.
#include <cstdio>
#include <vector>

#include "core/error.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/press_images.hpp"
#include "dataset/window_table.hpp"
#include "predict/model_file.hpp"
#include "predict/predictor.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: consumer dataset.h5 model.h5\n");
    return 2;
  }
  try {
    namespace dataset = haptex::dataset;
    const haptex::h5::File file = dataset::open_checked(argv[1], dataset::Kind::dataset);
    const dataset::WindowTable windows = dataset::read_window_table(file);
    const haptex::predict::Model model = haptex::predict::read_model(argv[2]);
    haptex::predict::Predictor predictor(model);
    const std::string& material = windows.materials.at(std::size_t(windows.material.at(0)));
    const int index = model.material_index(material);
    if (index < 0) throw haptex::Error(haptex::Error::Kind::bad_input, std::string(argv[2]) + " has no material " + material);
    std::vector<float> spectrum(dataset::kTargetBins);
    predictor.predict(predictor.material_code(index), windows.action_of(0), spectrum);
    const haptex::h5::Group press =
        file.root().open_group(dataset::layout::kMaterials).open_group(material).open_group(dataset::layout::kPresses).open_group("0");
    const std::size_t png = dataset::encode_png(dataset::read_press_image(press, dataset::layout::kPeak)).size();
    std::printf("windows %zu\nmaterial %s\npeak png %zu bytes\n", windows.size(), material.c_str(), png);
    for (const float a : spectrum) std::printf("%.9g\n", double(a));
  } catch (const haptex::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
  return 0;
}
