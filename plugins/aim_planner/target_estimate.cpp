#include "target_estimate.hpp"

namespace kestrel::aim {

namespace {
std::variant<tracking::KalmanTrack, tracking::ImmTrack> make_filter(const Eigen::Vector3d& z,
                                                                    const TargetFilterConfig& k) {
  using tracking::MotionModel;
  if (k.model == TargetFilterConfig::Model::imm)
    return tracking::ImmTrack(z,
                              {{MotionModel::constant_velocity, k.q_velocity},
                               {MotionModel::constant_acceleration, k.q},
                               {MotionModel::coordinated_turn, k.q_turn}},
                              k.switch_probability, k.r, 1.0);
  if (k.model == TargetFilterConfig::Model::constant_velocity)
    return tracking::ImmTrack(z, {{MotionModel::constant_velocity, k.q_velocity}}, 0.0, k.r, 1.0);
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

Eigen::Vector3d TargetEstimate::position_after(double tau) const {
  if (const auto* imm = std::get_if<tracking::ImmTrack>(&filter_)) return imm->predicted_state(tau).head<3>();
  const tracking::State x = std::get<tracking::KalmanTrack>(filter_).state();
  return (tracking::transition(tau) * x).head<3>();
}

std::vector<double> TargetEstimate::model_probabilities() const {
  if (const auto* imm = std::get_if<tracking::ImmTrack>(&filter_); imm && imm->models().size() > 1)
    return imm->model_probabilities();
  return {};
}

std::vector<guidance::MotionHypothesis> TargetEstimate::hypotheses() const {
  if (const auto* imm = std::get_if<tracking::ImmTrack>(&filter_)) {
    std::vector<guidance::MotionHypothesis> out;
    for (std::size_t i = 0; i < imm->models().size(); ++i)
      out.push_back({imm->models()[i].motion, imm->model_filters()[i].x, imm->model_filters()[i].P,
                     imm->model_probabilities()[i]});
    return out;
  }
  const auto& kalman = std::get<tracking::KalmanTrack>(filter_);
  return {{tracking::MotionModel::constant_acceleration, kalman.state(), kalman.covariance(), 1.0}};
}

}  // namespace kestrel::aim
