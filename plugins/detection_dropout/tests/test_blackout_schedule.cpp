// Blackouts of the detections, as detection_dropout schedules them.
#include <gmock/gmock.h>

#include "blackout_schedule.hpp"
#include "kestrel/error.hpp"

using namespace kestrel::scenario;

TEST(BlackoutSchedule, HidesNFramesEveryPeriodFromTheFirstBlackout) {
  BlackoutSchedule s(3, 1.0, 2.0);  // 3 frames at 1 s, 3 s, 5 s ...
  std::vector<int> hidden;
  for (int k = 0; k < 30 * 6; ++k)  // 30 FPS for 6 s
    if (s.hide(k / 30.0)) hidden.push_back(k);
  EXPECT_THAT(hidden, ::testing::ElementsAre(30, 31, 32, 90, 91, 92, 150, 151, 152));
}

TEST(BlackoutSchedule, CountsFramesNotTime) {
  // At 2 FPS a 3-frame blackout lasts 1.5 s; frames that never arrive do not count.
  BlackoutSchedule s(3, 0.0, 10.0);
  EXPECT_TRUE(s.hide(0.0));
  EXPECT_TRUE(s.hide(0.5));
  EXPECT_TRUE(s.hide(4.0));
  EXPECT_FALSE(s.hide(4.5));
  EXPECT_TRUE(s.hide(10.0));  // the next period
  EXPECT_FALSE(BlackoutSchedule(0, 0.0, 1.0).hide(0.0));
  EXPECT_THROW(BlackoutSchedule(1, 0.0, 0.0), kestrel::Error);
}
