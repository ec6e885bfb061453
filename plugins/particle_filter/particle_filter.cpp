#include "particle_filter.hpp"

namespace kestrel::tracking {

ComponentSpec ParticleFilter::spec() {
  ConfigSpec<ParticleOptions> c;
  declare(c);
  return ComponentSpec("particle", "Constant-acceleration particle filter per track (MRPT CParticleFilter)")
      .details(
          "Each track is a particle filter (mrpt::bayes::CParticleFilter over a CParticleFilterData model) whose "
          "particles follow the constant-acceleration model with white-noise jerk of intensity q; a detection "
          "weights them by a Gaussian likelihood of variance r per axis; MRPT resamples when the effective sample "
          "size falls below resample_below_ess, and a shrinkage kernel of bandwidth kernel_bandwidth regularises "
          "the copies (Musso; Liu and West). A detection much sharper than the cloud (just after birth, or a small "
          "r) is applied in up to correction_stages tempered stages (progressive correction). The component's seed "
          "is the random stream: each new track's seed derives from it.")
      .config(std::move(c));
}

ParticleFilter::ParticleFilter(const ComponentInit& init)
    : ParticleFilter(init.config<ParticleOptions>(), init.seed()) {}

std::unique_ptr<TrackFilter> ParticleFilter::start(const Eigen::Vector3d& first_detection) {
  // Each new track gets its own seed, derived from the component's: runs reproduce, tracks differ.
  return std::make_unique<ParticleTrackFilter>(first_detection, options_, seed_ + 0x9e3779b97f4a7c15ull * ++births_);
}

}  // namespace kestrel::tracking
