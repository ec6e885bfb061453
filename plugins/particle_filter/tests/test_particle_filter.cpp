// The particle track filter (MRPT CParticleFilter) and the `particle` filter component, on
// targets whose path is known.
#include <gmock/gmock.h>

#include <cmath>
#include <random>

#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/deleter.hpp"
#include "kestrel/tracking/initiator.hpp"
#include "kestrel/tracking/selector.hpp"
#include "kestrel/tracking/track_manager.hpp"
#include "particle_filter.hpp"
#include "particle_track_filter.hpp"

using namespace kestrel;
using namespace kestrel::tracking;

namespace {

// Mean position error over the last half of a run tracking a figure-8-like path.
double tracking_error(const ParticleOptions& o) {
  ParticleTrackFilter f({0, 0, 5}, o, 1);
  std::mt19937_64 rng(2);
  std::normal_distribution<double> noise(0, 0.1);
  double error = 0;
  int n = 0;
  for (int k = 1; k <= 120; ++k) {
    f.predict(1.0 / 30);
    const double t = k / 30.0;
    const Eigen::Vector3d truth(std::sin(0.5 * t), 0.5 * std::sin(t), 5.0);
    const double nz = noise(rng), ny = noise(rng), nx = noise(rng);  // in sequence, z first, for every compiler
    f.update(truth + Eigen::Vector3d(nx, ny, nz));
    if (k > 60) {
      error += (f.state().head<3>() - truth).norm();
      ++n;
    }
  }
  return error / n;
}

}  // namespace

// Detections carry 0.1 m of Gaussian noise per axis: their mean error is 0.1 sqrt(8 / pi) =
// 0.16 m. A filter on the path averages that noise down, so its mean error is smaller.
const double kDetectionMeanError = 0.1 * std::sqrt(8.0 / M_PI);

TEST(ParticleTrackFilter, FollowsAManoeuvringTarget) {
  EXPECT_LT(tracking_error(ParticleOptions{}), kDetectionMeanError);  // the node's defaults
  ParticleOptions narrow;
  narrow.p = 0.01;  // a prior closer to a hovering drone's
  EXPECT_LT(tracking_error(narrow), kDetectionMeanError);
}

TEST(ParticleTrackFilter, EveryResamplingMethodWorks) {
  using PF = mrpt::bayes::CParticleFilter;
  for (const auto method : {PF::prMultinomial, PF::prResidual, PF::prStratified, PF::prSystematic}) {
    ParticleOptions o;
    o.p = 0.01;
    o.resampling = method;
    EXPECT_LT(tracking_error(o), kDetectionMeanError) << method;
  }
}

// MRPT resamples with its global generator, which each filter seeds: one run after another with
// the same seed gives the same estimate (as lockstep graph runs do).
TEST(ParticleTrackFilter, SameSeedSameEstimate) {
  auto run = [](std::uint64_t seed) {
    ParticleTrackFilter f({1, 2, 3}, ParticleOptions{}, seed);
    for (int k = 0; k < 20; ++k) {
      f.predict(0.1);
      f.update({1.0 + 0.05 * k, 2, 3});
    }
    return Eigen::VectorXd(f.state());
  };
  EXPECT_EQ(run(7), run(7));
  EXPECT_NE(run(7), run(8));
}

namespace {

// RMSE over seconds 2-12 of the particle filter and of the Kalman filter with the same model on
// the same noisy detections of a figure-8 (noise 0.15 m per axis).
std::pair<double, double> against_kalman(const ParticleOptions& o, std::uint64_t seed) {
  ParticleTrackFilter pf({0, 0, 5}, o, seed);
  auto kf = ConstantAccelerationKalman::start({0, 0, 5}, o.p);
  std::mt19937_64 rng(seed + 100);
  std::normal_distribution<double> noise(0, 0.15);
  double pf_sq = 0, kf_sq = 0;
  int n = 0;
  for (int k = 1; k <= 360; ++k) {
    pf.predict(1.0 / 30);
    kf.predict(1.0 / 30, o.q);
    const double t = k / 30.0;
    const Eigen::Vector3d truth(std::sin(0.52 * t), 0.5 * std::sin(1.04 * t), 5.0);
    const double nz = noise(rng), ny = noise(rng), nx = noise(rng);  // in sequence, z first, for every compiler
    const Eigen::Vector3d z = truth + Eigen::Vector3d(nx, ny, nz);
    pf.update(z);
    kf.update(z, o.r);
    if (k > 60) {
      pf_sq += (pf.state().head<3>() - truth).squaredNorm();
      kf_sq += (kf.position() - truth).squaredNorm();
      ++n;
    }
  }
  return {std::sqrt(pf_sq / n), std::sqrt(kf_sq / n)};
}

}  // namespace

// On a linear-Gaussian model the Kalman filter is optimal; a sound particle filter comes close.
// With r = 0.02 the detection is far sharper than the birth prior (30 m/s of velocity spread):
// without progressive correction the cloud collapses onto a few particles and loses the target.
TEST(ParticleTrackFilter, ComesCloseToTheKalmanFilterOnALinearGaussianTarget) {
  for (const double r : {1.0, 0.02}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      ParticleOptions o;
      o.r = r;
      const auto [pf, kf] = against_kalman(o, seed);
      EXPECT_LT(pf, 1.2 * kf) << "r " << r << ", seed " << seed;
    }
  }
}

TEST(ParticleTrackFilter, ProgressiveCorrectionKeepsASharpDetectionFromCollapsingTheCloud) {
  ParticleOptions plain;
  plain.r = 0.02;
  plain.max_correction_stages = 1;
  ParticleOptions staged = plain;
  staged.max_correction_stages = 10;
  int plain_lost = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    plain_lost += against_kalman(plain, seed).first > 1.0;
    const auto [pf, kf] = against_kalman(staged, seed);
    EXPECT_LT(pf, 1.2 * kf) << "seed " << seed;  // as close to the optimal filter as with a broad r
  }
  EXPECT_GE(plain_lost, 1);  // the plain update lost the target (metres off) in some runs
}

