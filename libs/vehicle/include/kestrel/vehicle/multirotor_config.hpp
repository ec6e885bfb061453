#pragma once
// The multirotor's parameters as a node declares them: the simulator and the controllers each
// bind this group into their config struct with one call, so the names, units, ranges and the
// Firefly defaults are written once. `airframe` names the vehicle (kestrel/vehicle/airframe.hpp);
// a field set to other than its (Firefly) default changes that airframe.
#include <Eigen/Core>
#include <kestrel/config_spec.hpp>
#include <string>

#include "kestrel/vehicle/airframe.hpp"
#include "kestrel/vehicle/multirotor.hpp"

namespace kestrel::vehicle {

struct MultirotorConfig {
  std::string airframe = "firefly";
  double mass_kg = 1.56779;
  Eigen::Vector3d inertia_kg_m2{0.0347563, 0.0458929, 0.0977};
  int rotor_count = 6;
  double first_rotor_angle_deg = 30.0;
  double arm_length_m = 0.215;
  double thrust_constant = 8.54858e-6;
  double moment_constant = 0.016;
  double motor_time_constant_up_s = 0.0125;
  double motor_time_constant_down_s = 0.025;
  double max_rotor_speed_rad_s = 838.0;
  double rotor_drag_coefficient = 8.06428e-5;

  /// The airframe's body, with each field set to other than its default in its place.
  Multirotor multirotor() const;
};

/// Declares the MultirotorConfig fields of `group` in c (RotorS Firefly defaults).
template <class Config>
void declare_multirotor(ConfigSpec<Config>& c, MultirotorConfig Config::*group) {
  using M = MultirotorConfig;
  c.param("airframe", group, &M::airframe)
      .describe(
          "the vehicle: firefly (the paper's hexacopter) or interceptor (a 1 kg quadrotor, thrust-to-weight 4.5); "
          "each parameter below set to other than its default (the Firefly's) changes it")
      .allowed = airframe_names();
  c.param("mass_kg", group, &M::mass_kg).with_unit("kg").range(0.01, 1000.0).describe("vehicle mass");
  c.param("inertia_kg_m2", group, &M::inertia_kg_m2)
      .with_unit("kg m^2")
      .range(1e-6, 1000.0)
      .describe("diagonal of the inertia about body x, y, z");
  c.param("rotor_count", group, &M::rotor_count)
      .range(4, 12)
      .describe("rotors, evenly spaced, alternating spin (the first counter-clockwise)");
  c.param("first_rotor_angle_deg", group, &M::first_rotor_angle_deg)
      .with_unit("deg")
      .range(-180.0, 180.0)
      .describe("angle of the first rotor from body x (forward), towards body y (left)");
  c.param("arm_length_m", group, &M::arm_length_m).with_unit("m").range(0.01, 10.0).describe("centre to rotor");
  c.param("thrust_constant", group, &M::thrust_constant)
      .with_unit("N/(rad/s)^2")
      .range(1e-9, 1.0)
      .describe("rotor thrust per squared rotor speed");
  c.param("moment_constant", group, &M::moment_constant)
      .with_unit("m")
      .range(0.0, 1.0)
      .describe("rotor drag torque per newton of thrust");
  c.param("motor_time_constant_up_s", group, &M::motor_time_constant_up_s)
      .with_unit("s")
      .range(1e-4, 1.0)
      .describe("first-order motor lag when speeding up");
  c.param("motor_time_constant_down_s", group, &M::motor_time_constant_down_s)
      .with_unit("s")
      .range(1e-4, 1.0)
      .describe("first-order motor lag when slowing down");
  c.param("max_rotor_speed_rad_s", group, &M::max_rotor_speed_rad_s)
      .with_unit("rad/s")
      .range(1.0, 100000.0)
      .describe("rotor speed limit");
  c.param("rotor_drag_coefficient", group, &M::rotor_drag_coefficient)
      .with_unit("N s/m per rad/s")
      .range(0.0, 1.0)
      .describe("rotor drag: force against the airspeed across each disc, per rad/s of rotor speed");
}

}  // namespace kestrel::vehicle
