#include "kestrel/guidance/target_futures.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace kestrel::guidance {

double TargetFutures::horizon_s() const {
  return paths.empty() ? 0.0 : step_s * static_cast<double>(paths.front().cols() - 1);
}

Eigen::Vector3d TargetFutures::position(std::size_t i, double t) const {
  const Eigen::Matrix3Xd& path = paths[i];
  const double k = std::clamp(t / step_s, 0.0, static_cast<double>(path.cols() - 1));
  const auto lo = static_cast<Eigen::Index>(std::floor(k));
  const Eigen::Index hi = std::min<Eigen::Index>(lo + 1, path.cols() - 1);
  const double w = k - static_cast<double>(lo);
  return (1.0 - w) * path.col(lo) + w * path.col(hi);
}

Eigen::Vector3d TargetFutures::mean(double t) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < paths.size(); ++i) sum += position(i, t);
  return paths.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(paths.size()));
}

Eigen::Vector3d TargetFutures::mean_velocity(double t) const {
  const double a = std::max(0.0, t - 0.5 * step_s), b = std::min(horizon_s(), t + 0.5 * step_s);
  return b > a ? Eigen::Vector3d((mean(b) - mean(a)) / (b - a)) : Eigen::Vector3d::Zero();
}

ComponentSpec ImmSamples::spec() {
  using C = FuturesConfig;
  ConfigSpec<C> c;
  c.param("samples", &C::samples).range(1, 4096).describe("how many paths are drawn");
  c.param("horizon_s", &C::horizon_s).with_unit("s").range(0.2, 30.0).describe("how far ahead each path goes");
  c.param("step_s", &C::step_s).with_unit("s").range(0.01, 1.0).describe("the paths' time step");
  c.param("q_velocity", &C::q_velocity)
      .with_unit("m^2/s^3")
      .range(0.0, 1e6)
      .describe("the constant-velocity model's paths: white-noise acceleration intensity (how fast they spread)");
  c.param("q_acceleration", &C::q_acceleration)
      .with_unit("m^2/s^5")
      .range(0.0, 1e6)
      .describe("the constant-acceleration model's paths: white-noise jerk intensity");
  c.param("q_turn", &C::q_turn)
      .with_unit("m^2/s^5")
      .range(0.0, 1e6)
      .describe("the coordinated turn's paths: white-noise jerk intensity");
  c.param("covariance_scale", &C::covariance_scale)
      .range(0.0, 100.0)
      .describe(
          "each path starts from a draw of its model's state with the estimate's covariance taken this many times (1: "
          "as the filter reports it); the aim's report, futures_calibration, says whether the paths are too wide or "
          "too "
          "narrow");
  c.param("max_speed_m_s", &C::max_speed_m_s)
      .with_unit("m/s")
      .range(0.1, 100.0)
      .describe("no path flies faster (a multirotor's top speed)");
  c.param("max_acceleration_m_s2", &C::max_acceleration_m_s2)
      .with_unit("m/s^2")
      .range(0.1, 100.0)
      .describe("no path accelerates harder");
  using R = ReactionConfig;
  c.param("reaction_prior", &C::reaction, &R::prior)
      .range(0.0, 1.0)
      .describe(
          "the weight of the hypothesis that the target reacts to the hunter (flies away from it within "
          "reaction_radius_m) before the sightings say; 0: no such hypothesis");
  c.param("reaction_radius_m", &C::reaction, &R::radius_m)
      .with_unit("m")
      .range(0.0, 100.0)
      .describe("a reacting target flies away from a hunter this near");
  c.param("reaction_speed_m_s", &C::reaction, &R::speed_m_s)
      .with_unit("m/s")
      .range(0.0, 100.0)
      .describe("straight away from the hunter, at its own speed, or this speed if it is slower");
  c.param("reaction_acceleration_m_s2", &C::reaction, &R::acceleration_m_s2)
      .with_unit("m/s^2")
      .range(0.1, 100.0)
      .describe("accelerating no harder than this");
  c.param("reaction_response_s", &C::reaction, &R::response_s)
      .with_unit("s")
      .range(0.01, 10.0)
      .describe("its velocity's time constant towards the flight away (a multirotor's response)");
  c.param("reaction_concentration", &C::reaction, &R::concentration)
      .range(0.01, 100.0)
      .describe(
          "how tightly a reacting target's motion points away from the hunter (the sightings' headings are scored "
          "against it, and against any heading alike, each frame the hunter is within the radius)");
  c.param("reaction_evidence_time_s", &C::reaction, &R::evidence_time_s)
      .with_unit("s")
      .range(0.01, 100.0)
      .describe("this long of frames counts as one observation (the estimate's frames are not independent)");
  c.param("reaction_memory_s", &C::reaction, &R::memory_s)
      .with_unit("s")
      .range(0.1, 3600.0)
      .describe("the evidence fades towards the prior with this time constant: a target may change its ways");
  c.param("reaction_max_probability", &C::reaction, &R::max_probability)
      .range(0.5, 1.0)
      .describe("neither hypothesis is ever surer than this");
  using P = RepeatConfig;
  c.param("repeat_prior", &C::repeat, &P::prior)
      .range(0.0, 1.0)
      .describe(
          "the weight of the hypothesis that the target repeats its own past (the method of analogues: what followed "
          "the past states nearest the present one) before the sightings say; 0: no such hypothesis");
  c.param("repeat_window_s", &C::repeat, &P::window_s)
      .with_unit("s")
      .range(1.0, 600.0)
      .describe("how much of the target's past is searched for analogues");
  c.param("repeat_matches", &C::repeat, &P::matches).range(1, 256).describe("the analogues used, nearest first");
  c.param("repeat_position_m", &C::repeat, &P::position_m)
      .with_unit("m")
      .range(0.01, 100.0)
      .describe("the scale of a position match");
  c.param("repeat_velocity_m_s", &C::repeat, &P::velocity_m_s)
      .with_unit("m/s")
      .range(0.01, 100.0)
      .describe("the scale of a velocity match");
  c.param("repeat_max_distance", &C::repeat, &P::max_distance)
      .range(0.1, 100.0)
      .describe("no analogue farther than this from the present state, in those scales");
  c.param("repeat_check_s", &C::repeat, &P::check_s)
      .with_unit("s")
      .range(0.1, 10.0)
      .describe("how far ahead the analogues' forecasts and the models' are checked against the sightings");
  c.param("repeat_error_m", &C::repeat, &P::error_m)
      .with_unit("m")
      .range(0.01, 100.0)
      .describe("the forecasts' error scale in that check");
  c.param("repeat_evidence_time_s", &C::repeat, &P::evidence_time_s)
      .with_unit("s")
      .range(0.01, 100.0)
      .describe("this long of sightings counts as one observation");
  c.param("repeat_max_probability", &C::repeat, &P::max_probability)
      .range(0.5, 1.0)
      .describe("neither hypothesis is ever surer than this");
  c.rule("step_s < horizon_s", {"step_s", "horizon_s"}, [](const C& k) { return k.step_s < k.horizon_s; });
  return ComponentSpec("imm_samples", "The target's futures, sampled from each model of its estimate")
      .details(
          "Draws `samples` paths over horizon_s: each motion model of the aim's estimate (an IMM's constant "
          "velocity, constant acceleration and coordinated turn, or the one model of a Kalman filter) gives paths in "
          "proportion to its probability, each starting from a draw of that model's state (mean and covariance) and "
          "integrated every step_s with the model's transition and its white-noise manoeuvre (q_*), speed and "
          "acceleration clipped to max_speed_m_s and max_acceleration_m_s2. The planner chooses where and when to "
          "launch from these paths, and the fire policy weighs a shot now against one later on the same paths. With "
          "reaction_prior above 0, the target may also react to the hunter: within reaction_radius_m it flies away "
          "from it; the chance of a launch counts the futures both ways, the reacting ones flown against the "
          "hunter's own path, weighed by how well each hypothesis explains the headings seen near the hunter.")
      .config(std::move(c));
}

