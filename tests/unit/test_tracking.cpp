// The constant-acceleration Kalman filter, the associators and track management, against
// hand-computed values, the continuous-time model and brute force.
#include <gmock/gmock.h>

#include <functional>
#include <random>

#include "associators.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/track_manager.hpp"

using namespace kestrel;
using namespace kestrel::tracking;

TEST(ConstantAcceleration, TransitionIsTheKinematicModel) {
  const auto F = transition(0.1);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(F(index(a, 0), index(a, 0)), 1.0);
    EXPECT_DOUBLE_EQ(F(index(a, 0), index(a, 1)), 0.1);
    EXPECT_DOUBLE_EQ(F(index(a, 0), index(a, 2)), 0.005);
    EXPECT_DOUBLE_EQ(F(index(a, 1), index(a, 2)), 0.1);
    EXPECT_DOUBLE_EQ(F(index(a, 2), index(a, 1)), 0.0);
  }
  EXPECT_EQ((F.array() != 0).count(), 18);  // 9 ones + 3 x (dt, dt^2/2, dt): axes do not mix
}

TEST(ConstantAcceleration, ProcessNoiseIsTheDiscreteWhiteNoiseJerkModel) {
  // Q = integral over [0, dt] of F(s) G q G^T F(s)^T ds, with G = (0, 0, 1) per axis: integrate
  // numerically and compare with the closed form.
  const double dt = 0.2, q = 3.0;
  Covariance integral = Covariance::Zero();
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    const double s = (i + 0.5) * dt / steps;
    const Covariance F = transition(s);
    Eigen::Matrix<double, 9, 3> G = Eigen::Matrix<double, 9, 3>::Zero();
    for (int a = 0; a < 3; ++a) G(index(a, 2), a) = 1.0;
    integral += F * G * (q * Eigen::Matrix3d::Identity()) * G.transpose() * F.transpose() * (dt / steps);
  }
  const Covariance Q = process_noise(dt, q);
  EXPECT_LT((Q - integral).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_DOUBLE_EQ(Q(index(0, 0), index(0, 0)), q * std::pow(dt, 5) / 20);
  EXPECT_DOUBLE_EQ(Q(index(1, 1), index(1, 2)), q * dt * dt / 2);
  EXPECT_DOUBLE_EQ(Q(index(2, 2), index(2, 2)), q * dt);
  EXPECT_DOUBLE_EQ(Q(index(0, 0), index(1, 0)), 0.0);
}

TEST(ConstantAcceleration, InitialCovarianceIsThePapers) {
  const auto P = initial_covariance(2.0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(P(index(a, 0), index(a, 0)), 2.0 * 1.0);
    EXPECT_DOUBLE_EQ(P(index(a, 1), index(a, 1)), 2.0 * 900.0);
    EXPECT_DOUBLE_EQ(P(index(a, 2), index(a, 2)), 2.0 * 30.25);
  }
}

TEST(ConstantAcceleration, PredictAndUpdateMatchHandComputedValues) {
  auto kf = ConstantAccelerationKalman::start({1, 2, 3}, 1.0);
  kf.predict(0.1, 0.0);
  // Position variance after predict: 1 + dt^2 900 + (dt^2/2)^2 30.25.
  const double pp = 1.0 + 0.01 * 900.0 + 0.005 * 0.005 * 30.25;
  EXPECT_NEAR(kf.P(0, 0), pp, 1e-12);
  EXPECT_NEAR(kf.P(index(0, 0), index(0, 1)), 0.1 * 900.0 + 0.005 * 0.1 * 30.25, 1e-12);  // cov(x, v)
  EXPECT_TRUE(kf.position().isApprox(Eigen::Vector3d(1, 2, 3)));
  // Update x with z = 1.5, r = 1: gain on position pp / (pp + 1); on velocity cov(x,v) / (pp + 1).
  const double pxv = kf.P(index(0, 0), index(0, 1));
  kf.update({1.5, 2, 3}, 1.0);
  EXPECT_NEAR(kf.x(index(0, 0)), 1.0 + pp / (pp + 1.0) * 0.5, 1e-12);
  EXPECT_NEAR(kf.x(index(0, 1)), pxv / (pp + 1.0) * 0.5, 1e-12);
  EXPECT_NEAR(kf.P(0, 0), pp - pp * pp / (pp + 1.0), 1e-9);
  EXPECT_NEAR(kf.x(index(1, 0)), 2.0, 1e-12);  // other axes untouched
}

