// Telling an evader from a target on its own path: it flees the hunter that closes on it.
#include <gtest/gtest.h>

#include <cmath>

#include "flee_watch.hpp"

using namespace kestrel::aim;

namespace {

constexpr double kFrameDt = 1.0 / 30.0;

struct Flight {
  Eigen::Vector3d hunter{0.0, 0.0, 2.0}, hunter_velocity{4.0, 0.0, 0.0};
  Eigen::Vector3d target{5.0, 0.0, 2.0}, target_velocity{5.0, 0.0, 0.0};
};

// Flies both at constant velocity for `seconds`, a frame at a time, into the watch.
void fly(FleeWatch& watch, Flight& f, double seconds) {
  for (double t = 0.0; t < seconds - 1e-9; t += kFrameDt) {
    f.hunter += f.hunter_velocity * kFrameDt;
    f.target += f.target_velocity * kFrameDt;
    watch.update(kFrameDt, f.target, f.target_velocity, f.hunter, f.hunter_velocity);
  }
}

}  // namespace

TEST(FleeWatch, ATargetRunningFromTheClosingHunterIsAnEvaderAfterTheSetTime) {
  FleeWatch watch(FleeWatchConfig{});
  Flight f;  // the hunter closes at 4 m/s, the target runs straight away at 5 m/s
  fly(watch, f, 0.2);
  EXPECT_FALSE(watch.fleeing());
  EXPECT_NEAR(watch.fleeing_for_s(), 0.2, 1e-9);
  fly(watch, f, 0.1);
  EXPECT_TRUE(watch.fleeing());
  // It stays one when it stops, and until reset.
  f.target_velocity.setZero();
  fly(watch, f, 2.0);
  EXPECT_TRUE(watch.fleeing());
  watch.reset();
  EXPECT_FALSE(watch.fleeing());
  EXPECT_EQ(watch.fleeing_for_s(), 0.0);
}

TEST(FleeWatch, AWeavingEvaderFleesAsLongAsMostOfItsSpeedIsAway) {
  FleeWatch watch(FleeWatchConfig{});
  Flight f;
  f.target_velocity = 6.0 * Eigen::Vector3d(1.0, 0.6, 0.0).normalized();  // 0.86 of it away
  fly(watch, f, 0.3);
  EXPECT_TRUE(watch.fleeing());
}

TEST(FleeWatch, ATargetOnItsOwnPathIsNoEvader) {
  const FleeWatchConfig config;
  {  // crossing the line of sight
    FleeWatch watch(config);
    Flight f;
    f.target_velocity = {0.0, 8.0, 0.0};
    fly(watch, f, 0.3);
    EXPECT_FALSE(watch.fleeing());
  }
  {  // moving away at an angle: 3 of its 5 m/s away, a share of 0.6
    FleeWatch watch(config);
    Flight f;
    f.target_velocity = {3.0, 4.0, 0.0};
    fly(watch, f, 0.3);
    EXPECT_FALSE(watch.fleeing());
  }
  {  // moving away slowly: 1 m/s, under min_speed_m_s
    FleeWatch watch(config);
    Flight f;
    f.target_velocity = {1.0, 0.0, 0.0};
    f.hunter_velocity = {0.5, 0.0, 0.0};
    fly(watch, f, 1.0);
    EXPECT_FALSE(watch.fleeing());
  }
  {  // moving away from a hunter that waits: it flies its own way, not from the hunter
    FleeWatch watch(config);
    Flight f;
    f.hunter_velocity.setZero();
    fly(watch, f, 1.0);
    EXPECT_FALSE(watch.fleeing());
  }
  {  // moving away beyond max_range_m
    FleeWatch watch(config);
    Flight f;
    f.target = {9.0, 0.0, 2.0};
    fly(watch, f, 1.0);
    EXPECT_FALSE(watch.fleeing());
  }
}

TEST(FleeWatch, BriefBurstsAwayDoNotAddUp) {
  // A figure-8 seen from its side moves away from the hunter for a moment each turn.
  FleeWatch watch(FleeWatchConfig{});
  Flight f;
  for (int turn = 0; turn < 6; ++turn) {
    f.target_velocity = {5.0, 0.0, 0.0};
    fly(watch, f, 0.2);
    f.target_velocity = {0.0, turn % 2 == 0 ? 5.0 : -5.0, 0.0};  // across, left then right
    fly(watch, f, 0.2);
  }
  EXPECT_FALSE(watch.fleeing());
  EXPECT_EQ(watch.fleeing_for_s(), 0.0);
}

TEST(FleeWatch, TheTimeAndTheThresholdsAreParameters) {
  FleeWatchConfig config;
  config.time_s = 1.0;
  config.min_share = 0.5;
  FleeWatch watch(config);
  Flight f;
  f.target_velocity = {3.0, 4.0, 0.0};  // a share of 0.6: fleeing, with min_share 0.5
  fly(watch, f, 0.9);
  EXPECT_FALSE(watch.fleeing());
  fly(watch, f, 0.2);
  EXPECT_TRUE(watch.fleeing());
}

// An evader calms once the hunter is far; a figure-8 swinging away along the line of sight passed
// for one, but keeps its speed with the hunter far: it flies its own path, and is no evader again.
TEST(FleeWatch, ATargetThatKeepsItsSpeedWithTheHunterFarIsNoEvader) {
  FleeWatchConfig config;
  config.calm_speed_m_s = 3.0;
  config.calm_time_s = 1.5;
  // Seen fleeing, then the hunter stops beyond max_range_m and the target flies at `velocity`.
  const auto fled_then_far = [&](FleeWatch& watch, const Eigen::Vector3d& velocity) {
    Flight f;
    fly(watch, f, 0.3);
    EXPECT_TRUE(watch.fleeing());
    f.hunter = f.target - Eigen::Vector3d(config.max_range_m + 4.0, 0.0, 0.0);
    f.hunter_velocity.setZero();
    f.target_velocity = velocity;
    return f;
  };
  {  // cruising at 2 m/s: an evader still
    FleeWatch watch(config);
    Flight f = fled_then_far(watch, {0.0, 2.0, 0.0});
    fly(watch, f, 5.0);
    EXPECT_TRUE(watch.fleeing());
    EXPECT_FALSE(watch.own_path());
  }
  {  // at 6 m/s, across: no evader after calm_time_s, and not again when it flees
    FleeWatch watch(config);
    Flight f = fled_then_far(watch, {0.0, 6.0, 0.0});
    fly(watch, f, 1.4);
    EXPECT_TRUE(watch.fleeing());
    fly(watch, f, 0.2);
    EXPECT_FALSE(watch.fleeing());
    EXPECT_TRUE(watch.own_path());
    Flight again;
    fly(watch, again, 1.0);
    EXPECT_FALSE(watch.fleeing());
    watch.reset();
    EXPECT_FALSE(watch.own_path());
  }
  {  // fast while the hunter is near: not judged (it flees), whatever its speed
    FleeWatch watch(config);
    Flight f = fled_then_far(watch, {0.0, 6.0, 0.0});
    f.hunter = f.target - Eigen::Vector3d(config.max_range_m - 2.0, 0.0, 0.0);
    fly(watch, f, 0.5);  // crossing, it stays within max_range_m for these 0.5 s
    EXPECT_TRUE(watch.fleeing());
  }
}