ImmSamples::ImmSamples(const ComponentInit& init) : ImmSamples(init.config<FuturesConfig>(), init.seed()) {}

ImmSamples::ImmSamples(FuturesConfig config, std::uint64_t seed) : cfg_(config), rng_(seed) {}

double ImmSamples::q_of(tracking::MotionModel model) const {
  using M = tracking::MotionModel;
  return model == M::constant_velocity  ? cfg_.q_velocity
         : model == M::coordinated_turn ? cfg_.q_turn
                                        : cfg_.q_acceleration;
}

namespace {

// A square root of a covariance (S S^T = P) that also takes a singular one (a constant-velocity
// state has no acceleration spread).
tracking::Covariance square_root(const tracking::Covariance& P) {
  const Eigen::SelfAdjointEigenSolver<tracking::Covariance> eig(0.5 * (P + P.transpose()));
  return eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

// Each hypothesis's share of n paths, by largest remainder; every path is someone's.
std::vector<std::int64_t> shares(const std::vector<MotionHypothesis>& hypotheses, std::int64_t n) {
  double total = 0.0;
  for (const auto& h : hypotheses) total += std::max(0.0, h.probability);
  std::vector<std::int64_t> count(hypotheses.size(), 0);
  std::vector<std::pair<double, std::size_t>> remainder;
  std::int64_t given = 0;
  for (std::size_t i = 0; i < hypotheses.size(); ++i) {
    const double exact = total > 0.0 ? static_cast<double>(n) * std::max(0.0, hypotheses[i].probability) / total
                                     : static_cast<double>(n) / static_cast<double>(hypotheses.size());
    count[i] = static_cast<std::int64_t>(std::floor(exact));
    given += count[i];
    remainder.emplace_back(exact - static_cast<double>(count[i]), i);
  }
  std::stable_sort(remainder.begin(), remainder.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; given < n && k < remainder.size(); ++k, ++given) ++count[remainder[k].second];
  return count;
}

void clip(Eigen::Ref<Eigen::Vector3d> v, double limit) {
  const double n = v.norm();
  if (n > limit) v *= limit / n;
}

}  // namespace

TargetFutures ImmSamples::predict(const std::vector<MotionHypothesis>& hypotheses) {
  TargetFutures futures;
  futures.step_s = cfg_.step_s;
  if (hypotheses.empty()) return futures;
  const auto steps = static_cast<Eigen::Index>(std::ceil(cfg_.horizon_s / cfg_.step_s - 1e-9));
  const std::vector<std::int64_t> count = shares(hypotheses, cfg_.samples);
  futures.paths.reserve(static_cast<std::size_t>(cfg_.samples));
  for (std::size_t h = 0; h < hypotheses.size(); ++h) {
    if (count[h] == 0) continue;
    const MotionHypothesis& hyp = hypotheses[h];
    const tracking::Covariance start_root = square_root(cfg_.covariance_scale * hyp.covariance);
    const tracking::Covariance noise_root =
        square_root(tracking::model_process_noise(hyp.model, cfg_.step_s, q_of(hyp.model)));
    for (std::int64_t n = 0; n < count[h]; ++n) {
      tracking::State z;
      for (int i = 0; i < 9; ++i) z[i] = normal_(rng_);
      tracking::State x = hyp.mean + start_root * z;
      clip(x.segment<3>(3), cfg_.max_speed_m_s);
      clip(x.segment<3>(6), cfg_.max_acceleration_m_s2);
      Eigen::Matrix3Xd path(3, steps + 1);
      path.col(0) = x.head<3>();
      for (Eigen::Index k = 1; k <= steps; ++k) {
        for (int i = 0; i < 9; ++i) z[i] = normal_(rng_);
        const Eigen::Vector3d velocity = x.segment<3>(3);
        x = tracking::model_transition(hyp.model, x, cfg_.step_s) * x + noise_root * z;
        clip(x.segment<3>(6), cfg_.max_acceleration_m_s2);
        clip(x.segment<3>(3), cfg_.max_speed_m_s);
        // The position follows the clipped velocities (trapezoidal), so no step is faster than the limit.
        x.head<3>() = path.col(k - 1) + 0.5 * (velocity + x.segment<3>(3)) * cfg_.step_s;
        path.col(k) = x.head<3>();
      }
      futures.paths.push_back(std::move(path));
    }
  }
  // The target repeating its past: a share of the paths, by the hypothesis's weight, replaced by
  // the analogues' (spread over the models' paths, so that each model keeps its share of the rest).
  if (cfg_.repeat.prior > 0.0 && !futures.empty()) {
    const auto analogues = repeat_.paths(steps, cfg_.step_s, futures.mean(cfg_.repeat.check_s));
    const auto n = futures.paths.size();
    const auto m = std::min(n, static_cast<std::size_t>(std::lround(repeat_.probability() * static_cast<double>(n))));
    if (!analogues.empty())
      for (std::size_t i = 0; i < m; ++i) futures.paths[i * n / m] = analogues[i % analogues.size()];
  }
  return futures;
}

void ImmSamples::observe(double dt, const tracking::State& target, const Eigen::Vector3d& hunter) {
  belief_.observe(dt, target.head<3>(), target.segment<3>(3), hunter);
  repeat_.observe(dt, target.head<3>(), target.segment<3>(3));
}

}  // namespace kestrel::guidance
