// Tracker plus association time per frame for N targets with N detections: the tracker with the
// Kalman filter and the Hungarian and greedy associators, and with the particle filter.
#include <benchmark/benchmark.h>

#include <random>

#include "associators.hpp"
#include "kestrel/tracking/kalman_filter.hpp"
#include "kestrel/tracking/track_manager.hpp"
#include "particle_filter.hpp"

namespace {

using namespace kestrel;
using namespace kestrel::tracking;

// N targets on a 2 m grid, each circling slowly; detections carry 5 cm of noise.
std::vector<Eigen::Vector3d> detections(int n, int frame, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<Eigen::Vector3d> out;
  const double t = frame / 30.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d centre(2.0 * (i % 10), 2.0 * (i / 10), 5.0);
    const double nz = noise(rng), ny = noise(rng), nx = noise(rng);  // in sequence, z first, for every compiler
    out.push_back(centre + Eigen::Vector3d(0.3 * std::sin(t + i), 0.3 * std::cos(t + i), 0.0) +
                  Eigen::Vector3d(nx, ny, nz));
  }
  return out;
}

template <class A>
void run(benchmark::State& state, std::shared_ptr<Filter> filter) {
  const int n = static_cast<int>(state.range(0));
  TrackManager manager(TrackerParts{std::move(filter), std::make_shared<A>(Metric::euclidean, 1.0),
                                    std::make_shared<ConsecutiveHitsInitiator>(ConsecutiveHitsConfig{}),
                                    std::make_shared<ConsecutiveMissesDeleter>(ConsecutiveMissesConfig{}),
                                    std::make_shared<LongestLivingSelector>()});
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

std::shared_ptr<Filter> kalman() { return std::make_shared<KalmanFilter>(KalmanConfig{}); }

void BM_KalmanHungarian(benchmark::State& state) { run<HungarianAssociator>(state, kalman()); }
void BM_KalmanGreedy(benchmark::State& state) { run<GreedyAssociator>(state, kalman()); }
void BM_ParticleHungarian(benchmark::State& state) {
  run<HungarianAssociator>(state, std::make_shared<ParticleFilter>(ParticleOptions{}, 1));
}

BENCHMARK(BM_KalmanHungarian)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_KalmanGreedy)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParticleHungarian)->Arg(1)->Arg(10)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
