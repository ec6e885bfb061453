// The oCamS IMU's lines, on lines whose values are known: the camera's BNO055 integers scaled
// to SI units, myAHRS+ lines with their XOR checksums, replies, and corrupt lines refused with
// what is wrong.
#include <gmock/gmock.h>

#include "imu_protocol.hpp"

using namespace kestrel::ocams;

TEST(OcamsImuLine, AnAmgquaLineIsScaledToSiUnits) {
  // At rest, level: 1 g up, no rotation, the earth's field; quaternion x, y, z, w on the wire.
  const ImuLine l = parse_imu_line("$AMGQUA,66449,-3,2,981,628,8,-400,9,-18,0,0,0,8192,14189\r\n");
  ASSERT_EQ(l.kind, ImuLine::Kind::sample);
  const ImuSample& s = l.sample;
  EXPECT_EQ(s.format, "AMGQUA");
  EXPECT_EQ(s.device_ms, 66449u);
  EXPECT_FALSE(s.gravity_removed);
  EXPECT_NEAR(s.acceleration_m_s2.z(), 9.81, 1e-12);
  EXPECT_NEAR(s.acceleration_m_s2.x(), -0.03, 1e-12);
  EXPECT_NEAR(s.angular_rate_radps.x(), 0.01, 1e-12);
  EXPECT_NEAR(s.angular_rate_radps.y(), -0.02, 1e-12);
  EXPECT_NEAR(s.magnetic_field_t.x(), 39.25e-6, 1e-15);
  ASSERT_TRUE(s.orientation);
  // z = 0.5, w = 0.866: 60 degrees about z
  EXPECT_NEAR(Eigen::AngleAxisd(*s.orientation).angle(), M_PI / 3, 1e-3);
  EXPECT_NEAR(s.orientation->z(), 0.5, 1e-3);
}

TEST(OcamsImuLine, EulerAndLinearAccelerationFormats) {
  const ImuLine e = parse_imu_line("$AMGEUL,66449,-301,142,920,628,8,-400,-4,-11,-4,-281,-140,0");
  ASSERT_TRUE(e.sample.euler_deg);
  EXPECT_FALSE(e.sample.orientation);
  EXPECT_NEAR(e.sample.euler_deg->x(), -281 / 16.0, 1e-12);
  EXPECT_NEAR(e.sample.acceleration_m_s2.norm(), 9.78, 0.01);  // 1 g
  const ImuLine lin = parse_imu_line("$LMGQUA,1706673,-97,944,253,-819,-1316,273,0,0,0,0,0,0,16384");
  EXPECT_TRUE(lin.sample.gravity_removed);
  EXPECT_NEAR(lin.sample.orientation->w(), 1.0, 1e-12);
}

TEST(OcamsImuLine, MyAhrsLinesAreCheckedByTheirXorChecksum) {
  const std::string body =
      "$QUATIMU,53,0.0424,-0.0155,0.2916,0.9554,0.0232,0.0020,-0.9989,0.0000,-0.1220,0.3050,"
      "125.8008,-88.4766,123.5449,36.8";
  char hex[3];
  std::snprintf(hex, sizeof hex, "%02X", imu_checksum(body));
  const ImuLine l = parse_imu_line(body + "*" + hex + "\r\n");
  EXPECT_EQ(l.sample.sequence, 53u);
  EXPECT_NEAR(l.sample.acceleration_m_s2.z(), -0.9989 * 9.80665, 1e-9);
  EXPECT_NEAR(l.sample.angular_rate_radps.z(), 0.3050 * M_PI / 180, 1e-12);
  EXPECT_NEAR(l.sample.orientation->w(),
              0.9554 / std::sqrt(0.0424 * 0.0424 + 0.0155 * 0.0155 + 0.2916 * 0.2916 + 0.9554 * 0.9554), 1e-12);
  // One digit changed: the checksum no longer holds.
  std::string corrupt = body + "*" + hex;
  corrupt[12] = '5';
  EXPECT_THROW(parse_imu_line(corrupt), ImuLineError);
  // The documented example of the protocol: "@version" has checksum 3A.
  EXPECT_EQ(imu_checksum("@version"), 0x3A);
  EXPECT_EQ(myahrs_command("version"), "@version*3A\r\n");
}

TEST(OcamsImuLine, RepliesAndCommands) {
  EXPECT_EQ(parse_imu_line("~AMGQUA").kind, ImuLine::Kind::reply);
  EXPECT_EQ(parse_imu_line("~mode,ERROR,bad mode").kind, ImuLine::Kind::error_reply);
  EXPECT_EQ(ocams_format_command("AMGQUA"), "@AMGQUA\r\n");
  EXPECT_THROW(ocams_format_command("QUAT"), kestrel::Error);
}

TEST(OcamsImuLine, CorruptLinesSayWhatIsWrong) {
  auto error_of = [](const std::string& line) {
    try {
      parse_imu_line(line);
    } catch (const ImuLineError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(error_of("$AMGQUA,66449,-3,2,981,628,8,-400,9,-18,0,0,0,8192"),
              ::testing::HasSubstr("has 13 values, not 14"));
  EXPECT_THAT(error_of("$AMGQUA,66449,-3,2,9x1,628,8,-400,9,-18,0,0,0,8192,14189"),
              ::testing::HasSubstr("field 4 '9x1' is not a number"));
  EXPECT_THAT(error_of("$AMGQUA,66449,-3,2,981,628,8,-400,9,-18,0,0,0,0,0"),
              ::testing::HasSubstr("quaternion of norm 0"));
  EXPECT_THAT(error_of("$AMGQUA,66449,-3,2,981,628,8,-400,9,-18,0,0,0,99999,14189"),
              ::testing::HasSubstr("out of range"));
  EXPECT_THAT(error_of("$GPS,1,2"), ::testing::HasSubstr("format 'GPS'"));
  EXPECT_THAT(error_of("AMGQUA,1"), ::testing::HasSubstr("not $, ~ or @"));
  EXPECT_THAT(error_of("$QUATIMU,1*ZZ"), ::testing::HasSubstr("not two hex digits"));
  EXPECT_THAT(error_of(""), ::testing::HasSubstr("empty"));
  EXPECT_THAT(error_of(std::string("\x01\xff$AMGQUA", 9)), ::testing::HasSubstr("starts with '?'"));
}
