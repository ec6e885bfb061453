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

/// Where trees and buildings stand. `scattered`: anywhere between two ranges from the world
/// origin, so they can stand in the line of sight. `band`: in a band of depth in front of a
/// camera, across its field of view, so that an intruder nearer than the band is seen against
/// them and never hidden by them.
enum class ClutterLayout { scattered, band };

/// The camera a `band` of clutter is laid out for: where it stands and what it sees.
struct ClutterBandView {
  Eigen::Vector3d camera_position{0.0, 0.0, 2.0};
  double camera_yaw_rad = 0.0;
  double half_fov_rad = 0.6;
};

struct SceneOptions {
  double ground_half_extent_m = 80.0;
  int clutter_count = 12;
  ClutterLayout clutter_layout = ClutterLayout::scattered;
  double clutter_tree_fraction = 0.65;  ///< the others are buildings
  double clutter_min_range_m = 12.0;    ///< scattered: from the world origin
  double clutter_max_range_m = 40.0;
  double clutter_bearing_deg = 60.0;  ///< scattered: within +-this of world +x
  double clutter_band_near_m = 6.0;   ///< band: depth of each object's nearest point, in front of the camera
  double clutter_band_far_m = 8.0;
  ClutterBandView band_view;
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
  /// The radius of each clutter object's footprint about its position.
  const std::vector<double>& clutter_footprint_radii() const { return clutter_radii_; }

 private:
  void add_clutter(const SceneOptions& options);
  /// Where a clutter object of footprint `radius` stands on the ground, by the layout's rule, from
  /// two uniform draws in [0, 1).
  static Eigen::Vector3d clutter_site(const SceneOptions& options, double a, double b, double radius);

  mrpt::opengl::COpenGLScene::Ptr scene_;
  std::map<std::uint64_t, mrpt::opengl::CSetOfObjects::Ptr> intruders_;
  std::map<std::uint64_t, bool> placed_;
  std::vector<Eigen::Vector3d> clutter_;
  std::vector<double> clutter_radii_;
  DroneShape drone_shape_;
  std::uint64_t seed_;
};

}  // namespace kestrel::sim
