#include "tracks_in_world.hpp"

namespace kestrel::tracking {

msg::Track track_in_camera(msg::Track track, const geometry::CameraPose& camera) {
  const Eigen::Matrix3d to_camera = camera.world_from_camera().transpose();
  const Eigen::Index n = track.state.size();
  // B rotates every whole 3-block; the position is also moved to the camera's origin.
  Eigen::MatrixXd b = Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index i = 0; i + 3 <= n; i += 3) b.block<3, 3>(i, i) = to_camera;
  track.state = b * track.state;
  if (n >= 3) track.state.head<3>() -= to_camera * camera.position_world;
  if (track.covariance.rows() == n && track.covariance.cols() == n)
    track.covariance = b * track.covariance * b.transpose();
  if (track.detection.allFinite()) track.detection = camera.to_camera(track.detection);
  return track;
}

}  // namespace kestrel::tracking
