// The `particle_tracker` node: the same contract and outputs as kalman_tracker, with a particle
// filter per track built on MRPT's CParticleFilter.
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/track_manager.hpp>
#include <kestrel/tracking/tracker_params.hpp>

#include "particle_track_filter.hpp"

namespace kestrel::tracking {

class ParticleTracker final : public Node {
 public:
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::Tracks> kTracks{"tracks"};

  static NodeSpec spec() {
    NodeSpec spec =
        NodeSpec("particle_tracker", "Multi-target tracker: constant-acceleration particle filters (MRPT)")
            .details(
                "Same contract as kalman_tracker. Each track is a particle filter (mrpt::bayes::CParticleFilter over "
                "a CParticleFilterData model) whose particles follow the constant-acceleration model with "
                "white-noise jerk of intensity q; a detection weights them by a Gaussian likelihood of variance r "
                "per axis; MRPT resamples when the effective sample size falls below resample_below_ess, and a "
                "shrinkage kernel of bandwidth kernel_bandwidth regularises the copies (Musso; Liu and West). A "
                "detection much sharper than the cloud (just after birth, or a small r) is applied in up to "
                "correction_stages tempered stages (progressive correction), so the cloud does not collapse.")
            .input(kDetections, "detections of one frame (camera frame)")
            .output(kTracks, "every track with its state and covariance (particle moments), and the selected target")
            .param(param("particles", 1000).range(1, 1000000).describe("particles per track"))
            .param(param("resampling", std::string("systematic"))
                       .one_of({"multinomial", "residual", "stratified", "systematic"})
                       .describe("MRPT resampling method"))
            .param(param("resample_below_ess", 0.5).range(0.0, 1.0).describe("resample when ESS / N falls below this"))
            .param(param("q", 1.0).range(0.0, 1e6).with_unit("m^2/s^5").describe("process noise (jerk) intensity"))
            .param(param("r", 1.0).range(1e-9, 1e6).with_unit("m^2").describe("measurement noise variance per axis"))
            .param(param("p", 1.0).range(1e-9, 1e6).describe(
                "initial spread: particles drawn from N(z, p diag(1, 900, 30.25))"))
            .param(param("kernel_bandwidth", 0.5)
                       .range(0.0, 1.0)
                       .describe("regularisation after resampling, h of the shrinkage kernel (Musso's optimum for 1000 "
                                 "particles in 9 dimensions: 0.54); 0 = none"))
            .param(param("correction_stages", 10)
                       .range(1, 1000)
                       .describe("most tempered stages one detection is applied in; 1 = a plain update"));
    return add_track_management_params(spec);
  }

  explicit ParticleTracker(NodeInit& init) : manager_(make_track_manager(init, factory(init))) {}

  void process(Context& ctx) override { ctx.publish(kTracks, track(manager_, *ctx.get(kDetections))); }

 private:
  static FilterFactory factory(NodeInit& init) {
    ParticleOptions o;
    o.particles = init.param<int>("particles");
    o.resampling = init.param<std::string>("resampling");
    o.resample_below_ess = init.param<double>("resample_below_ess");
    o.q = init.param<double>("q");
    o.r = init.param<double>("r");
    o.p = init.param<double>("p");
    o.kernel_bandwidth = init.param<double>("kernel_bandwidth");
    o.max_correction_stages = init.param<int>("correction_stages");
    // Each new track gets its own seed, derived from the node's: runs reproduce, tracks differ.
    return [o, seed = init.seed(), births = std::make_shared<std::uint64_t>(0)](const Eigen::Vector3d& z) {
      return std::make_unique<ParticleTrackFilter>(z, o, seed + 0x9e3779b97f4a7c15ull * ++*births);
    };
  }

  TrackManager manager_;
};
KESTREL_REGISTER_NODE(ParticleTracker)

}  // namespace kestrel::tracking