TEST(ConstantAcceleration, TracksAConstantAcceleration) {
  auto kf = ConstantAccelerationKalman::start({0, 0, 5}, 1.0);
  const double dt = 1.0 / 30;
  for (int k = 1; k <= 300; ++k) {
    kf.predict(dt, 0.01);
    const double t = k * dt;
    kf.update({0.5 * 0.8 * t * t, 2.0 * t, 5.0}, 0.01);
  }
  EXPECT_NEAR(kf.x(index(0, 2)), 0.8, 0.02);
  EXPECT_NEAR(kf.x(index(1, 1)), 2.0, 0.02);
}

namespace {

std::vector<PredictedMeasurement> at(const std::vector<Eigen::Vector3d>& positions) {
  std::vector<PredictedMeasurement> out;
  for (const auto& p : positions) out.push_back({p, Eigen::Matrix3d::Identity()});
  return out;
}

// Best number of pairs within the gate, then least total distance, by enumeration.
std::pair<int, double> brute_force(const Eigen::MatrixXd& cost) {
  std::pair<int, double> best{0, 0.0};
  std::vector<char> used(static_cast<std::size_t>(cost.cols()), 0);
  std::function<void(int, int, double)> visit = [&](int r, int n, double total) {
    if (r == cost.rows()) {
      if (n > best.first || (n == best.first && total < best.second - 1e-12)) best = {n, total};
      return;
    }
    visit(r + 1, n, total);
    for (int c = 0; c < cost.cols(); ++c)
      if (!used[static_cast<std::size_t>(c)] && std::isfinite(cost(r, c))) {
        used[static_cast<std::size_t>(c)] = 1;
        visit(r + 1, n + 1, total + cost(r, c));
        used[static_cast<std::size_t>(c)] = 0;
      }
  };
  visit(0, 0, 0.0);
  return best;
}

}  // namespace

TEST(Associators, HungarianMatchesBruteForceOnRandomScenes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  std::uniform_int_distribution<int> count(0, 6);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Eigen::Vector3d> tracks(static_cast<std::size_t>(count(rng))),
        detections(static_cast<std::size_t>(count(rng)));
    for (auto& t : tracks) t = {coord(rng), coord(rng), 5.0};
    for (auto& d : detections) d = {coord(rng), coord(rng), 5.0};
    for (const Metric metric : {Metric::euclidean, Metric::mahalanobis}) {
      const HungarianAssociator hungarian(metric, 1.0);
      const auto a = hungarian.associate(at(tracks), detections);
      const auto expected = brute_force(distance_matrix(at(tracks), detections, metric, 1.0));
      EXPECT_EQ(a.pairs, expected.first);
      EXPECT_NEAR(a.total_cost, expected.second, 1e-9);
      for (std::size_t t = 0; t < tracks.size(); ++t) {
        if (a.row_to_col[t] < 0) continue;
        EXPECT_LE((tracks[t] - detections[static_cast<std::size_t>(a.row_to_col[t])]).norm(), 1.0);
      }
    }
  }
}

TEST(Associators, RectangularInfeasibleAndGreedyCases) {
  const HungarianAssociator hungarian(Metric::euclidean, 1.0);
  const GreedyAssociator greedy(Metric::euclidean, 1.0);
  // More detections than tracks; one detection beyond every gate.
  auto a = hungarian.associate(at({{0, 0, 5}}), {{3, 0, 5}, {0.2, 0, 5}, {0.5, 0, 5}});
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1));
  // Nothing within the gate: infeasible, nothing assigned.
  a = hungarian.associate(at({{0, 0, 5}, {1, 1, 5}}), {{5, 5, 5}});
  EXPECT_EQ(a.pairs, 0);
  EXPECT_TRUE(hungarian.associate({}, {{0, 0, 0}}).row_to_col.empty());
  // Greedy takes the closest pair first and loses the second match the optimum keeps.
  const auto tracks = at({{0, 0, 5}, {0.9, 0, 5}});
  const std::vector<Eigen::Vector3d> detections = {{0.5, 0, 5}, {-0.6, 0, 5}};
  EXPECT_EQ(hungarian.associate(tracks, detections).pairs, 2);
  const auto g = greedy.associate(tracks, detections);
  EXPECT_EQ(g.pairs, 2);  // greedy: (t1, d0) at 0.4, then (t0, d1) at 0.6
  EXPECT_THAT(g.row_to_col, ::testing::ElementsAre(1, 0));
  const auto tight = GreedyAssociator(Metric::euclidean, 0.55).associate(tracks, detections);
  EXPECT_EQ(tight.pairs, 1);
  EXPECT_EQ(HungarianAssociator(Metric::euclidean, 0.55).associate(tracks, detections).pairs, 1);
}

