// The aim's planning cost per frame: the target's futures drawn from a three-model estimate
// (imm_samples), the intercept_search over them, and the capture chance of a shot now, as the
// aim planner runs them each frame, with and without a target that reacts to the hunter or repeats itself. The goal is
// 5 ms a frame at 30 Hz (docs/control.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <kestrel/guidance/capture_chance.hpp>
#include <kestrel/guidance/intercept_search.hpp>
#include <kestrel/guidance/target_futures.hpp>

namespace {

using namespace kestrel;
using namespace kestrel::guidance;

// A target 6 m ahead crossing at 2 m/s, as an IMM of constant velocity, acceleration and a turn
// would hold it after a few frames.
std::vector<MotionHypothesis> estimate() {
  std::vector<MotionHypothesis> out;
  for (auto model : {tracking::MotionModel::constant_velocity, tracking::MotionModel::constant_acceleration,
                     tracking::MotionModel::coordinated_turn}) {
    MotionHypothesis h;
    h.model = model;
    h.mean.head<3>() = Eigen::Vector3d(6.0, -1.0, 2.0);
    h.mean.segment<3>(3) = Eigen::Vector3d(0.0, 2.0, 0.0);
    h.covariance = 0.01 * tracking::Covariance::Identity();
    h.probability = 1.0 / 3.0;
    out.push_back(h);
  }
  return out;
}

Engagement engagement(const TargetFutures& futures, const net::NetModel& net) {
  Engagement e;
  e.dt = 1.0 / 30.0;
  e.position = Eigen::Vector3d(0.0, 0.0, 3.0);
  e.geometry = {{0.0, 1.0, 2.0}, {0.1, 0.0, 0.0}};
  e.limits = {12.0, 8.0};
  e.min_altitude = 0.5;
  e.futures = &futures;
  e.net = &net;
  return e;
}

void BM_Futures(benchmark::State& state) {
  FuturesConfig config;
  config.samples = state.range(0);
  ImmSamples predictor(config, 1);
  const auto hypotheses = estimate();
  for (auto _ : state) benchmark::DoNotOptimize(predictor.predict(hypotheses).size());
}

void BM_PlanAndShotNow(benchmark::State& state) {
  FuturesConfig config;
  config.samples = state.range(0);
  ImmSamples predictor(config, 1);
  const net::NetModel net{net::NetParams{}};
  const auto futures = predictor.predict(estimate());
  InterceptSearch planner{InterceptSearchConfig{}};
  const Engagement e = engagement(futures, net);
  const Launch now{0.0, geometry::level_camera(e.position, 0.0), Eigen::Vector3d::Zero()};
  for (auto _ : state) {
    benchmark::DoNotOptimize(planner.command(e).velocity);
    benchmark::DoNotOptimize(capture_chance(futures, net, now).probability);
    planner.reset();  // every frame a full search: the launch flown is not kept
  }
  state.counters["planned"] = planner.command(e).terminal ? 0.0 : 1.0;  // 1: a launch was found, not the aim law
}

// The same with the hypothesis that the target reacts to the hunter held at 0.5: each candidate's
// chance also flies a quarter of the paths again against the hunter's path to that launch.
void BM_PlanAgainstAReactingTarget(benchmark::State& state) {
  FuturesConfig config;
  config.samples = state.range(0);
  config.reaction.prior = 0.5;
  ImmSamples predictor(config, 1);
  const net::NetModel net{net::NetParams{}};
  const auto futures = predictor.predict(estimate());
  InterceptSearch planner{InterceptSearchConfig{}};
  Engagement e = engagement(futures, net);
  e.reaction = predictor.reaction();
  for (auto _ : state) {
    benchmark::DoNotOptimize(planner.command(e).velocity);
    planner.reset();
  }
  state.counters["planned"] = planner.command(e).terminal ? 0.0 : 1.0;
}

// The futures with the hypothesis that the target repeats its past, after 20 s of a target circling
// every 4 s: the analogues searched in the kept past each frame.
void BM_FuturesOfATargetThatRepeatsItself(benchmark::State& state) {
  FuturesConfig config;
  config.samples = state.range(0);
  config.repeat.prior = 0.5;
  ImmSamples predictor(config, 1);
  const double w = 2.0 * M_PI / 4.0, dt = 1.0 / 30.0;
  tracking::State x = tracking::State::Zero();
  for (double t = 0.0; t < 20.0; t += dt) {
    x.head<3>() = Eigen::Vector3d(6.0 + 2.0 * std::cos(w * t), 2.0 * std::sin(w * t), 2.0);
    x.segment<3>(3) = Eigen::Vector3d(-2.0 * w * std::sin(w * t), 2.0 * w * std::cos(w * t), 0.0);
    predictor.observe(dt, x, Eigen::Vector3d::Zero());
  }
  const auto hypotheses = estimate();
  for (auto _ : state) benchmark::DoNotOptimize(predictor.predict(hypotheses).size());
}

BENCHMARK(BM_Futures)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FuturesOfATargetThatRepeatsItself)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlanAndShotNow)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlanAgainstAReactingTarget)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
