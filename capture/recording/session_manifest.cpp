#include "capture/recording/session_manifest.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "capture/device/fourcc.hpp"
#include "capture/device/usb_bandwidth.hpp"
#include "capture/recording/delivered_rate.hpp"
#include "core/content_mark.hpp"
#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "core/naming.hpp"
#include "core/version.hpp"

namespace haptex::capture {
namespace {

nlohmann::json locked_array(const ControlLock& controls) {
  nlohmann::json locked = nlohmann::json::array();
  for (const auto& c : controls.locked)
    locked.push_back({{"name", c.name}, {"id", c.id}, {"value", c.value}, {"requested", c.requested}});
  return locked;
}

nlohmann::json press_json(const RecordedPress& p) {
  return {{"index", p.index},
          {"file", p.file},
          {"take_first_frame", p.take_first_frame},
          {"take_last_frame", p.take_last_frame},
          {"contact_first", p.contact_first},
          {"contact_last", p.contact_last},
          {"peak_frame", p.peak_frame},
          {"first_sequence", p.first_sequence},
          {"last_sequence", p.last_sequence},
          {"frames", p.frames},
          {"dropped_frames", p.dropped_frames},
          {"error_frames", p.error_frames},
          {"corrupt_frames", p.corrupt_frames},
          {"sha256", p.sha256},
          {"ended_by", p.ended_by}};
}

double mbit(double bytes_per_second) { return bytes_per_second * 8 / 1e6; }

nlohmann::json usb_link_json(const SessionDescription& s) {
  nlohmann::json link = {{"speed_mbps", *s.link.speed_mbps},
                         {"video_capacity_mbps", mbit(isochronous_bytes_per_second(*s.link.speed_mbps))}};
  if (s.link.version) link["version"] = *s.link.version;
  if (const auto budget = link_budget(s.format, s.link)) link["stream_mbps_estimate"] = mbit(budget->needed);
  return link;
}

nlohmann::json totals_json(const TakeTotals& t) {
  nlohmann::json totals = {{"frames", t.frames}, {"dropped_frames", t.dropped_frames}, {"error_buffers", t.error_buffers},
                           {"corrupt_frames", t.corrupt_frames}, {"poll_timeouts", t.poll_timeouts},
                           {"max_queue_depth", t.max_queue_depth}, {"wall_seconds", t.wall_seconds},
                           {"cpu_seconds", t.cpu_seconds}};
  if (t.delivered_fps) {
    totals["delivered_fps"] = *t.delivered_fps;
    totals["timestamp_span_seconds"] = t.timestamp_span_seconds;
  }
  return totals;
}

}  // namespace

std::string delivery_warning(const SessionDescription& s, const TakeTotals& t) {
  if (!t.delivered_fps) return "";
  return slow_delivery_warning({s.identity.path, *t.delivered_fps, s.format.fps(), t.timestamp_span_seconds, t.frames,
                                t.dropped_frames, t.error_buffers});
}

std::string locked_controls_json(const ControlLock& controls) { return locked_array(controls).dump(); }
std::string missing_controls_json(const ControlLock& controls) { return nlohmann::json(controls.missing).dump(); }

nlohmann::json session_manifest(const SessionDescription& s, const ReferenceSummary& r,
                                const std::vector<RecordedPress>& presses, const TakeTotals& t,
                                const std::string& ended_by, const std::string& error) {
  nlohmann::json press_list = nlohmann::json::array();
  for (const auto& p : presses) press_list.push_back(press_json(p));
  nlohmann::json doc = {
      {"format", kSessionManifestFormat},
      {"haptex_version", kVersion},
      {"created_utc", h5::utc_now_iso8601()},
      {"command", s.command},
      {"material", s.material},
      {"material_id", material_id(s.material)},
      {"device", {{"node", s.identity.path}, {"card", s.identity.card}, {"driver", s.identity.driver},
                  {"bus_info", s.identity.bus_info}, {"serial", s.serial}}},
      {"stream", {{"fourcc", fourcc_text(s.format.fourcc)}, {"width", s.format.width}, {"height", s.format.height},
                  {"requested_fps", s.format.requested_fps}, {"granted_fps", s.format.fps()}, {"buffers", s.buffers}}},
      {"controls", {{"locked", locked_array(s.controls)}, {"missing", s.controls.missing}}},
      {"recorder", {{"warmup_frames", s.warmup_frames}, {"reference_frames", s.reference_frames},
                    {"pre_frames", s.pre_frames}, {"post_frames", s.post_frames}, {"noise", r.noise},
                    {"pixel_threshold", r.pixel_threshold}, {"no_contact_level", r.level}, {"trigger", r.trigger}, {"release", r.release},
                    {"reference_restarts", r.restarts}}},
      {"presses", press_list},
      {"totals", totals_json(t)},
      {"ended_by", ended_by}};
  if (!s.model.empty()) doc["device"]["model"] = s.model;
  if (s.link.speed_mbps) doc["device"]["usb_link"] = usb_link_json(s);
  nlohmann::json warnings = nlohmann::json::array();
  for (const std::string& w : {s.link_warning, delivery_warning(s, t)})
    if (!w.empty()) warnings.push_back(w);
  doc["warnings"] = warnings;
  if (!error.empty()) doc["error"] = error;
  return doc;
}

void write_session_manifest(const std::string& path, const nlohmann::json& manifest) {
  // Rewritten after every press: the take's own file in its own folder, replaced without a check (a file
  // system that keeps no extended attributes has no mark to check: review 22, F5 cut takes short so).
  // Marked, so that a later --force replaces it only while it holds what haptex wrote
  // (session_folder.cpp, core/content_mark.hpp; review 21, F6): a check given marks the file.
  PartialFile out(path, true, [](const std::string&) {});
  json::write_file(manifest, "capture-session.schema.json", out);
  out.commit();
}

}  // namespace haptex::capture
