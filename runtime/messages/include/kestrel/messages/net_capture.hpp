#pragma once
// An intruder caught in the net: from this moment it is tangled, stops flying and falls.
#include <Eigen/Core>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct NetCapture {
  Time stamp{0};                                             ///< when the net closed on it
  std::uint64_t object_id = 0;                               ///< the intruder's ground-truth id
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();  ///< where it was caught
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::NetCapture, "kestrel.NetCapture", "an intruder caught in the net: which, when and where");
KESTREL_MESSAGE_FIELDS(kestrel::msg::NetCapture, {"stamp", "Time", "ns", "", "when the net closed on it"},
                       {"object_id", "uint64", "", "", "the intruder's ground-truth id"},
                       {"position_world", "Eigen::Vector3d", "m", "world", "where it was caught"});
