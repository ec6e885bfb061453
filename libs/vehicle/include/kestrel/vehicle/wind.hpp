#pragma once
// Wind: a constant mean plus gusts. Each gust component is a first-order Gauss-Markov
// (Ornstein-Uhlenbeck) process with a given standard deviation and correlation time, the
// simplest model with the right spectrum shape at low frequencies; sampled exactly, so the
// statistics do not depend on the step.
#include <Eigen/Core>
#include <random>

namespace kestrel::vehicle {

class Wind {
 public:
  Wind(Eigen::Vector3d mean_m_s, double gust_std_m_s, double gust_time_constant_s, std::uint64_t seed);

  /// The wind after another dt seconds (world frame, m/s).
  Eigen::Vector3d advance(double dt);
  Eigen::Vector3d current() const { return mean_ + gust_; }

 private:
  Eigen::Vector3d mean_;
  double std_, time_constant_;
  Eigen::Vector3d gust_ = Eigen::Vector3d::Zero();
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace kestrel::vehicle
