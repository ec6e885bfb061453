#include "kestrel/tracking/imm_filter.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "kestrel/error.hpp"

namespace kestrel::tracking {

ImmTrack::ImmTrack(const Eigen::Vector3d& first_detection, const ImmConfig& config) : cfg_(config) {
  for (auto& m : models_) m = ConstantAccelerationKalman::start(first_detection, config.p);
  mu_ = {1.0 - config.switch_probability, config.switch_probability};  // most flight is steady
}

void ImmTrack::predict(double dt) {
  const double stay = 1.0 - cfg_.switch_probability;
  // Mixing: the chance the motion was in model i given it is now in model j.
  std::array<double, kModels> predicted{};
  double mix[kModels][kModels];
  for (int j = 0; j < kModels; ++j) {
    for (int i = 0; i < kModels; ++i) predicted[j] += (i == j ? stay : 1.0 - stay) * mu_[i];
    for (int i = 0; i < kModels; ++i)
      mix[i][j] = predicted[j] > 0 ? (i == j ? stay : 1.0 - stay) * mu_[i] / predicted[j] : 0.5;
  }
  std::array<ConstantAccelerationKalman, kModels> mixed;
  for (int j = 0; j < kModels; ++j) {
    mixed[j].x.setZero();
    for (int i = 0; i < kModels; ++i) mixed[j].x += mix[i][j] * models_[i].x;
    mixed[j].P.setZero();
    for (int i = 0; i < kModels; ++i) {
      const State d = models_[i].x - mixed[j].x;
      mixed[j].P += mix[i][j] * (models_[i].P + d * d.transpose());
    }
  }
  models_ = mixed;
  models_[0].predict(dt, cfg_.q_steady);
  models_[1].predict(dt, cfg_.q_manoeuvre);
  mu_ = predicted;
}

void ImmTrack::update(const Eigen::Vector3d& z) {
  // Each model's likelihood of the detection, N(z - Hx; 0, S), in logs against underflow.
  std::array<double, kModels> log_weight{};
  for (int j = 0; j < kModels; ++j) {
    const Eigen::Matrix3d S = models_[j].innovation_covariance(cfg_.r);
    const Eigen::Vector3d v = z - models_[j].position();
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(S);
    const double log_det = ldlt.vectorD().array().log().sum();
    log_weight[j] = std::log(std::max(mu_[j], 1e-300)) - 0.5 * (v.dot(ldlt.solve(v)) + log_det);
    models_[j].update(z, cfg_.r);
  }
  const double top = std::max(log_weight[0], log_weight[1]);
  double sum = 0.0;
  for (int j = 0; j < kModels; ++j) sum += mu_[j] = std::exp(log_weight[j] - top);
  for (auto& m : mu_) m /= sum;
  // Neither model may die out: the chain must be able to switch back.
  for (auto& m : mu_) m = std::clamp(m, 1e-6, 1.0 - 1e-6);
}

void ImmTrack::moments(State& x, Covariance& P) const {
  x.setZero();
  for (int j = 0; j < kModels; ++j) x += mu_[j] * models_[j].x;
  P.setZero();
  for (int j = 0; j < kModels; ++j) {
    const State d = models_[j].x - x;
    P += mu_[j] * (models_[j].P + d * d.transpose());
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
  c.rule("q_steady <= q_manoeuvre", {"q_steady", "q_manoeuvre"},
         [](const ImmConfig& k) { return k.q_steady <= k.q_manoeuvre; });
  return ComponentSpec("imm", "Interacting multiple models: steady and manoeuvring constant-acceleration filters")
      .details(
          "Each track runs two of the paper's constant-acceleration Kalman filters, one with process noise "
          "q_steady (steady flight) and one with q_manoeuvre (turns, braking), mixed each frame by their "
          "probabilities (IMM, Blom and Bar-Shalom), which follow how well each predicted the detections and a "
          "Markov chain that switches with switch_probability a frame. The published state and covariance are "
          "the mixture's.")
      .config(std::move(c));
}

ImmFilter::ImmFilter(const ComponentInit& init) : cfg_(init.config<ImmConfig>()) {}

std::unique_ptr<TrackFilter> ImmFilter::start(const Eigen::Vector3d& first_detection) {
  return std::make_unique<ImmTrack>(first_detection, cfg_);
}

}  // namespace kestrel::tracking
