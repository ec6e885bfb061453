#pragma once
// The ground taken out of a stereo cloud by where the camera is, the way stereo sees it: a point
// is ground when, along its own ray, it lies no nearer than the ground plane by more than a
// margin in disparity. Far away a ray meets the ground at a grazing angle, and a small disparity
// error moves a ground point metres along the ray, and so up off the plane: a 2 m high camera's
// ray meets the ground 15 m out, and a quarter pixel nearer (fx b = 36.5 px m) puts the point
// 1.4 m short and 0.2 m up, half a pixel 2.6 m short and 0.35 m up. A height threshold must grow
// with range to hold such points; a margin in disparity is the same at every range, as stereo's
// noise is.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "kestrel/geometry/frames.hpp"

namespace kestrel::ground {

struct GroundOptions {
  double margin_px = 0.5;   ///< a point nearer than the ground along its ray by less than this is ground
  double ground_z_m = 0.0;  ///< the ground plane's height (world z)
};

/// The ground test for one camera pose, set up once per cloud. For a camera-frame point `p` seen
/// by the camera (stereo with fx * baseline `focal_baseline`): its disparity d = focal_baseline /
/// p.z and the ground's along the same ray, d / t, where t is how many times farther the ray meets
/// the ground than p. The point is ground when d (1 - 1/t) < margin_px, which holds for every
/// point beneath the plane (t < 1) too. A ray that never meets the ground (level or up, or a
/// camera beneath the plane) is not ground.
class GroundTest {
 public:
  GroundTest(const geometry::CameraPose& camera, double focal_baseline, const GroundOptions& options);
  bool operator()(const Eigen::Vector3d& p) const;

 private:
  Eigen::RowVector3d world_z_;  // the camera-frame row that gives a ray's world z change
  double height_, focal_baseline_, margin_px_;
};

/// One point: GroundTest(camera, focal_baseline, options)(p).
bool is_ground(const Eigen::Vector3d& p, const geometry::CameraPose& camera, double focal_baseline,
               const GroundOptions& options);

/// The cloud without its ground points (the others in their order).
pcl::PointCloud<pcl::PointXYZ>::Ptr remove_ground(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                  const geometry::CameraPose& camera, double focal_baseline,
                                                  const GroundOptions& options);

}  // namespace kestrel::ground
