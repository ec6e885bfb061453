#pragma once
// A hexacopter shaped after the RotorS Firefly: 0.215 m arms, 0.1 m rotors (about 0.63 m across)
// and landing skids (about 0.21 m tall), every part textured for stereo matching.
#include <mrpt/opengl/CSetOfObjects.h>

#include <cstdint>

namespace kestrel::sim {

struct DroneShape {
  double arm_length_m = 0.215;
  double rotor_radius_m = 0.10;
  double body_size_m = 0.20;
  double height_m = 0.21;  ///< skids to rotor tops
};

/// The drone in its body frame (x forward, y left, z up; origin at the centre of mass).
mrpt::opengl::CSetOfObjects::Ptr make_hexacopter(const DroneShape& shape, std::uint64_t texture_seed);

}  // namespace kestrel::sim
