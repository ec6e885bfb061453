// Tracker plus association time per frame for N targets with N detections: the Kalman tracker
// with the Hungarian and greedy associators, and the particle tracker.
#include <benchmark/benchmark.h>

#include <random>

#include "associators.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/track_manager.hpp"
#include "particle_track_filter.hpp"

namespace {

using namespace kestrel;
using namespace kestrel::tracking;

class KalmanFilter final : public TrackFilter {
 public:
  explicit KalmanFilter(const Eigen::Vector3d& z) : kf_(ConstantAccelerationKalman::start(z, 1.0)) {}
  void predict(double dt) override { kf_.predict(dt, 1.0); }
  void update(const Eigen::Vector3d& z) override { kf_.update(z, 1.0); }
  PredictedMeasurement predicted_measurement() const override {
    return {kf_.position(), kf_.innovation_covariance(1.0)};
  }
  Eigen::VectorXd state() const override { return kf_.x; }
  Eigen::MatrixXd covariance() const override { return kf_.P; }

 private:
  ConstantAccelerationKalman kf_;
};

// N targets on a 2 m grid, each circling slowly; detections carry 5 cm of noise.
std::vector<Eigen::Vector3d> detections(int n, int frame, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<Eigen::Vector3d> out;
  const double t = frame / 30.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d centre(2.0 * (i % 10), 2.0 * (i / 10), 5.0);
    out.push_back(centre + Eigen::Vector3d(0.3 * std::sin(t + i), 0.3 * std::cos(t + i), 0.0) +
                  Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  return out;
}

template <class A>
void run(benchmark::State& state, FilterFactory factory) {
  const int n = static_cast<int>(state.range(0));
  TrackManager manager(std::make_shared<A>(Metric::euclidean, 1.0), std::move(factory), TrackManagerOptions{});
  std::mt19937_64 rng(1);
  int frame = 0;
  for (; frame < 30; ++frame) manager.step(from_seconds(frame / 30.0), detections(n, frame, rng));  // tracks exist
  std::vector<std::vector<Eigen::Vector3d>> frames;
  for (int k = 0; k < 64; ++k) frames.push_back(detections(n, frame + k, rng));
  std::size_t k = 0;
  for (auto _ : state) {
    const auto tracks = manager.step(from_seconds((frame + static_cast<int>(k)) / 30.0), frames[k % frames.size()]);
    benchmark::DoNotOptimize(tracks.items.size());
    ++k;
    if (k % frames.size() == 0) frame += static_cast<int>(frames.size());
  }
  state.counters["tracks"] = static_cast<double>(manager.size());
}

FilterFactory kalman() {
  return [](const Eigen::Vector3d& z) { return std::make_unique<KalmanFilter>(z); };
}

void BM_KalmanHungarian(benchmark::State& state) { run<HungarianAssociator>(state, kalman()); }
void BM_KalmanGreedy(benchmark::State& state) { run<GreedyAssociator>(state, kalman()); }
void BM_ParticleHungarian(benchmark::State& state) {
  run<HungarianAssociator>(state, [seed = std::uint64_t{1}](const Eigen::Vector3d& z) mutable {
    return std::make_unique<ParticleTrackFilter>(z, ParticleOptions{}, ++seed);
  });
}

BENCHMARK(BM_KalmanHungarian)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_KalmanGreedy)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParticleHungarian)->Arg(1)->Arg(10)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
