#pragma once
// A small HaTT model set for tests: four AR(5) models on the corners of [0, 100] mm/s x [0, 2] N in
// two triangles, only the (100 mm/s, 2 N) corner excited (variance 0.5), poles close to the unit
// circle (radius up to 0.99972), and corners whose coefficients could not be blended stably.
#include "core/ar/piecewise_model.hpp"

namespace haptex::test {

extern const char* const kArFixtureXml;  // the model file's text

ar::PiecewiseArModel ar_fixture();

}  // namespace haptex::test
