#include "kestrel/tracking/imm_filter.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "kestrel/error.hpp"

namespace kestrel::tracking {

std::vector<ImmModel> imm_models(const ImmConfig& config) {
  std::vector<ImmModel> models{{MotionModel::constant_acceleration, config.q_steady},
                               {MotionModel::constant_acceleration, config.q_manoeuvre}};
  if (config.q_velocity > 0.0) models.push_back({MotionModel::constant_velocity, config.q_velocity});
  if (config.q_turn > 0.0) models.push_back({MotionModel::coordinated_turn, config.q_turn});
  return models;
}

ImmTrack::ImmTrack(const Eigen::Vector3d& first_detection, std::vector<ImmModel> models, double switch_probability,
                   double r, double p)
    : models_(std::move(models)), switch_probability_(switch_probability), r_(r) {
  if (models_.empty()) throw Error("an IMM needs at least one motion model");
  filters_.assign(models_.size(), ConstantAccelerationKalman::start(first_detection, p));
  // Most flight starts in the first model.
  const double n = static_cast<double>(models_.size());
  mu_.assign(models_.size(), n > 1 ? switch_probability / (n - 1.0) : 1.0);
  mu_[0] = n > 1 ? 1.0 - switch_probability : 1.0;
}

double ImmTrack::switch_to(std::size_t i, std::size_t j) const {
  if (models_.size() == 1) return 1.0;
  return i == j ? 1.0 - switch_probability_ : switch_probability_ / static_cast<double>(models_.size() - 1);
}

void ImmTrack::predict(double dt) {
  const std::size_t n = models_.size();
  // Mixing: the chance the motion was in model i given it is now in model j.
  std::vector<double> predicted(n, 0.0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) predicted[j] += switch_to(i, j) * mu_[i];
  std::vector<ConstantAccelerationKalman> mixed(n);
  for (std::size_t j = 0; j < n; ++j) {
    auto weight = [&](std::size_t i) {
      return predicted[j] > 0 ? switch_to(i, j) * mu_[i] / predicted[j] : 1.0 / static_cast<double>(n);
    };
    mixed[j].x.setZero();
    for (std::size_t i = 0; i < n; ++i) mixed[j].x += weight(i) * filters_[i].x;
    mixed[j].P.setZero();
    for (std::size_t i = 0; i < n; ++i) {
      const State d = filters_[i].x - mixed[j].x;
      mixed[j].P += weight(i) * (filters_[i].P + d * d.transpose());
    }
  }
  filters_ = std::move(mixed);
  for (std::size_t j = 0; j < n; ++j)
    filters_[j].predict(model_transition(models_[j].motion, filters_[j].x, dt),
                        model_process_noise(models_[j].motion, dt, models_[j].q));
  mu_ = std::move(predicted);
}

void ImmTrack::update(const Eigen::Vector3d& z) {
  const std::size_t n = models_.size();
  // Each model's likelihood of the detection, N(z - Hx; 0, S), in logs against underflow.
  std::vector<double> log_weight(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::Matrix3d S = filters_[j].innovation_covariance(r_);
    const Eigen::Vector3d v = z - filters_[j].position();
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(S);
    const double log_det = ldlt.vectorD().array().log().sum();
    log_weight[j] = std::log(std::max(mu_[j], 1e-300)) - 0.5 * (v.dot(ldlt.solve(v)) + log_det);
    filters_[j].update(z, r_);
  }
  const double top = *std::max_element(log_weight.begin(), log_weight.end());
  double sum = 0.0;
  for (std::size_t j = 0; j < n; ++j) sum += mu_[j] = std::exp(log_weight[j] - top);
  for (auto& m : mu_) m /= sum;
  // No model may die out: the chain must be able to switch back.
  if (n > 1)
    for (auto& m : mu_) m = std::clamp(m, 1e-6, 1.0 - 1e-6);
}

State ImmTrack::predicted_state(double tau) const {
  State x = State::Zero();
  for (std::size_t j = 0; j < filters_.size(); ++j)
    x += mu_[j] * model_transition(models_[j].motion, filters_[j].x, tau) * filters_[j].x;
  return x;
}

void ImmTrack::moments(State& x, Covariance& P) const {
  x.setZero();
  for (std::size_t j = 0; j < filters_.size(); ++j) x += mu_[j] * filters_[j].x;
  P.setZero();
  for (std::size_t j = 0; j < filters_.size(); ++j) {
    const State d = filters_[j].x - x;
    P += mu_[j] * (filters_[j].P + d * d.transpose());
  }
}

ComponentSpec ImmFilter::spec() {
  ConfigSpec<ImmConfig> c;
  c.param("q_steady", &ImmConfig::q_steady)
      .range(0.0, 1e6)
      .with_unit("m^2/s^5")
      .describe("process noise (jerk) intensity of the steady-flight model");
  c.param("q_manoeuvre", &ImmConfig::q_manoeuvre)
      .range(0.0, 1e9)
      .with_unit("m^2/s^5")
      .describe("process noise (jerk) intensity of the manoeuvre model");
  c.param("switch_probability", &ImmConfig::switch_probability)
      .range(1e-6, 0.5)
      .describe("chance, each frame, that the motion passes from one model to the other");
  c.param("r", &ImmConfig::r).range(1e-9, 1e6).with_unit("m^2").describe("measurement noise: R = r I3");
  c.param("p", &ImmConfig::p)
      .range(1e-9, 1e6)
      .describe("initial covariance scale: P0 = p diag(1, 900, 30.25) per axis");
  c.param("q_velocity", &ImmConfig::q_velocity)
      .range(0.0, 1e9)
      .with_unit("m^2/s^3")
      .describe("> 0: a constant-velocity model joins, driven by white-noise acceleration of this intensity");
  c.param("q_turn", &ImmConfig::q_turn)
      .range(0.0, 1e9)
      .with_unit("m^2/s^5")
      .describe(
          "> 0: a coordinated-turn model joins (the horizontal velocity turning at the rate the state shows), with "
          "this jerk intensity");
  c.rule("q_steady <= q_manoeuvre", {"q_steady", "q_manoeuvre"},
         [](const ImmConfig& k) { return k.q_steady <= k.q_manoeuvre; });
  return ComponentSpec("imm",
                       "Interacting multiple models: steady and manoeuvring constant-acceleration filters, and on "
                       "request constant-velocity and coordinated-turn ones")
      .details(
          "Each track runs two of the paper's constant-acceleration Kalman filters, one with process noise "
          "q_steady (steady flight) and one with q_manoeuvre (turns, braking), mixed each frame by their "
          "probabilities (IMM, Blom and Bar-Shalom), which follow how well each predicted the detections and a "
          "Markov chain that leaves each model with switch_probability a frame. q_velocity > 0 adds a "
          "constant-velocity model, q_turn > 0 a coordinated turn (Bar-Shalom, Li, Kirubarajan 11.7). The published "
          "state and covariance are the mixture's.")
      .config(std::move(c));
}

ImmFilter::ImmFilter(const ComponentInit& init) : cfg_(init.config<ImmConfig>()) {}

std::unique_ptr<TrackFilter> ImmFilter::start(const Eigen::Vector3d& first_detection) {
  return std::make_unique<ImmTrack>(first_detection, cfg_);
}

}  // namespace kestrel::tracking
