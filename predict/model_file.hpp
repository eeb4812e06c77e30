#pragma once
// The model file (haptex_format model/3; schemas/hdf5-layout.md): weights, normalisation
// statistics, the texture descriptor's spec, the training options and metrics, and the hashes of
// the dataset and split it was trained on. Plain float32 arrays and attributes, so numpy can run
// the network from it.
#include <optional>
#include <string>

#include "core/h5/atomic_file.hpp"
#include "predict/model.hpp"

namespace haptex::predict {

// 2: the action at the window's middle, a new press recognised (1: the action before the window).

// Written to a temporary name and renamed (core/h5/atomic_file.hpp). Throws haptex::Error (bad_input)
// when the output exists and overwrite is false.
void write_model(const Model& model, const std::string& path, bool overwrite, const std::string& source);
// The model into `out`, not committed: for a command whose outputs appear together.
void write_model(const Model& model, h5::AtomicFile& out, const std::string& source);

// Throws haptex::Error (bad_input) naming the file and the object when it is not a model file or
// its arrays disagree in size.
Model read_model(const std::string& path);

// A model's record of its training log (docs/architecture.md, "Outputs are atomic"): the log's path
// and its SHA-256 as written, so that --force over the model retires that log while it is those bytes.
struct TrainingLogRecord {
  std::string log;  // as a path from here (stored relative to the model's folder)
  std::string sha256;
};
// Records `record` in the model `out` will be at `model_path`.
void record_training_log(h5::AtomicFile& out, const std::string& model_path, const TrainingLogRecord& record);
// The record of the model file at `path`, or nothing when it records none or is no readable model file.
std::optional<TrainingLogRecord> recorded_training_log(const std::string& path);

}  // namespace haptex::predict
