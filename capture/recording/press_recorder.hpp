#pragma once
// `haptex capture record`: one take from a sensor, cut live into one press file per press, plus the
// session manifest. Two threads: the capture thread only waits for frames, copies them out of the
// driver's buffers and queues the buffers again; the processing thread decodes, scores, segments and
// writes (take_processor.hpp). The capture thread never waits on the other, so a slow disk or decoder
// delays the files, never the driver.
//
// Ctrl-C (the stop flag), an unplugged sensor, a stall or the time limit end the take cleanly: the
// press being recorded is closed with every frame taken so far, and the manifest says how it ended.
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "capture/device/format_negotiation.hpp"
#include "capture/device/kernel_interface.hpp"
#include "capture/device/v4l2_stream.hpp"
#include "capture/recording/session_manifest.hpp"
#include "capture/recording/take_processor.hpp"
#include "core/progress.hpp"

namespace haptex::capture {

struct SessionRequest {
  std::string node;           // the capture node, /dev/videoN
  std::string serial, model;  // from USB discovery, when known
  UsbLink link;               // the sensor's USB link (sensor_discovery.hpp); unknown: nothing is judged
  FormatRequest format;
  std::map<std::uint32_t, std::int64_t> controls;  // by control ID
  unsigned buffers = 6;
  std::string output_dir;
  bool overwrite = false;               // replace the folder's old session (capture/recording/session_folder.hpp)
  std::vector<std::string> inputs;      // files the take reads (a replayed file): never replaced
  std::string command;  // provenance
};

struct RecordingResult {
  SessionDescription session;
  std::vector<RecordedPress> presses;
  TakeTotals totals;
  ReferenceSummary reference;
  std::string ended_by;  // presses, time limit, interrupted, disconnected, stalled, source ended (a replay)
  std::string manifest;
  std::string delivery_warning;  // the take delivered clearly fewer frames than granted; empty otherwise
  bool device_fault() const { return ended_by == "disconnected" || ended_by == "stalled"; }
};

// Told, before the take starts, what the user should know first: a mode the USB link cannot carry.
using Warn = std::function<void(const std::string&)>;

// Opens, negotiates, locks controls and records. Throws haptex::Error: bad_input for bad options,
// devices and output folders (before anything is written), failed when the work fails.
RecordingResult record_session(KernelInterface& kernel, const SessionRequest& request, const RecorderOptions& options,
                               const std::atomic<bool>* stop = nullptr, const Progress& progress = {},
                               const Warn& warn = {});

// The take alone, on a stream set up by the caller (tests and benchmarks use it directly).
RecordingResult record_take(V4l2Stream& stream, const SessionDescription& session, const std::string& output_dir,
                            const RecorderOptions& options, const std::atomic<bool>* stop = nullptr,
                            const Progress& progress = {});

void check_recorder_options(const RecorderOptions& options);

}  // namespace haptex::capture
