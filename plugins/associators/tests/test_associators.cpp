// The associators against brute force, and the tracking loop (kestrel::tracking::TrackManager)
// composed with them, on scenes whose answer is known.
#include <gmock/gmock.h>

#include <functional>
#include <random>

#include "associators.hpp"
#include "kestrel/error.hpp"
#include "kestrel/testing/fixed_filter.hpp"
#include "kestrel/tracking/constant_acceleration.hpp"
#include "kestrel/tracking/deleter.hpp"
#include "kestrel/tracking/imm_filter.hpp"
#include "kestrel/tracking/initiator.hpp"
#include "kestrel/tracking/kalman_filter.hpp"
#include "kestrel/tracking/selector.hpp"
#include "kestrel/tracking/track_manager.hpp"

using namespace kestrel;
using namespace kestrel::tracking;
using kestrel::testing::FixedFilter;

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

TEST(Associators, RectangularAndInfeasibleCases) {
  const HungarianAssociator hungarian(Metric::euclidean, 1.0);
  // More detections than tracks; one detection beyond every gate.
  auto a = hungarian.associate(at({{0, 0, 5}}), {{3, 0, 5}, {0.2, 0, 5}, {0.5, 0, 5}});
  EXPECT_THAT(a.row_to_col, ::testing::ElementsAre(1));
  // Nothing within the gate: infeasible, nothing assigned.
  a = hungarian.associate(at({{0, 0, 5}, {1, 1, 5}}), {{5, 5, 5}});
  EXPECT_EQ(a.pairs, 0);
  EXPECT_TRUE(hungarian.associate({}, {{0, 0, 0}}).row_to_col.empty());
  EXPECT_TRUE(GreedyAssociator(Metric::euclidean, 1.0).associate(at({{0, 0, 5}}), {}).row_to_col[0] < 0);
}

// Track 1 is 0.4 m from detection 0 and 0.9 m from detection 1; track 0 has detection 0 alone
// within its gate (0.5 m; detection 1 is 1.8 m away). Greedy takes the closest pair first,
// (track 1, detection 0), and leaves track 0 with nothing; the optimum pairs both tracks.
TEST(Associators, GreedyLosesAMatchThatHungarianMakes) {
  const auto tracks = at({{0, 0, 5}, {0.9, 0, 5}});
  const std::vector<Eigen::Vector3d> detections = {{0.5, 0, 5}, {1.8, 0, 5}};
  const auto optimal = HungarianAssociator(Metric::euclidean, 1.0).associate(tracks, detections);
  EXPECT_EQ(optimal.pairs, 2);
  EXPECT_THAT(optimal.row_to_col, ::testing::ElementsAre(0, 1));
  EXPECT_NEAR(optimal.total_cost, 0.5 + 0.9, 1e-12);
  const auto greedy = GreedyAssociator(Metric::euclidean, 1.0).associate(tracks, detections);
  EXPECT_EQ(greedy.pairs, 1);
  EXPECT_THAT(greedy.row_to_col, ::testing::ElementsAre(-1, 0));
  EXPECT_THAT(greedy.col_to_row, ::testing::ElementsAre(1, -1));
  EXPECT_NEAR(greedy.total_cost, 0.4, 1e-12);
}

// Both pair every track, but greedy's first, closest pair (track 0, detection 0: 1.0 m) forces
// the expensive (track 1, detection 1: 4.1 m); the optimum crosses them for 2.0 + 1.1 m.
TEST(Associators, GreedyPaysMoreThanHungarianForTheSamePairs) {
  const auto tracks = at({{0, 0, 5}, {2.1, 0, 5}});
  const std::vector<Eigen::Vector3d> detections = {{1.0, 0, 5}, {-2.0, 0, 5}};
  const auto optimal = HungarianAssociator(Metric::euclidean, 5.0).associate(tracks, detections);
  EXPECT_THAT(optimal.row_to_col, ::testing::ElementsAre(1, 0));
  EXPECT_NEAR(optimal.total_cost, 3.1, 1e-12);
  const auto greedy = GreedyAssociator(Metric::euclidean, 5.0).associate(tracks, detections);
  EXPECT_THAT(greedy.row_to_col, ::testing::ElementsAre(0, 1));
  EXPECT_NEAR(greedy.total_cost, 5.1, 1e-12);
}

