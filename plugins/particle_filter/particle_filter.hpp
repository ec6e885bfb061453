#pragma once
// The `particle` filter component: each track is a constant-acceleration particle filter on
// MRPT's machinery (ParticleTrackFilter). The component's seed is its random stream: each new
// track draws its own seed from it, so runs reproduce and tracks never share a stream.
#include <cstdint>
#include <memory>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/filter.hpp"
#include "particle_track_filter.hpp"

namespace kestrel::tracking {

class ParticleFilter final : public Filter {
 public:
  static ComponentSpec spec();
  /// Declares the particle filter's parameters.
  static void declare(ConfigSpec<ParticleOptions>& c) {
    using PF = mrpt::bayes::CParticleFilter;
    c.param("particles", &ParticleOptions::particles).range(1, 1000000).describe("particles per track");
    c.choice("resampling", &ParticleOptions::resampling,
             {{"multinomial", PF::prMultinomial},
              {"residual", PF::prResidual},
              {"stratified", PF::prStratified},
              {"systematic", PF::prSystematic}})
        .describe("MRPT resampling method");
    c.param("resample_below_ess", &ParticleOptions::resample_below_ess)
        .range(0.0, 1.0)
        .describe("resample when ESS / N falls below this");
    c.param("q", &ParticleOptions::q).range(0.0, 1e6).with_unit("m^2/s^5").describe("process noise (jerk) intensity");
    c.param("r", &ParticleOptions::r).range(1e-9, 1e6).with_unit("m^2").describe("measurement noise variance per axis");
    c.param("p", &ParticleOptions::p)
        .range(1e-9, 1e6)
        .describe("initial spread: particles drawn from N(z, p diag(1, 900, 30.25))");
    c.param("kernel_bandwidth", &ParticleOptions::kernel_bandwidth)
        .range(0.0, 1.0)
        .describe(
            "regularisation after resampling, h of the shrinkage kernel (Musso's optimum for 1000 particles in 9 "
            "dimensions: 0.54); 0 = none");
    c.param("correction_stages", &ParticleOptions::max_correction_stages)
        .range(1, 1000)
        .describe("most tempered stages one detection is applied in; 1 = a plain update");
  }

  explicit ParticleFilter(const ComponentInit& init);
  ParticleFilter(const ParticleOptions& options, std::uint64_t seed) : options_(options), seed_(seed) {}

  std::unique_ptr<TrackFilter> start(const Eigen::Vector3d& first_detection) override;

 private:
  ParticleOptions options_;
  std::uint64_t seed_;
  std::uint64_t births_ = 0;
};

}  // namespace kestrel::tracking
