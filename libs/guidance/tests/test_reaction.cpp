// The hypothesis that the target reacts to the hunter: its motion, the belief in it, and the
// capture chance it takes away.
#include <gmock/gmock.h>

#include <kestrel/guidance/capture_chance.hpp>
#include <kestrel/guidance/reaction.hpp>
#include <kestrel/guidance/target_futures.hpp>

using namespace kestrel;
using namespace kestrel::guidance;

namespace {

ReactionConfig reacting(double prior = 0.5) {
  ReactionConfig c;
  c.prior = prior;
  c.radius_m = 6.0;
  c.speed_m_s = 6.0;
  c.acceleration_m_s2 = 6.0;
  return c;
}

// n paths hovering at `at` for 3 s, on a 0.1 s grid.
TargetFutures hovering(const Eigen::Vector3d& at, std::size_t n = 8) {
  TargetFutures f;
  f.step_s = 0.1;
  for (std::size_t i = 0; i < n; ++i) f.paths.push_back(at.replicate(1, 31));
  return f;
}

}  // namespace

TEST(Reaction, ATargetFleesOnlyAHunterWithinTheRadiusAndNoHarderThanItsLimit) {
  const ReactionConfig c = reacting();
  const Eigen::Vector3d target(5.0, 0.0, 2.0), still = Eigen::Vector3d::Zero();
  EXPECT_TRUE(reaction_acceleration(c, target, still, {-2.0, 0.0, 2.0}).isZero());  // 7 m away
  const Eigen::Vector3d a = reaction_acceleration(c, target, still, {1.0, 0.0, 2.0});
  EXPECT_NEAR(a.norm(), 6.0, 1e-9);
  EXPECT_GT(a.x(), 5.99);  // straight away from the hunter
  // Already fleeing at its speed: no more to do.
  EXPECT_NEAR(reaction_acceleration(c, target, {6.0, 0.0, 0.0}, {1.0, 0.0, 2.0}).norm(), 0.0, 1e-9);
}

TEST(Reaction, TheBeliefFollowsWhatTheSightingsShow) {
  const Eigen::Vector3d hunter(0.0, 0.0, 2.0), p(4.0, 0.0, 2.0);
  ReactionBelief fleeing(reacting(0.2)), crossing(reacting(0.2)), hovering(reacting(0.2));
  for (int k = 0; k < 30; ++k) {                               // one second within the radius
    fleeing.observe(1.0 / 30.0, p, {6.0, 1.0, 0.0}, hunter);   // away from the hunter
    crossing.observe(1.0 / 30.0, p, {0.0, 6.0, 0.0}, hunter);  // across its line of sight
    hovering.observe(1.0 / 30.0, p, Eigen::Vector3d::Zero(), hunter);
  }
  EXPECT_GT(fleeing.probability(), 0.85);
  EXPECT_LT(crossing.probability(), 0.05);
  EXPECT_LT(hovering.probability(), 0.05);
  // Far from the hunter nothing is learnt; the evidence fades towards the prior.
  ReactionBelief far(reacting(0.2));
  far.observe(1.0, {40.0, 0.0, 2.0}, {5.0, 0.0, 0.0}, hunter);
  EXPECT_NEAR(far.probability(), 0.2, 1e-9);
  for (int k = 0; k < 100; ++k) fleeing.observe(1.0, {40.0, 0.0, 2.0}, Eigen::Vector3d::Zero(), hunter);
  EXPECT_NEAR(fleeing.probability(), 0.2, 1e-3);
  // No prior: no hypothesis at all.
  ReactionBelief none(reacting(0.0));
  none.observe(1.0, p, {6.0, 0.0, 0.0}, hunter);
  EXPECT_EQ(none.probability(), 0.0);
}

TEST(Reaction, ReactingPathsFleeTheHuntersPathAndOnlyWithinTheRadius) {
  const TargetFutures base = hovering({5.0, 0.0, 2.0});
  const ReactionConfig c = reacting();
  // A hunter that stays 10 m off leaves the paths where they were.
  const TargetFutures calm = reacting_futures(base, c, [](double) { return Eigen::Vector3d(-5.0, 0.0, 2.0); });
  ASSERT_EQ(calm.size(), 2u);  // every fourth path
  EXPECT_TRUE(calm.position(0, 3.0).isApprox(Eigen::Vector3d(5.0, 0.0, 2.0), 1e-9));
  // One that comes within 4 m drives them away, along +x, until they are out of its radius.
  const TargetFutures fled = reacting_futures(base, c, [](double) { return Eigen::Vector3d(1.0, 0.0, 2.0); });
  EXPECT_GT(fled.position(0, 1.0).x(), 5.5);
  EXPECT_NEAR(fled.position(0, 3.0).y(), 0.0, 1e-9);
  EXPECT_GE((fled.position(0, 3.0) - Eigen::Vector3d(1.0, 0.0, 2.0)).norm(), 6.0 - 0.1);
}

TEST(Reaction, AReactingTargetTakesAwayTheChanceOfANearLaunch) {
  // A level launcher at the origin facing +x; the net opens 2 m ahead and 1 m below after 0.4 s.
  const net::NetModel net{net::NetParams{{0.0, 1.0, 2.0}, 0.4, 0.6, 0.3}};
  const Launch launch{0.0, geometry::level_camera(Eigen::Vector3d(0.0, 0.0, 3.0), 0.0), Eigen::Vector3d::Zero()};
  const TargetFutures futures = hovering({2.0, 0.0, 2.0});
  ReactionConfig c = reacting();
  c.acceleration_m_s2 = 12.0;  // it darts sideways, off the net's line, before the net opens
  c.response_s = 0.1;
  const HunterPath here = [](double) { return Eigen::Vector3d(2.0, -3.0, 2.0); };
  EXPECT_DOUBLE_EQ(capture_chance(futures, net, launch, ReactingTarget{0.0, &c, here}).probability, 1.0);
  // Half sure it reacts: the reacting half is gone before the net opens.
  EXPECT_DOUBLE_EQ(capture_chance(futures, net, launch, ReactingTarget{0.5, &c, here}).probability, 0.5);
}
