#pragma once
// The simulated world the stereo camera renders: a textured ground, background clutter and the
// intruder drones, in world coordinates (x forward, y left, z up).
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>

#include "drone_model.hpp"

namespace kestrel::sim {

struct SceneOptions {
  double ground_half_extent_m = 80.0;
  int clutter_count = 12;
  double clutter_min_range_m = 12.0;  ///< from the world origin
  double clutter_max_range_m = 40.0;
  double clutter_bearing_deg = 60.0;  ///< clutter within +-this of world +x
  DroneShape drone;
  std::uint64_t seed = 1;
};

class WorldScene {
 public:
  explicit WorldScene(const SceneOptions& options);

  /// Places intruder `id` (creating its model on first use); `yaw` turns it about world z.
  void set_intruder(std::uint64_t id, const Eigen::Vector3d& position, double yaw);
  /// Hides intruders not placed since the last call.
  void hide_unplaced_intruders();

  const mrpt::opengl::COpenGLScene& scene() const { return *scene_; }
  /// Where the clutter objects stand (centre of their footprint), for tests and reports.
  const std::vector<Eigen::Vector3d>& clutter_positions() const { return clutter_; }

 private:
  void add_clutter(const SceneOptions& options);

  mrpt::opengl::COpenGLScene::Ptr scene_;
  std::map<std::uint64_t, mrpt::opengl::CSetOfObjects::Ptr> intruders_;
  std::map<std::uint64_t, bool> placed_;
  std::vector<Eigen::Vector3d> clutter_;
  DroneShape drone_shape_;
  std::uint64_t seed_;
};

}  // namespace kestrel::sim
