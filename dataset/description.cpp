#include "dataset/description.hpp"

#include "dataset/layout.hpp"

namespace haptex::dataset {

h5::Dataset describe(h5::Dataset d, const std::string& units, const std::string& description) {
  if (!units.empty()) d.set_attr(layout::kUnits, units);
  d.set_attr(layout::kDescription, description);
  return d;
}

}  // namespace haptex::dataset
