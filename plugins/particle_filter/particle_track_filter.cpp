#include "particle_track_filter.hpp"

#include <mrpt/random/RandomGenerators.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <mutex>

#include "kestrel/error.hpp"

namespace kestrel::tracking {

namespace {

// MRPT resamples with one process-wide generator. Each update takes it under this lock and
// reseeds it from the track's own generator, so that a track's random stream depends on its seed
// alone (lockstep runs reproduce whatever the other tracks do) and two tracker nodes on two
// realtime threads never use it at once.
std::mutex& mrpt_generator_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

ParticleTrackFilter::ParticleTrackFilter(const Eigen::Vector3d& z, const ParticleOptions& options, std::uint64_t seed)
    : options_(options), rng_(seed) {
  if (options.particles < 1) throw Error("a particle filter needs at least one particle");
  if (options.max_correction_stages < 1) throw Error("a particle filter update needs at least one stage");
  filter_.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
  filter_.m_options.resamplingMethod = options.resampling;
  filter_.m_options.BETA = options.resample_below_ess;
  filter_.m_options.sampleSize = static_cast<unsigned>(options.particles);
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
      // Drawn z first, in sequenced declarations: the order GCC gave the old constructor call's
      // unsequenced arguments, now the same with every compiler.
      const double wz = unit(rng_), wy = unit(rng_), wx = unit(rng_);
      const Eigen::Vector3d w = L * Eigen::Vector3d(wx, wy, wz);
      for (int k = 0; k < 3; ++k) particle.d(index(a, k)) += w(k);
    }
  }
}

void ParticleTrackFilter::update(const Eigen::Vector3d& z) {
  pending_ = z;
  std::vector<double> log_likelihood(m_particles.size());
  for (std::size_t i = 0; i < m_particles.size(); ++i)
    log_likelihood[i] = -0.5 * (z - m_particles[i].d.head<3>()).squaredNorm() / options_.r;

  // Progressive correction (Musso, Oudjane and Le Gland, 2001): when the detection is far sharper
  // than the cloud, as just after birth, weighting by the whole likelihood leaves a handful of
  // particles. The likelihood is then applied in tempered stages, each as large as keeps half the
  // particles effective, with resampling and regularisation in between.
  const std::lock_guard<std::mutex> lock(mrpt_generator_mutex());
  mrpt::random::getRandomGenerator().randomize(static_cast<std::uint32_t>(rng_()));
  double remaining = 1.0;
  for (int stage = 0; remaining > 0.0; ++stage) {
    const bool last_allowed = stage + 1 >= options_.max_correction_stages;
    const double exponent = last_allowed ? remaining : largest_exponent(log_likelihood, remaining);
    remaining = exponent >= remaining ? 0.0 : remaining - exponent;
    const bool intermediate = remaining > 0.0;
    // MRPT calls the hook below with the stage's exponent (its powFactor), normalises the
    // weights and resamples when the ESS is low; between stages it always resamples.
    filter_.m_options.powFactor = exponent;
    filter_.m_options.BETA = intermediate ? 1.0 : options_.resample_below_ess;
    filter_.executeOn(*this, nullptr, nullptr);
    if (resampling_) {
      // MRPT 2.5 does not reset the weights after resampling when asked to keep the particle
      // count (later releases do): the copies must start equal, or heavy particles count twice.
      for (auto& p : m_particles) p.log_w = 0.0;
      regularise();
      if (intermediate)
        for (std::size_t i = 0; i < m_particles.size(); ++i)
          log_likelihood[i] = -0.5 * (z - m_particles[i].d.head<3>()).squaredNorm() / options_.r;
    }
  }
}

// The largest share of the likelihood, up to `remaining`, whose weights keep the effective
// sample size at or above half the particles (bisection; the ESS falls as the exponent grows).
double ParticleTrackFilter::largest_exponent(const std::vector<double>& log_likelihood, double remaining) const {
  auto ess_share = [&](double exponent) {
    double max_log = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_particles.size(); ++i)
      max_log = std::max(max_log, m_particles[i].log_w + exponent * log_likelihood[i]);
    double sum = 0.0, sum_sq = 0.0;
    for (std::size_t i = 0; i < m_particles.size(); ++i) {
      const double w = std::exp(m_particles[i].log_w + exponent * log_likelihood[i] - max_log);
      sum += w;
      sum_sq += w * w;
    }
    return sum * sum / sum_sq / static_cast<double>(m_particles.size());
  };
  constexpr double kKeptShare = 0.5;
  if (ess_share(remaining) >= kKeptShare) return remaining;
  double lo = 0.0, hi = remaining;
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ess_share(mid) >= kKeptShare ? lo : hi) = mid;
  }
  return std::max(lo, 1e-6 * remaining);
}

// Resampling leaves many identical particles, and white-noise jerk alone restores too little
// diversity in velocity and acceleration: the cloud collapses and the filter diverges. The
// regularised filter (Musso, Oudjane and Le Gland, 2001) draws each particle from a Gaussian
// kernel shaped by the cloud's covariance; Liu and West's shrinkage towards the mean keeps the
// cloud's mean and covariance unchanged, so the jitter adds diversity, not uncertainty.
void ParticleTrackFilter::regularise() {
  const double h = options_.kernel_bandwidth;
  if (h <= 0 || m_particles.size() < 2) return;
  State mean = State::Zero();
  for (const auto& p : m_particles) mean += p.d;
  mean /= static_cast<double>(m_particles.size());
  Covariance cov = Covariance::Zero();
  for (const auto& p : m_particles) cov += (p.d - mean) * (p.d - mean).transpose();
  cov /= static_cast<double>(m_particles.size());
  const Eigen::LLT<Covariance> llt(cov + 1e-12 * Covariance::Identity());
  if (llt.info() != Eigen::Success) return;
  const Covariance L = llt.matrixL();
  const double shrink = std::sqrt(std::max(0.0, 1.0 - h * h));
  std::normal_distribution<double> unit(0.0, 1.0);
  for (auto& p : m_particles) {
    State xi;
    for (int i = 0; i < 9; ++i) xi(i) = unit(rng_);
    p.d = shrink * p.d + (1.0 - shrink) * mean + h * (L * xi);
  }
}

void ParticleTrackFilter::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection*, const mrpt::obs::CSensoryFrame*,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& options) {
  for (auto& particle : m_particles)
    particle.log_w += -0.5 * options.powFactor * (pending_ - particle.d.head<3>()).squaredNorm() / options_.r;
  // The same test MRPT applies next (ESS after normalisation below BETA): remember its answer.
  resampling_ = ESS() < options.BETA;
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

}  // namespace kestrel::tracking
