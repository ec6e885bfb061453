#pragma once
// The link's view of the autopilot as kestrel's AutopilotStatus message, and the rule that says
// whether the link is up: a heartbeat from the autopilot within the timeout.
#include <kestrel/messages/autopilot_status.hpp>

#include "link.hpp"

namespace kestrel::mavlink {

bool link_up(const VehicleView& view, LinkClock::time_point now, double heartbeat_timeout_s);

msg::AutopilotStatus autopilot_status(const VehicleView& view, LinkClock::time_point now, double heartbeat_timeout_s);

}  // namespace kestrel::mavlink
