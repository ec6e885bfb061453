#include "ground_removal.hpp"

namespace kestrel::ground {

bool is_ground(const Eigen::Vector3d& p, const geometry::CameraPose& camera, double focal_baseline,
               const GroundOptions& options) {
  if (!(p.z() > 0.0)) return false;  // not a stereo point in front of the camera
  const double height = camera.position_world.z() - options.ground_z_m;
  const double ray_z = (camera.world_from_camera() * p).z();  // world z change from the camera to p
  if (height <= 0.0 || ray_z >= 0.0) return false;            // the ray never meets the ground
  const double t = height / -ray_z;                           // the ground is t times as far along the ray as p
  const double disparity = focal_baseline / p.z();
  return disparity * (1.0 - 1.0 / t) < options.margin_px;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr remove_ground(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                  const geometry::CameraPose& camera, double focal_baseline,
                                                  const GroundOptions& options) {
  auto out = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  out->reserve(cloud.size());
  for (const auto& q : cloud.points)
    if (!is_ground(Eigen::Vector3d(q.x, q.y, q.z), camera, focal_baseline, options)) out->push_back(q);
  out->width = static_cast<std::uint32_t>(out->size());
  out->height = 1;
  out->is_dense = cloud.is_dense;
  return out;
}

}  // namespace kestrel::ground
