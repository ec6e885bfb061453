#pragma once
// The target's predicted futures: paths it may fly over the next seconds, sampled from the aim's
// estimate. Each motion model of the estimate (an IMM's constant velocity, constant acceleration
// and coordinated turn) gives paths in proportion to its probability, each path starting from a
// draw of that model's state and driven by that model's own manoeuvre noise. The planner and the
// fire decision read the same paths, so that a shot now and a shot later are weighed alike.
//
//   - id: aim
//     type: aim_planner
//     params:
//       predictor: {type: imm_samples, samples: 64, horizon_s: 3.0}
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <random>
#include <string_view>
#include <vector>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/guidance/reaction.hpp"
#include "kestrel/guidance/repeat_prediction.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/motion_models.hpp"

namespace kestrel::guidance {

/// Sampled paths of the target, on a common time grid from the estimate's time (world frame).
struct TargetFutures {
  double step_s = 0.1;
  /// One matrix per path: column k is the position at k * step_s.
  std::vector<Eigen::Matrix3Xd> paths;

  std::size_t size() const { return paths.size(); }
  bool empty() const { return paths.empty(); }
  double horizon_s() const;
  /// Path i at time t (linear between the grid's points; held past its ends).
  Eigen::Vector3d position(std::size_t i, double t) const;
  /// The mean over the paths at time t.
  Eigen::Vector3d mean(double t) const;
  /// The mean velocity over the paths at time t (a central difference over one step).
  Eigen::Vector3d mean_velocity(double t) const;
};

/// One hypothesis of the target's motion: a Gaussian over its [p v a] under one motion model.
struct MotionHypothesis {
  tracking::MotionModel model = tracking::MotionModel::constant_acceleration;
  tracking::State mean = tracking::State::Zero();
  tracking::Covariance covariance = tracking::Covariance::Identity();
  double probability = 1.0;
};

struct FuturesConfig {
  std::int64_t samples = 64;
  double horizon_s = 3.0;
  double step_s = 0.1;
  double q_velocity = 4.0;        ///< m^2/s^3: constant velocity's white-noise acceleration
  double q_acceleration = 10.0;   ///< m^2/s^5: constant acceleration's white-noise jerk
  double q_turn = 10.0;           ///< m^2/s^5: the coordinated turn's white-noise jerk
  double covariance_scale = 1.0;  ///< the estimate's covariance is taken this many times for the paths' starts
  double max_speed_m_s = 20.0;
  double max_acceleration_m_s2 = 12.0;
  ReactionConfig reaction;  ///< the hypothesis that it reacts to the hunter (prior 0: none)
  RepeatConfig repeat;      ///< the hypothesis that it repeats its own past (prior 0: none)
};

/// The component of kind "predictor" that draws the futures.
class Predictor {
 public:
  static constexpr std::string_view kKind = "predictor";
  virtual ~Predictor() = default;
  /// Paths from the estimate's hypotheses (their probabilities need not sum to 1).
  virtual TargetFutures predict(const std::vector<MotionHypothesis>& hypotheses) = 0;
  /// One frame of the estimate ([p v a], world) with the hunter at `hunter`: what the predictor
  /// learns of how the target behaves towards it.
  virtual void observe(double /*dt*/, const tracking::State& /*target*/, const Eigen::Vector3d& /*hunter*/) {}
  /// The hypothesis that the target reacts to the hunter, if the predictor holds one.
  virtual const ReactionBelief* reaction() const { return nullptr; }
  /// The weight of the hypothesis that the target repeats its own past, if the predictor holds one.
  virtual std::optional<double> repeating() const { return std::nullopt; }
  /// A new target: forget what was learnt of the last.
  virtual void reset() {}
};

/// `imm_samples`: paths drawn per model, in proportion to its probability (at least one path for a
/// model of probability >= 1/samples), integrated with the model's transition and process noise,
/// speed and acceleration clipped to what a multirotor flies. Its random draws come from the
/// component's seed, so a run reproduces.
class ImmSamples final : public Predictor {
 public:
  static ComponentSpec spec();
  explicit ImmSamples(const ComponentInit& init);
  ImmSamples(FuturesConfig config, std::uint64_t seed);
  TargetFutures predict(const std::vector<MotionHypothesis>& hypotheses) override;
  void observe(double dt, const tracking::State& target, const Eigen::Vector3d& hunter) override;
  const ReactionBelief* reaction() const override { return cfg_.reaction.prior > 0.0 ? &belief_ : nullptr; }
  std::optional<double> repeating() const override {
    return cfg_.repeat.prior > 0.0 ? std::optional<double>(repeat_.probability()) : std::nullopt;
  }
  void reset() override { belief_.reset(); }
  const FuturesConfig& config() const { return cfg_; }

 private:
  double q_of(tracking::MotionModel model) const;

  FuturesConfig cfg_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  ReactionBelief belief_{cfg_.reaction};
  RepeatPredictor repeat_{cfg_.repeat};
};

}  // namespace kestrel::guidance
