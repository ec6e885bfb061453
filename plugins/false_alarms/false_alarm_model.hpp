#pragma once
// Clutter for tracker tests, as Stone Soup and the tracking literature model it: each frame, a
// Poisson number of false detections with mean `rate`, spread uniformly over a box of the camera
// frame. Independent of the perception chain, so a tracker's robustness to false alarms can be
// measured on its own.
#include <Eigen/Core>
#include <random>
#include <vector>

namespace kestrel::scenario {

struct FalseAlarmBox {
  Eigen::Vector3d min = Eigen::Vector3d(-3.0, -2.0, 2.0);
  Eigen::Vector3d max = Eigen::Vector3d(3.0, 2.0, 10.0);
};

class FalseAlarmModel {
 public:
  /// `rate`: mean false detections per frame (>= 0). Throws kestrel::Error on a bad box or rate.
  FalseAlarmModel(double rate, FalseAlarmBox box);

  /// This frame's false detections, drawn with `rng`.
  std::vector<Eigen::Vector3d> draw(std::mt19937_64& rng) const;

 private:
  double rate_;
  FalseAlarmBox box_;
};

}  // namespace kestrel::scenario
