// How well the futures foresaw the sightings: ranks, and the coverage of calibrated, narrow and
// wide futures.
#include <gmock/gmock.h>

#include <kestrel/guidance/futures_calibration.hpp>
#include <kestrel/guidance/target_futures.hpp>
#include <random>

using namespace kestrel::guidance;

namespace {

// 200 paths from `at`, each flying a constant velocity drawn with `sigma` m/s per axis.
TargetFutures spread(const Eigen::Vector3d& at, double sigma, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, sigma);
  TargetFutures f;
  f.step_s = 0.1;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d v(n(rng), n(rng), n(rng));
    Eigen::Matrix3Xd path(3, 21);
    for (int k = 0; k <= 20; ++k) path.col(k) = at + v * (0.1 * k);
    f.paths.push_back(path);
  }
  return f;
}

// The share of 600 sightings, each 1 s after its futures (spread `drawn`) and truly spread `truth`,
// that fall within the futures' central half and central 90 %.
std::pair<double, double> coverage(double drawn, double truth) {
  std::mt19937_64 rng(4);
  std::normal_distribution<double> n(0.0, truth);
  FuturesCalibration calibration({1.0});
  for (int k = 0; k < 600; ++k) {
    const double t = 2.0 * k;  // far apart: each sighting has one drawing 1 s before it
    calibration.add(t, spread(Eigen::Vector3d(0.0, 0.0, 2.0), drawn, rng));
    calibration.observe(t + 1.0, Eigen::Vector3d(n(rng), n(rng), 2.0 + n(rng)));
  }
  const auto& tally = calibration.tallies().front();
  EXPECT_EQ(tally.sightings, 600u);
  return {tally.within_half / 600.0, tally.within_90 / 600.0};
}

}  // namespace

TEST(FuturesCalibration, RanksASightingAmongThePathsByItsDistanceFromTheirMean) {
  std::vector<Eigen::Vector3d> points;
  for (int i = -5; i <= 5; ++i) points.emplace_back(0.1 * i, 0.0, 0.0);
  points.emplace_back(0.0, 0.1, 0.0);
  points.emplace_back(0.0, 0.0, 0.1);
  EXPECT_EQ(FuturesCalibration::rank(points, Eigen::Vector3d::Zero()), 0.0);
  EXPECT_EQ(FuturesCalibration::rank(points, Eigen::Vector3d(5.0, 0.0, 0.0)), 1.0);
}

TEST(FuturesCalibration, CalibratedFuturesHoldHalfTheSightingsInTheirCentralHalf) {
  const auto [half, ninety] = coverage(1.0, 1.0);
  EXPECT_NEAR(half, 0.5, 0.06);
  EXPECT_NEAR(ninety, 0.9, 0.04);
}

TEST(FuturesCalibration, TooNarrowFuturesHoldTooFewAndTooWideTooMany) {
  EXPECT_LT(coverage(0.5, 1.0).second, 0.6);
  EXPECT_GT(coverage(2.0, 1.0).first, 0.85);
}

TEST(FuturesCalibration, ASightingWithNoDrawingTauBeforeItIsNotRanked) {
  std::mt19937_64 rng(1);
  FuturesCalibration calibration({0.5, 1.0});
  calibration.add(0.0, spread(Eigen::Vector3d::Zero(), 1.0, rng));
  calibration.observe(0.7, Eigen::Vector3d::Zero());  // neither 0.5 nor 1.0 s after it
  calibration.observe(0.5, Eigen::Vector3d::Zero());
  EXPECT_EQ(calibration.tallies()[0].sightings, 1u);
  EXPECT_EQ(calibration.tallies()[1].sightings, 0u);
  calibration.forget();
  calibration.observe(1.0, Eigen::Vector3d::Zero());
  EXPECT_EQ(calibration.tallies()[1].sightings, 0u);
  EXPECT_EQ(calibration.report()["0.5"]["sightings"], 1u);
}
