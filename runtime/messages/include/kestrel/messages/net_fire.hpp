#pragma once
// The order to fire the net: the aim held long enough within the net's capture radius.
#include <Eigen/Core>

#include "kestrel/message.hpp"

namespace kestrel::msg {

struct NetFire {
  Time stamp{0};                                          ///< when the order is given
  std::uint64_t target_id = 0;                            ///< the track aimed at
  Eigen::Vector3d aim_error_m = Eigen::Vector3d::Zero();  ///< x_E^d - x_E at the order, camera frame
};

}  // namespace kestrel::msg

KESTREL_MESSAGE(kestrel::msg::NetFire, "kestrel.NetFire", "order to fire the net, with the target and the aim error");
KESTREL_MESSAGE_FIELDS(kestrel::msg::NetFire, {"stamp", "Time", "ns", "", "when the order is given"},
                       {"target_id", "uint64", "", "", "id of the track aimed at"},
                       {"aim_error_m", "Eigen::Vector3d", "m", "camera", "x_E^d - x_E when the order is given"});