TEST(Associators, MahalanobisUsesTheInnovationCovariance) {
  PredictedMeasurement wide{{0, 0, 5}, Eigen::Vector3d(4.0, 0.01, 0.01).asDiagonal()};
  // 1.5 m along x is 0.75 sigma for a track uncertain in x; 0.5 m along y is 5 sigma.
  const auto cost = distance_matrix({wide}, {{1.5, 0, 5}, {0, 0.5, 5}}, Metric::mahalanobis, 3.0);
  EXPECT_NEAR(cost(0, 0), 0.75, 1e-12);
  EXPECT_FALSE(std::isfinite(cost(0, 1)));
}

namespace {

class FixedFilter final : public TrackFilter {  // the last detection is the estimate
 public:
  explicit FixedFilter(const Eigen::Vector3d& z) : p_(z) {}
  void predict(double) override {}
  void update(const Eigen::Vector3d& z) override { p_ = z; }
  PredictedMeasurement predicted_measurement() const override { return {p_, Eigen::Matrix3d::Identity()}; }
  Eigen::VectorXd state() const override { return p_; }
  Eigen::MatrixXd covariance() const override { return Eigen::Matrix3d::Identity(); }

 private:
  Eigen::Vector3d p_;
};

TrackManager manager(int max_misses, Selection selection = Selection::longest_living) {
  return TrackManager(
      std::make_shared<HungarianAssociator>(Metric::euclidean, 1.0),
      [](const Eigen::Vector3d& z) { return std::make_unique<FixedFilter>(z); },
      TrackManagerOptions{max_misses, selection});
}

Time frame(int k) { return from_seconds(k / 30.0); }

}  // namespace

TEST(TrackManager, BirthDeathAndTheLongestLivingTarget) {
  auto m = manager(2);
  auto out = m.step(frame(0), {{0, 0, 5}});
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].id, 1u);
  EXPECT_EQ(*out.selected_id, 1u);
  // A detection 3 m away is beyond epsilon_max: a second track is born.
  out = m.step(frame(1), {{0.1, 0, 5}, {3, 0, 5}});
  ASSERT_EQ(out.items.size(), 2u);
  EXPECT_EQ(out.items[0].hits, 2);
  EXPECT_EQ(out.items[1].id, 2u);
  EXPECT_EQ(*out.selected_id, 1u);  // the older one
  // Track 2 is missed three times in a row: deleted after max_misses = 2.
  for (int k = 2; k <= 4; ++k) out = m.step(frame(k), {{0.1, 0, 5}});
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].id, 1u);
  EXPECT_EQ(out.items[0].age, 5);
  // Track 1 missed for two frames survives (misses 2), the third kills it.
  out = m.step(frame(5), {});
  out = m.step(frame(6), {});
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].misses, 2);
  out = m.step(frame(7), {});
  EXPECT_TRUE(out.items.empty());
  EXPECT_FALSE(out.selected_id);
}

TEST(TrackManager, TentativeTracksAreNotPublishedUntilConfirmed) {
  TrackManager m(
      std::make_shared<HungarianAssociator>(Metric::euclidean, 1.0),
      [](const Eigen::Vector3d& z) { return std::make_unique<FixedFilter>(z); },
      TrackManagerOptions{2, Selection::longest_living, 3});
  // A one-frame false alarm at (3, 0, 5) never shows; the real target appears at its third hit.
  EXPECT_TRUE(m.step(frame(0), {{0, 0, 5}, {3, 0, 5}}).items.empty());
  EXPECT_TRUE(m.step(frame(1), {{0, 0, 5}}).items.empty());
  EXPECT_EQ(m.size(), 1u);  // the false alarm, tentative, was deleted at its first miss
  auto out = m.step(frame(2), {{0, 0, 5}});
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].id, 1u);
  EXPECT_EQ(*out.selected_id, 1u);
  // Intermittent noise at one place never adds up to a confirmed track: each blip is new.
  for (int k = 3; k < 9; ++k)
    out = m.step(frame(k),
                 k % 2 ? std::vector<Eigen::Vector3d>{{0, 0, 5}, {3, 0, 5}} : std::vector<Eigen::Vector3d>{{0, 0, 5}});
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].id, 1u);
  // A confirmed track keeps its max_misses allowance.
  out = m.step(frame(9), {});
  out = m.step(frame(10), {});
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].misses, 2);
}

TEST(TrackManager, SelectionRules) {
  auto nearest = manager(5, Selection::nearest);
  nearest.step(frame(0), {{0, 0, 8}});
  const auto out = nearest.step(frame(1), {{0, 0, 8}, {0, 0, 3}});
  EXPECT_EQ(*out.selected_id, 2u);
  EXPECT_EQ(parse_selection("most_hits"), Selection::most_hits);
  EXPECT_THROW(parse_selection("loudest"), Error);
}
