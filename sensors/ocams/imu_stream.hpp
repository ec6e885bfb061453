#pragma once
// The oCamS's IMU as a stream of kestrel Imu messages: the serial port opened, the output format
// asked for, each line parsed and checked, the device clock mapped onto the runtime's. Bad lines
// are counted, never fatal; a port that hangs up or falls silent is reopened when `reconnect`.
#include <chrono>
#include <functional>
#include <kestrel/messages/imu.hpp>
#include <memory>
#include <string>
#include <vector>

#include "device_clock.hpp"
#include "imu_port.hpp"

namespace kestrel::ocams {

struct ImuStreamOptions {
  std::string port = "/dev/ttyACM0";
  int baud = 115200;
  /// AMGQUA, AMGEUL, LMGQUA, LMGEUL (the oCamS's), or QUATIMU (a myAHRS+ board's, checksummed).
  std::string format = "AMGQUA";
  std::string frame = "ocams_imu";
  std::chrono::milliseconds silence_timeout{1000};
  bool reconnect = true;
};

struct ImuCounters {
  std::uint64_t samples = 0;
  std::uint64_t bad_lines = 0;
  std::uint64_t replies = 0;
  std::uint64_t error_replies = 0;
  std::uint64_t hangups = 0;
  std::uint64_t silences = 0;
  std::uint64_t reconnects = 0;
  std::string last_bad_line;  ///< what was wrong with the last bad line
};

class ImuStream {
 public:
  /// Opens the port and asks for the format. Throws Error ("no oCamS IMU at ...") when the port
  /// is not there.
  ImuStream(ImuStreamOptions options, std::function<Time()> now);

  /// The samples that arrive within `wait`, in order. Throws Error when the port hangs up or
  /// falls silent without `reconnect`.
  std::vector<msg::Imu> read(std::chrono::milliseconds wait);

  const ImuCounters& counters() const { return counters_; }
  bool connected() const { return port_ != nullptr; }

 private:
  void open();
  void lose(const std::string& why);

  ImuStreamOptions options_;
  std::function<Time()> now_;
  std::unique_ptr<ImuPort> port_;
  DeviceClock clock_;
  ImuCounters counters_;
  std::chrono::steady_clock::time_point last_line_, last_try_;
};

}  // namespace kestrel::ocams
