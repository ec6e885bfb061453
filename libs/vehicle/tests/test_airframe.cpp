// Airframes by name, and the node parameters that change one: a field left at its default is the
// airframe's, a field set to anything else replaces it.
#include <gmock/gmock.h>

#include <cmath>
#include <kestrel/error.hpp>
#include <kestrel/vehicle/airframe.hpp>
#include <kestrel/vehicle/multirotor_config.hpp>

using namespace kestrel::vehicle;

TEST(Airframe, TheDefaultParametersAreTheFirefly) {
  const Multirotor m = MultirotorConfig{}.multirotor();
  const Multirotor firefly = Multirotor::firefly();
  EXPECT_EQ(m.rotors.size(), 6u);
  EXPECT_DOUBLE_EQ(m.mass_kg, firefly.mass_kg);
  EXPECT_TRUE(m.wrench_matrix().isApprox(firefly.wrench_matrix()));
}

TEST(Airframe, NamedByTheParameterWithEachFieldSetReplacingItsOwn) {
  MultirotorConfig c;
  c.airframe = "interceptor";
  const Multirotor plain = c.multirotor();
  EXPECT_EQ(plain.rotors.size(), 4u);
  EXPECT_DOUBLE_EQ(plain.mass_kg, 1.0);
  EXPECT_NEAR(plain.rotors[0].angle_rad, M_PI / 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(plain.rotors[0].arm_length_m, 0.12);

  c.mass_kg = 1.3;        // a heavier payload
  c.arm_length_m = 0.15;  // longer arms: the ring is rebuilt with the airframe's count and angle
  const Multirotor changed = c.multirotor();
  EXPECT_DOUBLE_EQ(changed.mass_kg, 1.3);
  EXPECT_EQ(changed.rotors.size(), 4u);
  EXPECT_NEAR(changed.rotors[0].angle_rad, M_PI / 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(changed.rotors[3].arm_length_m, 0.15);
  EXPECT_DOUBLE_EQ(changed.thrust_constant, plain.thrust_constant);
}

TEST(Airframe, InterceptorHasTheThrustToWeightOfItsClass) {
  const Airframe& a = airframe("interceptor");
  // 4 x 1.408e-6 x 2800^2 N = 44.2 N on 1 kg.
  EXPECT_NEAR(a.body.max_thrust_n(), 44.15, 0.01);
  EXPECT_GE(a.body.thrust_to_weight(), 4.0);
  EXPECT_GE(a.envelope.max_speed_m_s, 15.0);
}

TEST(Airframe, AnUnknownNameIsRefusedWithTheKnownOnes) {
  try {
    airframe("blimp");
    FAIL() << "no error";
  } catch (const kestrel::Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("firefly, interceptor"));
  }
}
