// The `kalman_tracker` node: one 3D constant-acceleration Kalman filter per track, an associator
// component, and the paper's track management (section 2.3).
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/plugin.hpp>
#include <kestrel/tracking/constant_acceleration.hpp>
#include <kestrel/tracking/track_manager.hpp>
#include <kestrel/tracking/tracker_params.hpp>

namespace kestrel::tracking {

namespace {

class KalmanTrackFilter final : public TrackFilter {
 public:
  KalmanTrackFilter(const Eigen::Vector3d& z, double q, double r, double p)
      : kf_(ConstantAccelerationKalman::start(z, p)), q_(q), r_(r) {}
  void predict(double dt) override { kf_.predict(dt, q_); }
  void update(const Eigen::Vector3d& z) override { kf_.update(z, r_); }
  PredictedMeasurement predicted_measurement() const override {
    return {kf_.position(), kf_.innovation_covariance(r_)};
  }
  Eigen::VectorXd state() const override { return kf_.x; }
  Eigen::MatrixXd covariance() const override { return kf_.P; }

 private:
  ConstantAccelerationKalman kf_;
  double q_, r_;
};

}  // namespace

class KalmanTracker final : public Node {
 public:
  static constexpr Input<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::Tracks> kTracks{"tracks"};

  static NodeSpec spec() {
    NodeSpec spec =
        NodeSpec("kalman_tracker", "Multi-target tracker: constant-acceleration Kalman filters (paper, 2.3)")
            .details(
                "Each track is a 9-state constant-acceleration Kalman filter (position, velocity, acceleration) "
                "measured by detection centroids. Q is the discrete white-noise-jerk model scaled by q, R = r I3, "
                "P0 = p diag(1^2, 30^2, 5.5^2) per axis. Detections no track claims (beyond the associator's gate, "
                "epsilon_max) start tracks; a track is deleted after max_misses consecutive misses; the selected "
                "target is the longest-living track (or the rule chosen).")
            .input(kDetections, "detections of one frame (camera frame)")
            .output(kTracks, "every track with its state and covariance, and the selected target")
            .param(param("q", 1.0).range(0.0, 1e6).with_unit("m^2/s^5").describe("process noise (jerk) intensity"))
            .param(param("r", 1.0).range(1e-9, 1e6).with_unit("m^2").describe(
                "measurement noise: R = r I3 (paper: best RMSE at r = 1.0)"))
            .param(param("p", 1.0).range(1e-9, 1e6).describe("initial covariance scale: P0 = p diag(1, 900, 30.25)"));
    return add_track_management_params(spec);
  }

  explicit KalmanTracker(NodeInit& init)
      : manager_(make_track_manager(
            init, [q = init.param<double>("q"), r = init.param<double>("r"), p = init.param<double>("p")](
                      const Eigen::Vector3d& z) { return std::make_unique<KalmanTrackFilter>(z, q, r, p); })) {}

  void process(Context& ctx) override { ctx.publish(kTracks, track(manager_, *ctx.get(kDetections))); }

 private:
  TrackManager manager_;
};
KESTREL_REGISTER_NODE(KalmanTracker)

}  // namespace kestrel::tracking
