#include "link_status.hpp"

#include "kestrel/mavlink/autopilot_modes.hpp"

namespace kestrel::mavlink {

namespace {
double age_s(const VehicleView& view, LinkClock::time_point now) {
  return view.heartbeat_at ? std::chrono::duration<double>(now - *view.heartbeat_at).count() : -1.0;
}
}  // namespace

bool link_up(const VehicleView& view, LinkClock::time_point now, double heartbeat_timeout_s) {
  return view.heartbeat_at && age_s(view, now) <= heartbeat_timeout_s;
}

msg::AutopilotStatus autopilot_status(const VehicleView& view, LinkClock::time_point now, double heartbeat_timeout_s) {
  msg::AutopilotStatus s;
  s.link_up = link_up(view, now, heartbeat_timeout_s);
  s.heartbeat_age_s = age_s(view, now);
  const AutopilotKind kind = autopilot_kind(view.heartbeat.autopilot);
  s.autopilot = view.heartbeat_at ? autopilot_name(kind) : "";
  s.armed = view.heartbeat_at && is_armed(view.heartbeat);
  s.mode = view.heartbeat_at ? mode_name(kind, view.heartbeat.custom_mode) : "";
  s.external_control = view.heartbeat_at && in_external_control(kind, view.heartbeat);
  s.custom_mode = view.heartbeat.custom_mode;
  s.system_status = view.heartbeat.system_status;
  s.landed_state = view.extended.landed_state;
  s.frames_received = view.parser.frames;
  s.frames_bad = view.parser.bad_checksum + view.parser.bad_flags;
  return s;
}

}  // namespace kestrel::mavlink
