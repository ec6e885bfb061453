#pragma once
// One track as a particle filter on MRPT's machinery (mrpt::bayes::CParticleFilter over a
// CParticleFilterData model): each particle is a constant-acceleration state; prediction moves
// every particle with the model and samples white-noise jerk; an update weights the particles by
// the Gaussian likelihood of the detection (in tempered stages when it is much sharper than the
// cloud), MRPT normalises and resamples, and a shrinkage kernel regularises the copies.
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/bayes/CParticleFilterData.h>

#include <random>
#include <vector>

#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/moment_filter.hpp"

namespace kestrel::tracking {

struct ParticleOptions {
  int particles = 1000;
  double q = 1.0;
  double r = 1.0;
  double p = 1.0;
  mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm resampling = mrpt::bayes::CParticleFilter::prSystematic;
  double resample_below_ess = 0.5;  ///< resample when the effective sample size falls below this share
  double kernel_bandwidth = 0.5;    ///< h of the regularisation kernel after resampling (0 = none)
  int max_correction_stages = 10;   ///< tempered stages of one update at most (1 = plain update)
};

using ParticleData = mrpt::bayes::CParticleFilterData<State, mrpt::bayes::particle_storage_mode::VALUE>;

class ParticleTrackFilter final
    : public ParticleData,
      public mrpt::bayes::CParticleFilterDataImpl<ParticleTrackFilter, ParticleData::CParticleList>,
      public MomentTrackFilter {
 public:
  ParticleTrackFilter(const Eigen::Vector3d& first_detection, const ParticleOptions& options, std::uint64_t seed);

  void predict(double dt) override;
  void update(const Eigen::Vector3d& z) override;

 protected:
  // MRPT's hook: weights the (already predicted) particles by the pending detection.
  void prediction_and_update_pfStandardProposal(
      const mrpt::obs::CActionCollection* action, const mrpt::obs::CSensoryFrame* observation,
      const mrpt::bayes::CParticleFilter::TParticleFilterOptions& options) override;

  void moments(State& mean, Covariance& cov) const override;
  double measurement_noise() const override { return options_.r; }

 private:
  void regularise();
  double largest_exponent(const std::vector<double>& log_likelihood, double remaining) const;

  ParticleOptions options_;
  mrpt::bayes::CParticleFilter filter_;
  std::mt19937_64 rng_;
  Eigen::Vector3d pending_ = Eigen::Vector3d::Zero();
  bool resampling_ = false;  // set by the hook: MRPT is about to resample
};

}  // namespace kestrel::tracking
