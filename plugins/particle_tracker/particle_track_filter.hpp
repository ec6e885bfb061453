#pragma once
// One track as a particle filter on MRPT's machinery (mrpt::bayes::CParticleFilter over a
// CParticleFilterData model): each particle is a constant-acceleration state; prediction moves
// every particle with the model and samples white-noise jerk; an update weights the particles by
// the Gaussian likelihood of the detection, and MRPT normalises and resamples.
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/bayes/CParticleFilterData.h>

#include <random>
#include <string>

#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/track_manager.hpp"

namespace kestrel::tracking {

struct ParticleOptions {
  int particles = 1000;
  double q = 1.0;
  double r = 1.0;
  double p = 1.0;
  std::string resampling = "systematic";  ///< multinomial, residual, stratified, systematic
  double resample_below_ess = 0.5;         ///< resample when the effective sample size falls below this share
  double roughening = 0.2;                 ///< jitter after resampling, Gordon's K (0 = none)
};

using ParticleData = mrpt::bayes::CParticleFilterData<State, mrpt::bayes::particle_storage_mode::VALUE>;

class ParticleTrackFilter final
    : public ParticleData,
      public mrpt::bayes::CParticleFilterDataImpl<ParticleTrackFilter, ParticleData::CParticleList>,
      public TrackFilter {
 public:
  ParticleTrackFilter(const Eigen::Vector3d& first_detection, const ParticleOptions& options, std::uint64_t seed);

  void predict(double dt) override;
  void update(const Eigen::Vector3d& z) override;
  PredictedMeasurement predicted_measurement() const override;
  Eigen::VectorXd state() const override;
  Eigen::MatrixXd covariance() const override;

 protected:
  // MRPT's hook: weights the (already predicted) particles by the pending detection.
  void prediction_and_update_pfStandardProposal(const mrpt::obs::CActionCollection* action,
                                                const mrpt::obs::CSensoryFrame* observation,
                                                const mrpt::bayes::CParticleFilter::TParticleFilterOptions& options) override;

 private:
  void moments(State& mean, Covariance& cov) const;
  void roughen();

  ParticleOptions options_;
  mrpt::bayes::CParticleFilter filter_;
  std::mt19937_64 rng_;
  Eigen::Vector3d pending_ = Eigen::Vector3d::Zero();
  bool resampling_ = false;  // set by the hook: MRPT is about to resample
};

/// "multinomial", "residual", "stratified" or "systematic" as MRPT's enum.
mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm resampling_method(const std::string& name);

}  // namespace kestrel::tracking
