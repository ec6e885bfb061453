// The fire policies: the aim's own thresholds, and a capture now against the value of keeping the net.
#include <gmock/gmock.h>

#include "fire_policy.hpp"

using namespace kestrel::aim;

TEST(FirePolicy, ThresholdFiresOnTheAimsOwnVerdictOnly) {
  const ThresholdFire policy;
  EXPECT_TRUE(policy.worth_a_net({true, 0.0, 1.0, 2}));
  EXPECT_FALSE(policy.worth_a_net({false, 1.0, 0.0, 2}));
  EXPECT_FALSE(policy.needs_futures());  // the aim draws no futures for it
  EXPECT_TRUE(CaptureValue(CaptureValueConfig{}).needs_futures());
}

TEST(FirePolicy, CaptureValueFiresWhenNowIsWorthAtLeastWaiting) {
  const CaptureValue policy{CaptureValueConfig{0.3, 0.5}};
  EXPECT_TRUE(policy.worth_a_net({false, 0.6, 0.5, 2}));
  EXPECT_TRUE(policy.worth_a_net({false, 0.6, 0.6, 2}));
  EXPECT_FALSE(policy.worth_a_net({false, 0.6, 0.7, 2}));  // a better shot is coming
  EXPECT_TRUE(policy.worth_a_net({false, 0.4, std::nullopt, 2}));
}

TEST(FirePolicy, CaptureValueNeverFiresBelowItsFloorAndTheLastNetWaitsForMore) {
  const CaptureValue policy{CaptureValueConfig{0.3, 0.5}};
  EXPECT_FALSE(policy.worth_a_net({true, 0.25, 0.0, 2}));
  EXPECT_TRUE(policy.worth_a_net({false, 0.4, 0.1, 2}));
  EXPECT_FALSE(policy.worth_a_net({false, 0.4, 0.1, 1}));  // the last net
  EXPECT_TRUE(policy.worth_a_net({false, 0.55, 0.1, 1}));
  EXPECT_TRUE(policy.worth_a_net({false, 0.4, 0.1, -1}));  // no launcher: unlimited nets
}
