#include "ground_removal.hpp"

namespace kestrel::ground {

GroundTest::GroundTest(const geometry::CameraPose& camera, double focal_baseline, const GroundOptions& options)
    : world_z_(camera.world_from_camera().row(2)),
      height_(camera.position_world.z() - options.ground_z_m),
      focal_baseline_(focal_baseline),
      margin_px_(options.margin_px) {}

bool GroundTest::operator()(const Eigen::Vector3d& p) const {
  if (!(p.z() > 0.0)) return false;                  // not a stereo point in front of the camera
  const double ray_z = world_z_ * p;                 // world z change from the camera to p
  if (height_ <= 0.0 || ray_z >= 0.0) return false;  // the ray never meets the ground
  const double t = height_ / -ray_z;                 // the ground is t times as far along the ray as p
  const double disparity = focal_baseline_ / p.z();
  return disparity * (1.0 - 1.0 / t) < margin_px_;
}

bool is_ground(const Eigen::Vector3d& p, const geometry::CameraPose& camera, double focal_baseline,
               const GroundOptions& options) {
  return GroundTest(camera, focal_baseline, options)(p);
}

pcl::PointCloud<pcl::PointXYZ>::Ptr remove_ground(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                  const geometry::CameraPose& camera, double focal_baseline,
                                                  const GroundOptions& options) {
  const GroundTest ground(camera, focal_baseline, options);  // the pose's rotation, once a cloud
  auto out = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  out->reserve(cloud.size());
  for (const auto& q : cloud.points)
    if (!ground(Eigen::Vector3d(q.x, q.y, q.z))) out->push_back(q);
  out->width = static_cast<std::uint32_t>(out->size());
  out->height = 1;
  out->is_dense = cloud.is_dense;
  return out;
}

}  // namespace kestrel::ground
