#pragma once
// Joining stretches of vibration that were not adjacent (report.html's clips run on over several test
// sections, docs/evaluate.md "report.html"): a bare join steps from one stretch's last sample to the
// next one's first, which a listener hears as a click. Two stretches of a texture's vibration are
// uncorrelated, so an equal-power fade (cos and sin) keeps their power level through the join, where a
// linear fade would dip it by 3 dB at the middle.
#include <cstddef>
#include <span>
#include <vector>

namespace haptex::signal {

// Appends piece to out, the last `fade` samples of out overlapping piece's first `fade` samples with
// weights cos and sin of (pi/2)(i + 1/2)/fade; the fade shrinks to what out and piece hold. An empty
// out takes piece as it is. out grows by piece.size() minus the overlap.
void append_crossfaded(std::vector<double>& out, std::span<const double> piece, std::size_t fade);

}  // namespace haptex::signal
