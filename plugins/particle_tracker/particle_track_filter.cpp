#include "particle_track_filter.hpp"

#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "kestrel/error.hpp"

namespace kestrel::tracking {

mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm resampling_method(const std::string& name) {
  using PF = mrpt::bayes::CParticleFilter;
  if (name == "multinomial") return PF::prMultinomial;
  if (name == "residual") return PF::prResidual;
  if (name == "stratified") return PF::prStratified;
  if (name == "systematic") return PF::prSystematic;
  throw Error("unknown resampling method '" + name + "'");
}

ParticleTrackFilter::ParticleTrackFilter(const Eigen::Vector3d& z, const ParticleOptions& options, std::uint64_t seed)
    : options_(options), rng_(seed) {
  if (options.particles < 1) throw Error("a particle filter needs at least one particle");
  filter_.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
  filter_.m_options.resamplingMethod = resampling_method(options.resampling);
  filter_.m_options.BETA = options.resample_below_ess;
  filter_.m_options.sampleSize = static_cast<unsigned>(options.particles);
  // MRPT resamples with its own generator: seed it so lockstep runs reproduce.
  mrpt::random::getRandomGenerator().randomize(static_cast<std::uint32_t>(seed));

  // Particles drawn from the paper's prior: N(z, p diag(1, 900, 30.25)) per axis.
  const Eigen::LLT<Covariance> prior(initial_covariance(options.p));
  std::normal_distribution<double> unit(0.0, 1.0);
  m_particles.resize(static_cast<std::size_t>(options.particles));
  for (auto& particle : m_particles) {
    State noise;
    for (int i = 0; i < 9; ++i) noise(i) = unit(rng_);
    particle.d = prior.matrixL() * noise;
    particle.d.head<3>() += z;
    particle.log_w = 0.0;
  }
}

void ParticleTrackFilter::predict(double dt) {
  const Covariance F = transition(dt);
  // White-noise jerk, sampled per axis from its 3x3 block (position, velocity, acceleration).
  const Covariance Q = process_noise(dt, options_.q);
  Eigen::Matrix3d block;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) block(i, j) = Q(index(0, i), index(0, j));
  const Eigen::Matrix3d L = Eigen::LLT<Eigen::Matrix3d>(block + 1e-15 * Eigen::Matrix3d::Identity()).matrixL();
  std::normal_distribution<double> unit(0.0, 1.0);
  for (auto& particle : m_particles) {
    particle.d = F * particle.d;
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d w = L * Eigen::Vector3d(unit(rng_), unit(rng_), unit(rng_));
      for (int k = 0; k < 3; ++k) particle.d(index(a, k)) += w(k);
    }
  }
}

void ParticleTrackFilter::update(const Eigen::Vector3d& z) {
  pending_ = z;
  // MRPT calls the hook below, normalises the weights and resamples when the ESS is low.
  filter_.executeOn(*this, nullptr, nullptr);
  if (resampling_) {
    // MRPT 2.5 does not reset the weights after resampling when asked to keep the particle count
    // (later releases do): the copies must start equal, or heavy particles count twice.
    for (auto& p : m_particles) p.log_w = 0.0;
    roughen();
  }
}

// Resampling leaves many identical particles; without fresh diversity in the unobserved
// velocity and acceleration the cloud collapses and the filter diverges. Roughening (Gordon,
// Salmond and Smith, 1993) adds Gaussian jitter of K * spread * N^(-1/d) to each state dimension.
void ParticleTrackFilter::roughen() {
  if (options_.roughening <= 0 || m_particles.size() < 2) return;
  State lo = m_particles.front().d, hi = lo;
  for (const auto& p : m_particles) {
    lo = lo.cwiseMin(p.d);
    hi = hi.cwiseMax(p.d);
  }
  const double scale = options_.roughening * std::pow(static_cast<double>(m_particles.size()), -1.0 / 9.0);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (auto& p : m_particles)
    for (int i = 0; i < 9; ++i) p.d(i) += scale * (hi(i) - lo(i)) * unit(rng_);
}

void ParticleTrackFilter::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection*, const mrpt::obs::CSensoryFrame*,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions&) {
  for (auto& particle : m_particles)
    particle.log_w += -0.5 * (pending_ - particle.d.head<3>()).squaredNorm() / options_.r;
  // The same test MRPT applies next (ESS after normalisation below BETA): remember its answer.
  resampling_ = ESS() < options_.resample_below_ess;
}

void ParticleTrackFilter::moments(State& mean, Covariance& cov) const {
  double max_log = -std::numeric_limits<double>::infinity();
  for (const auto& particle : m_particles) max_log = std::max(max_log, particle.log_w);
  double total = 0.0;
  mean.setZero();
  for (const auto& particle : m_particles) {
    const double w = std::exp(particle.log_w - max_log);
    total += w;
    mean += w * particle.d;
  }
  mean /= total;
  cov.setZero();
  for (const auto& particle : m_particles) {
    const double w = std::exp(particle.log_w - max_log) / total;
    const State e = particle.d - mean;
    cov += w * e * e.transpose();
  }
}

PredictedMeasurement ParticleTrackFilter::predicted_measurement() const {
  State mean;
  Covariance cov;
  moments(mean, cov);
  return {mean.head<3>(), cov.topLeftCorner<3, 3>() + options_.r * Eigen::Matrix3d::Identity()};
}

Eigen::VectorXd ParticleTrackFilter::state() const {
  State mean;
  Covariance cov;
  moments(mean, cov);
  return mean;
}

Eigen::MatrixXd ParticleTrackFilter::covariance() const {
  State mean;
  Covariance cov;
  moments(mean, cov);
  return cov;
}

}  // namespace kestrel::tracking
