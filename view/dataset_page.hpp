#pragma once
// `haptex view dataset.h5 [--split split.json] -o SITE/`: the dataset as one page a user looks at before
// any model exists (docs/view.md). Per material: each press's peak frame and its frames around the
// peak (the contact sheet), the force-speed coverage of its windows coloured by train, validation and
// test (with a split), their mean spectrum, and the start of each recording's vibration to listen to.
#include <optional>
#include <string>

#include "split/split_windows.hpp"

namespace haptex::view {

// Start of each recording played (10 kHz samples), and the widths of the press images.
inline constexpr std::size_t kClipSamples = 30000;  // 3 s
inline constexpr int kPeakWidth = 240, kFrameWidth = 80;
// Points of a material's coverage chart at most (every window when fewer).
inline constexpr std::size_t kMostPoints = 3000;

// The page's HTML (page/html_page.hpp: self-contained, with the load check). Throws haptex::Error
// (bad_input) naming the file and the object when the dataset is not one haptex can read.
std::string dataset_page(const std::string& dataset_path, const std::optional<split::DatasetSplit>& split);

}  // namespace haptex::view
