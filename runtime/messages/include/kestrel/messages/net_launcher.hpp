#pragma once
// The net launcher's state: how many nets it still carries and when it can fire again. The aim
// reads it to spend its last nets on good shots only.
#include <cstdint>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct NetLauncher {
  Time stamp{0};                ///< when this state began (a shot, or the start)
  std::int64_t nets_left = -1;  ///< nets still loaded; -1: unlimited
  std::int64_t nets_used = 0;   ///< nets fired so far
  Time ready_at{0};             ///< it cannot fire before this (reloading)
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::NetLauncher, "kestrel.NetLauncher",
                "the net launcher's state: nets left and when it can fire again");
KESTREL_MESSAGE_FIELDS(kestrel::msg::NetLauncher, {"stamp", "Time", "ns", "", "when this state began"},
                       {"nets_left", "int64", "", "", "nets still loaded; -1: unlimited"},
                       {"nets_used", "int64", "", "", "nets fired so far"},
                       {"ready_at", "Time", "ns", "", "it cannot fire before this (reloading)"});
