#pragma once
// Counts frames lost between two delivered frames. A gap in the driver's sequence numbers is a
// lost frame; so is a timestamp gap of more than 1.5 nominal periods (some drivers do not count
// frames the sensor never sent). The larger of the two counts, so no loss is counted twice.
#include <cstdint>

namespace haptex::capture {

class DropCounter {
 public:
  explicit DropCounter(double period_ns) : period_ns_(period_ns) {}

  // Returns how many frames were lost just before this one. `flagged`: buffers the driver returned
  // flagged as errors since the previous frame (counted apart as error buffers): the sequence numbers
  // they used are no loss.
  std::uint64_t observe(std::uint32_t sequence, std::int64_t timestamp_ns, std::uint64_t flagged = 0);

  std::uint64_t dropped() const { return dropped_; }
  std::uint64_t sequence_gaps() const { return sequence_gaps_; }    // losses the sequence numbers showed
  std::uint64_t timestamp_gaps() const { return timestamp_gaps_; }  // extra losses only the clock showed

 private:
  double period_ns_;
  bool first_ = true;
  std::uint32_t last_sequence_ = 0;
  std::int64_t last_timestamp_ns_ = 0;
  std::uint64_t dropped_ = 0, sequence_gaps_ = 0, timestamp_gaps_ = 0;
};

}  // namespace haptex::capture
