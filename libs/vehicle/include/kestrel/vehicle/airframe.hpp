#pragma once
// A hunter's airframe, named once and read by every node that flies or plans for it: the body
// the simulators fly (mass, inertia, rotors, motors), the Lee controller's gains tuned for it,
// and the flight envelope the aim plans within. A graph picks it by name (`airframe: interceptor`
// on quadrotor_sim, lee_controller, sim_autopilot and aim_planner), as PX4 picks an airframe.
//
//   firefly      the paper's: RotorS' AscTec Firefly hexacopter, 1.57 kg, thrust-to-weight 2.3
//   interceptor  a racing-class quadrotor, 1.0 kg, thrust-to-weight 4.5, 20 m/s
#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/vehicle/multirotor.hpp"

namespace kestrel::vehicle {

/// Lee's geometric controller gains (Lee, Leok & McClamroch 2010), per axis.
struct LeeGainSet {
  Eigen::Vector3d position{6.0, 6.0, 6.0};         ///< k_x, N/m
  Eigen::Vector3d velocity{4.7, 4.7, 4.7};         ///< k_v, N s/m
  Eigen::Vector3d attitude{3.0, 3.0, 0.15};        ///< k_R, N m/rad
  Eigen::Vector3d angular_rate{0.52, 0.52, 0.18};  ///< k_Omega, N m s/rad
};

/// What the airframe can fly: the aim plans within it, the controller tilts no further.
struct FlightEnvelope {
  double max_speed_m_s = 5.0;
  double max_acceleration_m_s2 = 4.0;  ///< horizontal, held at level height
  double max_tilt_deg = 60.0;
};

struct Airframe {
  std::string name;
  Multirotor body;
  LeeGainSet gains;
  FlightEnvelope envelope;
};

/// The airframe of that name; throws kestrel::Error naming the known ones otherwise.
const Airframe& airframe(std::string_view name);
/// The names, for a parameter's allowed values.
std::vector<std::string> airframe_names();

}  // namespace kestrel::vehicle