TEST(Associators, MahalanobisUsesTheInnovationCovariance) {
  PredictedMeasurement wide{{0, 0, 5}, Eigen::Vector3d(4.0, 0.01, 0.01).asDiagonal()};
  // 1.5 m along x is 0.75 sigma for a track uncertain in x; 0.5 m along y is 5 sigma.
  const auto cost = distance_matrix({wide}, {{1.5, 0, 5}, {0, 0.5, 5}}, Metric::mahalanobis, 3.0);
  EXPECT_NEAR(cost(0, 0), 0.75, 1e-12);
  EXPECT_FALSE(std::isfinite(cost(0, 1)));
}

namespace {

class FixedFilters final : public Filter {
 public:
  std::unique_ptr<TrackFilter> start(const Eigen::Vector3d& z) override { return std::make_unique<FixedFilter>(z); }
};

TrackManager manager(int max_misses,
                     std::shared_ptr<const Selector> selector = std::make_shared<LongestLivingSelector>(),
                     int confirm_hits = 1) {
  return TrackManager(TrackerParts{
      std::make_shared<FixedFilters>(), std::make_shared<HungarianAssociator>(Metric::euclidean, 1.0),
      std::make_shared<ConsecutiveHitsInitiator>(ConsecutiveHitsConfig{confirm_hits}),
      std::make_shared<ConsecutiveMissesDeleter>(ConsecutiveMissesConfig{max_misses}), std::move(selector)});
}

Time frame(int k) { return from_seconds(k / 30.0); }

std::vector<std::uint64_t> ids(const msg::Tracks& tracks) {
  std::vector<std::uint64_t> out;
  for (const auto& t : tracks.items) out.push_back(t.id);
  return out;
}

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
  EXPECT_EQ(m.counts().frames, 8u);
  EXPECT_EQ(m.counts().empty_frames, 3u);
  EXPECT_EQ(m.counts().tracks_started, 2u);
  EXPECT_EQ(m.counts().target_coasted_frames, 2u);  // frames 5 and 6: the target had no detection
}

TEST(TrackManager, TentativeTracksAreNotPublishedUntilConfirmed) {
  auto m = manager(2, std::make_shared<LongestLivingSelector>(), 3);
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
  EXPECT_EQ(m.counts().tracks_confirmed, 1u);
}

// Track 1 is born first but coasts three frames; track 2, born a frame later, is hit every frame.
// The oldest is 1, the most hit is 2.
TEST(TrackManager, MostHitsSelectsTheTrackWithMostDetectionsNotTheOldest) {
  auto longest = manager(5);
  auto most_hits = manager(5, std::make_shared<MostHitsSelector>());
  const Eigen::Vector3d a(0, 0, 5), b(2, 0, 5);
  const std::vector<std::vector<Eigen::Vector3d>> frames = {{a}, {b}, {b}, {b}, {a, b}, {a, b}};
  msg::Tracks by_age, by_hits;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    by_age = longest.step(frame(static_cast<int>(k)), frames[k]);
    by_hits = most_hits.step(frame(static_cast<int>(k)), frames[k]);
  }
  ASSERT_THAT(ids(by_hits), ::testing::ElementsAre(1u, 2u));
  EXPECT_EQ(by_hits.items[0].age, 6);
  EXPECT_EQ(by_hits.items[0].hits, 3);
  EXPECT_EQ(by_hits.items[1].age, 5);
  EXPECT_EQ(by_hits.items[1].hits, 5);
  EXPECT_EQ(*by_age.selected_id, 1u);
  EXPECT_EQ(*by_hits.selected_id, 2u);
}

TEST(TrackManager, DetectionsGoingBackInTimeAreRefusedAndChangeNothing) {
  auto m = manager(2);
  m.step(frame(3), {{0, 0, 5}});
  try {
    m.step(frame(2), {{0, 0, 5}});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("detections went back in time"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("0.066667 s came after one at 0.100000 s"));
  }
  EXPECT_EQ(m.counts().frames, 1u);
  const auto out = m.step(frame(4), {{0, 0, 5}});  // the next frame in order is tracked as usual
  ASSERT_EQ(out.items.size(), 1u);
  EXPECT_EQ(out.items[0].hits, 2);
  // The same stamp twice is not going back: no prediction, one more update.
  EXPECT_EQ(m.step(frame(4), {{0, 0, 5}}).items[0].hits, 3);
}

