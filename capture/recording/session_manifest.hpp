#pragma once
// session.json beside the press files (schemas/capture-session.schema.json): the device, its serial
// and USB link, the granted format and rate, the locked controls, the thresholds, per press its frame
// ranges and losses, the rate the take delivered, and warnings. Rewritten after every press, so an
// interrupted take still describes what it saved.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "capture/device/camera_controls.hpp"
#include "capture/device/format_negotiation.hpp"
#include "capture/device/usb_discovery.hpp"
#include "capture/device/v4l2_device.hpp"

namespace haptex::capture {

inline constexpr const char* kSessionManifestFormat = "capture-session/1";  // schemas/capture-session.schema.json

struct SessionDescription {
  std::string command, material;
  DeviceIdentity identity;
  std::string serial, model;
  StreamFormat format;
  UsbLink link;              // unknown for the fake camera and nodes sysfs does not place on USB
  std::string link_warning;  // usb_bandwidth.hpp: the mode exceeds the link; empty when it fits or is unknown
  unsigned buffers = 0;
  ControlLock controls;
  int warmup_frames = 0, reference_frames = 0, pre_frames = 0, post_frames = 0;
};

struct ReferenceSummary {
  float noise = 0, pixel_threshold = 0, level = 0, trigger = 0, release = 0;
  int restarts = 0;  // references refused as not steady (the sensor was touched) before this one
};

struct RecordedPress {
  int index = 0;
  std::string file;  // name inside the session folder
  std::int64_t take_first_frame = 0, take_last_frame = 0;
  std::int64_t contact_first = -1, contact_last = -1, peak_frame = -1;  // take frame numbers
  std::uint32_t first_sequence = 0, last_sequence = 0;
  std::uint64_t frames = 0, dropped_frames = 0, error_frames = 0, corrupt_frames = 0;
  std::string ended_by;
  std::string sha256;  // of the press file as saved: --force replaces only this file (session_folder.cpp)
};

struct TakeTotals {
  std::uint64_t frames = 0, dropped_frames = 0, error_buffers = 0, corrupt_frames = 0, poll_timeouts = 0,
                max_queue_depth = 0;
  double wall_seconds = 0, cpu_seconds = 0;
  // The rate the driver delivered (delivered_rate.hpp), once the take is over and long enough.
  std::optional<double> delivered_fps;
  double timestamp_span_seconds = 0;  // first frame to last, by the driver's timestamps
};

// The end-of-take warning when the take delivered clearly fewer frames than granted; empty otherwise.
std::string delivery_warning(const SessionDescription& session, const TakeTotals& totals);

nlohmann::json session_manifest(const SessionDescription& session, const ReferenceSummary& reference,
                                const std::vector<RecordedPress>& presses, const TakeTotals& totals,
                                const std::string& ended_by, const std::string& error = {});
// Validates against the schema, writes path.partial, syncs and renames.
void write_session_manifest(const std::string& path, const nlohmann::json& manifest);
// JSON text of the locked controls and of the missing ones, as press files store them.
std::string locked_controls_json(const ControlLock& controls);
std::string missing_controls_json(const ControlLock& controls);

}  // namespace haptex::capture
