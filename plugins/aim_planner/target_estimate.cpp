#include "target_estimate.hpp"

namespace kestrel::aim {

namespace {
std::variant<tracking::KalmanTrack, tracking::ImmTrack> make_filter(const Eigen::Vector3d& z,
                                                                    const TargetFilterConfig& k) {
  if (k.model == TargetFilterConfig::Model::imm)
    return tracking::ImmTrack(z, tracking::ImmConfig{k.q, k.q_manoeuvre, k.switch_probability, k.r, 1.0});
  return tracking::KalmanTrack(z, tracking::KalmanConfig{k.q, k.r, 1.0});
}
}  // namespace

TargetEstimate::TargetEstimate(const Eigen::Vector3d& first_sighting, const TargetFilterConfig& config)
    : filter_(make_filter(first_sighting, config)) {}

void TargetEstimate::predict(double dt) {
  std::visit([&](auto& f) { f.predict(dt); }, filter_);
}

void TargetEstimate::update(const Eigen::Vector3d& sighting) {
  std::visit([&](auto& f) { f.update(sighting); }, filter_);
}

Eigen::VectorXd TargetEstimate::state() const {
  return std::visit([](const auto& f) { return f.state(); }, filter_);
}

Eigen::MatrixXd TargetEstimate::covariance() const {
  return std::visit([](const auto& f) { return f.covariance(); }, filter_);
}

Eigen::Matrix3d TargetEstimate::position_covariance_after(double tau) const {
  auto ahead = filter_;
  if (tau > 0.0) std::visit([&](auto& f) { f.predict(tau); }, ahead);
  return std::visit([](const auto& f) { return Eigen::Matrix3d(f.covariance().template topLeftCorner<3, 3>()); },
                    ahead);
}

}  // namespace kestrel::aim
