#pragma once
// The oCamS's IMU lines, parsed with no I/O. The camera's IMU is a Bosch BNO055 behind WithRobot's
// myAHRS+ firmware, on a CDC-ACM serial port. It speaks the myAHRS+ ASCII framing: commands start
// with '@', replies with '~', data with '$', fields are comma-separated and a line ends in CR LF.
// Two dialects are read:
//  - the oCamS's own data lines, as WithRobot's oCamS driver selects them (`@AMGQUA`): raw BNO055
//    integers, `$AMGQUA,time_ms,ax,ay,az,mx,my,mz,gx,gy,gz,qx,qy,qz,qw` (LMG: gravity removed;
//    EUL: three Euler angles instead of the quaternion), with no checksum;
//  - the myAHRS+ board's checksummed lines (`$QUATIMU,seq,x,y,z,w,ax,ay,az,gx,gy,gz,mx,my,mz,temp*HH`,
//    accelerations in g, rates in deg/s), where *HH is the XOR of every byte from the start
//    character up to '*'.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <kestrel/error.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace kestrel::ocams {

/// One IMU sample in SI units, in the IMU's own axes.
struct ImuSample {
  std::string format;                      ///< "AMGQUA", "QUATIMU", ...
  std::optional<std::uint32_t> device_ms;  ///< the device's clock, where the line carries it
  std::optional<std::uint32_t> sequence;   ///< myAHRS+ lines' counter (0..255)
  Eigen::Vector3d acceleration_m_s2 = Eigen::Vector3d::Zero();
  bool gravity_removed = false;  ///< LMG lines: linear acceleration
  Eigen::Vector3d angular_rate_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d magnetic_field_t = Eigen::Vector3d::Zero();
  std::optional<Eigen::Quaterniond> orientation;  ///< sensor to its reference (QUA lines)
  std::optional<Eigen::Vector3d> euler_deg;       ///< roll, pitch, yaw (EUL lines)
};

/// A line that cannot be what it claims to be.
class ImuLineError : public Error {
 public:
  using Error::Error;
};

/// What one line was.
struct ImuLine {
  enum class Kind { sample, reply, error_reply };
  Kind kind = Kind::sample;
  ImuSample sample;   ///< for Kind::sample
  std::string reply;  ///< the reply's text, "~AMGQUA" or "~mode,OK,mode=AC"
};

/// Parses one line, without its CR LF. Throws ImuLineError saying what is wrong with a line that
/// is corrupt: a bad checksum, a field that is not a number, too few or too many fields, an
/// unknown format.
ImuLine parse_imu_line(std::string_view line);

/// The XOR checksum of `text` (from the start character up to, not including, '*').
std::uint8_t imu_checksum(std::string_view text);

/// The line that selects an oCamS output format: "@AMGQUA\r\n". Throws on an unknown format.
std::string ocams_format_command(std::string_view format);
/// A myAHRS+ command with its checksum: "@asc_out,QUATIMU*HH\r\n".
std::string myahrs_command(std::string_view body);

/// The output formats the oCamS IMU offers.
bool is_ocams_format(std::string_view format);

}  // namespace kestrel::ocams
