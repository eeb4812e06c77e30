#pragma once
// The AR refit's data: training signal cut into short segments labelled with their median speed
// and force, and the segments grouped by where they lie in the (speed, force) plane.
//
// Why group: HaTT fitted 5 to 36 models per surface from 10 s of data (14 on average), each from a
// longer stretch of steady pressing and stroking; 10 s of 0.1 s segments give ~90 labels, several
// of them nearly on top of each other where the stroke lingers, and a lone segment's fit carries
// whatever transient it caught. So segments are binned on a cells x cells grid over the labels'
// bounding box and every occupied cell becomes one model, fitted from its segments together.
// The grid is kept fine (8 x 8 by default): on signals rendered from 6 published HaTT models,
// coarser grids (6 x 6, 4 x 4) cost up to 0.5 dB of spectral error at interior points (a cell
// then averages over operating points whose spectra differ), while one model per segment gained
// nothing over 8 x 8 (0.5 to 0.9 dB either way). Requiring several segments per model and
// merging sparser cells into neighbours was tried and dropped: with 10 s of data most cells
// hold one or two segments, and the merge collapsed the set to a handful of models (1.3 to 3.2 dB).
#include <cstddef>
#include <span>
#include <vector>

namespace haptex::evaluate {

// One contiguous stretch of training signal: one section of one recording (train or val set),
// 10 kHz, the three spans of equal length.
struct TrainingPiece {
  std::span<const double> accel;  // DFT321 acceleration, m/s^2
  std::span<const double> force;  // low-passed normal force, N
  std::span<const double> speed;  // low-passed tangential speed, mm/s
};

struct LabelledSegment {
  std::size_t piece = 0;  // index of its piece
  std::size_t start = 0;  // first sample, within the piece
  double speed = 0.0;     // median speed over the segment, mm/s
  double force = 0.0;     // median force over the segment, N
};

struct SegmentCut {
  std::vector<LabelledSegment> segments;  // the usable ones, in piece and time order
  std::size_t total_samples = 0;          // over all pieces
  std::size_t longest_piece = 0;          // samples
  std::size_t silent = 0;   // skipped: acceleration identically zero, or a value not finite
  std::size_t at_rest = 0;  // skipped: median speed or force under 0.05 (HaTT renders those as zero)
};

// Cuts every piece from its start into non-overlapping segments of `length` samples; a shorter
// tail is dropped, so no segment crosses a piece boundary. Throws haptex::Error when length is 0
// or a piece's spans differ in length.
SegmentCut cut_segments(std::span<const TrainingPiece> pieces, std::size_t length);

struct SegmentGroup {
  std::vector<std::size_t> members;  // indices into the segments, increasing
  double speed = 0.0;                // median of the members' speed labels, mm/s
  double force = 0.0;                // median of the members' force labels, N
};

// Bins the labels on a cells_per_axis x cells_per_axis grid over their bounding box (an axis
// with no extent has one cell); every occupied cell is one group. Groups come in grid order
// (force rows, then speed columns). Throws haptex::Error for no segments or cells_per_axis == 0.
std::vector<SegmentGroup> group_segments(std::span<const LabelledSegment> segments, std::size_t cells_per_axis);

}  // namespace haptex::evaluate