// MRPT resamples with a process-wide generator; each track reseeds it from its own stream, so a
// track's estimate does not depend on what other tracks did in between (the order of tracks and
// nodes cannot change a lockstep run).
TEST(ParticleTrackFilter, TracksDoNotShareARandomStream) {
  auto detection = [](int k) { return Eigen::Vector3d(0.02 * k, 0.0, 5.0); };
  ParticleOptions o;
  o.r = 0.05;  // sharp enough that MRPT resamples
  ParticleTrackFilter alone({0, 0, 5}, o, 11);
  for (int k = 1; k <= 15; ++k) {
    alone.predict(1.0 / 30);
    alone.update(detection(k));
  }
  ParticleTrackFilter a({0, 0, 5}, o, 11), other({2, 0, 6}, o, 12);
  for (int k = 1; k <= 15; ++k) {
    other.predict(1.0 / 30);
    other.update({2.0, 0.01 * k, 6.0});
    a.predict(1.0 / 30);
    a.update(detection(k));
  }
  EXPECT_EQ(Eigen::VectorXd(a.state()), Eigen::VectorXd(alone.state()));
}

namespace {

// Exact detections of two targets crossing the view on straight lines at constant velocity, 1.5 m
// apart, through the tracker with the `particle` filter component (seeded as a graph would).
struct TwoTargets {
  static Eigen::Vector3d a(int k) { return {-1.0 + 0.6 * k / 30.0, 0.0, 5.0}; }
  static Eigen::Vector3d b(int k) { return {1.0 - 0.6 * k / 30.0, 1.5, 6.0}; }

  static msg::Tracks run(std::uint64_t seed, int frames) {
    ParticleOptions o;
    o.r = 0.05;
    TrackManager m(TrackerParts{std::make_shared<ParticleFilter>(o, seed), std::make_shared<NearestAssociator>(),
                                std::make_shared<ConsecutiveHitsInitiator>(ConsecutiveHitsConfig{}),
                                std::make_shared<ConsecutiveMissesDeleter>(ConsecutiveMissesConfig{}),
                                std::make_shared<LongestLivingSelector>()});
    msg::Tracks out;
    for (int k = 0; k < frames; ++k) out = m.step(from_seconds(k / 30.0), {a(k), b(k)});
    return out;
  }

  // Pairs each track with the detection within 1 m: enough for targets 1.5 m apart.
  struct NearestAssociator final : Associator {
    algorithms::Assignment associate(const std::vector<PredictedMeasurement>& tracks,
                                     const std::vector<Eigen::Vector3d>& detections) const override {
      algorithms::Assignment a;
      a.row_to_col.assign(tracks.size(), -1);
      a.col_to_row.assign(detections.size(), -1);
      for (std::size_t t = 0; t < tracks.size(); ++t)
        for (std::size_t d = 0; d < detections.size(); ++d)
          if (a.col_to_row[d] < 0 && (tracks[t].position - detections[d]).norm() < 1.0) {
            a.row_to_col[t] = static_cast<int>(d);
            a.col_to_row[d] = static_cast<int>(t);
            break;
          }
      return a;
    }
  };
};

}  // namespace

// Two tracks, born in the first frame in the detections' order, each following its target: the
// position within 5 cm and the velocity within 0.15 m/s of the truth after 3 s.
TEST(ParticleFilterComponent, TracksTwoTargetsWhosePathsAreKnown) {
  const msg::Tracks out = TwoTargets::run(42, 91);
  ASSERT_EQ(out.items.size(), 2u);
  EXPECT_EQ(out.items[0].id, 1u);
  EXPECT_EQ(out.items[1].id, 2u);
  EXPECT_EQ(*out.selected_id, 1u);
  EXPECT_EQ(out.items[0].hits, 91);
  const Eigen::Vector3d va(0.6, 0, 0), vb(-0.6, 0, 0);
  EXPECT_LT((out.items[0].position() - TwoTargets::a(90)).norm(), 0.05);
  EXPECT_LT((out.items[1].position() - TwoTargets::b(90)).norm(), 0.05);
  EXPECT_LT((out.items[0].state.segment<3>(3) - va).norm(), 0.15);
  EXPECT_LT((out.items[1].state.segment<3>(3) - vb).norm(), 0.15);
}

// The component's seed is its random stream: the same seed gives the same tracks to the last
// bit, another seed other tracks, and the two tracks of one run never share a stream.
TEST(ParticleFilterComponent, EachTrackDrawsItsSeedFromTheComponentsSeed) {
  const auto first = TwoTargets::run(42, 10), again = TwoTargets::run(42, 10), other = TwoTargets::run(43, 10);
  EXPECT_EQ(first.items[0].state, again.items[0].state);
  EXPECT_EQ(first.items[1].state, again.items[1].state);
  EXPECT_NE(first.items[0].state, other.items[0].state);
  // Track by track, the component gives the seeds seed + k * golden ratio, k = 1, 2, ...
  ParticleOptions o;
  o.r = 0.05;
  ParticleFilter component(o, 42);
  auto t1 = component.start(TwoTargets::a(0));
  ParticleTrackFilter by_hand(TwoTargets::a(0), o, 42 + 0x9e3779b97f4a7c15ull);
  EXPECT_EQ(t1->state(), Eigen::VectorXd(by_hand.state()));
  auto t2 = component.start(TwoTargets::a(0));
  EXPECT_NE(t2->state(), t1->state());
}