TEST(TrackManager, EveryPartIsRequired) {
  TrackerParts parts{std::make_shared<FixedFilters>(), std::make_shared<HungarianAssociator>(Metric::euclidean, 1.0),
                     std::make_shared<ConsecutiveHitsInitiator>(ConsecutiveHitsConfig{}),
                     std::make_shared<ConsecutiveMissesDeleter>(ConsecutiveMissesConfig{}),
                     std::make_shared<LongestLivingSelector>()};
  EXPECT_NO_THROW(TrackManager{parts});
  auto without = parts;
  without.selector = nullptr;
  EXPECT_THROW(TrackManager{without}, Error);
  without = parts;
  without.filter = nullptr;
  EXPECT_THROW(TrackManager{without}, Error);
}

// The tracker with the Kalman filter component on a target whose path is known: a straight line
// at constant velocity, detected exactly at 30 Hz. The loop must give exactly the filter a hand
// run of the constant-acceleration Kalman filter gives, and the estimate must reach the truth.
TEST(TrackManager, KalmanTrackerFollowsAConstantVelocityTargetExactly) {
  const KalmanConfig config{1.0, 0.5, 1.0};
  TrackManager m(TrackerParts{std::make_shared<KalmanFilter>(config),
                              std::make_shared<HungarianAssociator>(Metric::euclidean, 1.0),
                              std::make_shared<ConsecutiveHitsInitiator>(ConsecutiveHitsConfig{}),
                              std::make_shared<ConsecutiveMissesDeleter>(ConsecutiveMissesConfig{}),
                              std::make_shared<LongestLivingSelector>()});
  auto truth = [](int k) { return Eigen::Vector3d(-1.0 + 0.8 * k / 30.0, 0.5 - 0.3 * k / 30.0, 5.0); };
  auto by_hand = ConstantAccelerationKalman::start(truth(0), config.p);
  msg::Tracks out = m.step(frame(0), {truth(0)});
  for (int k = 1; k <= 150; ++k) {
    out = m.step(frame(k), {truth(k)});
    by_hand.predict(to_seconds(frame(k) - frame(k - 1)), config.q);
    by_hand.update(truth(k), config.r);
  }
  ASSERT_THAT(ids(out), ::testing::ElementsAre(1u));
  EXPECT_EQ(*out.selected_id, 1u);
  EXPECT_EQ(out.items[0].hits, 151);
  EXPECT_EQ(Eigen::VectorXd(out.items[0].state), Eigen::VectorXd(by_hand.x));
  EXPECT_EQ(Eigen::MatrixXd(out.items[0].covariance), Eigen::MatrixXd(by_hand.P));
  const auto& x = out.items[0].state;
  EXPECT_LT((x.head<3>() - truth(150)).norm(), 1e-3);
  EXPECT_LT((x.segment<3>(3) - Eigen::Vector3d(0.8, -0.3, 0.0)).norm(), 1e-2);
  EXPECT_LT(x.tail<3>().norm(), 1e-2);
}

// The documented tie rule: equal scores go to the track that comes first, the oldest.
TEST(Selector, TiesGoToTheOldestTrack) {
  FixedFilter a({0, 0, 5}, 1.0), b({0, 5, 0}, 1.0), c({3, 0, 4}, 1.0);  // all 5 m away, same covariance
  const std::vector<TrackStatus> tied{{4, 7, 7, 0, true, &a}, {6, 7, 7, 0, true, &b}, {9, 7, 7, 0, true, &c}};
  for (const auto& selector : std::vector<std::shared_ptr<const Selector>>{
           std::make_shared<LongestLivingSelector>(), std::make_shared<MostHitsSelector>(),
           std::make_shared<NearestSelector>(), std::make_shared<MostConfidentSelector>()})
    EXPECT_EQ(*selector->select(tied), 4u);
  // In the loop: two tracks born in one frame and hit in every frame tie on every rule.
  auto m = manager(5, std::make_shared<MostHitsSelector>());
  msg::Tracks out;
  for (int k = 0; k < 4; ++k) out = m.step(frame(k), {{0, 0, 5}, {3, 0, 4}});
  ASSERT_THAT(ids(out), ::testing::ElementsAre(1u, 2u));
  EXPECT_EQ(*out.selected_id, 1u);
}
