#pragma once
// The net, as the paper describes its launcher: it flies a parabola and reaches its widest
// opening about 2 m ahead of and 1 m below the launcher (x_E^d = [0, 1, 2] m in the camera
// frame). Here it is fired with the launch velocity that makes its centre reach that point,
// relative to the launch pose, after flight_time_s (plus the hunter's own velocity, which it
// inherits). It stays open for open_for_s while it keeps flying, and catches an intruder whose
// centre comes within its radius while it is open.
#include <Eigen/Core>
#include <kestrel/geometry/frames.hpp>
#include <optional>

namespace kestrel::net {

struct NetParams {
  Eigen::Vector3d open_point_camera{0.0, 1.0, 2.0};
  double flight_time_s = 0.4;
  double radius_m = 0.6;  ///< the paper's net spans over 1 m
  double open_for_s = 0.3;
  double gravity = 9.81;
};

struct NetShot {
  double fired_at = 0.0;
  Eigen::Vector3d launch_position = Eigen::Vector3d::Zero();  ///< world
  Eigen::Vector3d launch_velocity = Eigen::Vector3d::Zero();  ///< world
};

class NetModel {
 public:
  explicit NetModel(NetParams params) : p_(std::move(params)) {}

  /// A shot fired at time t from a launcher at `launcher` (its camera-like frame) moving at
  /// `launcher_velocity` (world).
  NetShot fire(double t, const geometry::CameraPose& launcher, const Eigen::Vector3d& launcher_velocity) const;
  /// Centre of the net at time t (world), on its parabola.
  Eigen::Vector3d position(const NetShot& shot, double t) const;
  /// True while the net is open, from flight_time_s after the shot for open_for_s.
  bool open(const NetShot& shot, double t) const;
  /// True when the net is open at t and `target` (world) is within its radius.
  bool catches(const NetShot& shot, double t, const Eigen::Vector3d& target) const;
  /// The net against an intruder moving in a straight line from `from` (at t0) to `to` (at t1),
  /// checked every few milliseconds: a net several metres per second fast crosses a sampled
  /// intruder between two samples. The first time within [t0, t1] at which it catches, if any;
  /// `closest` is lowered to the least distance while open.
  std::optional<double> sweep(const NetShot& shot, double t0, const Eigen::Vector3d& from, double t1,
                              const Eigen::Vector3d& to, double& closest) const;
  /// True once the net can no longer catch anything.
  bool spent(const NetShot& shot, double t) const { return t > shot.fired_at + p_.flight_time_s + p_.open_for_s; }

  const NetParams& params() const { return p_; }

 private:
  NetParams p_;
};

}  // namespace kestrel::net
