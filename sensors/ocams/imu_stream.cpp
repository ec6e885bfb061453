#include "imu_stream.hpp"

#include <thread>

#include "imu_protocol.hpp"

namespace kestrel::ocams {

ImuStream::ImuStream(ImuStreamOptions options, std::function<Time()> now)
    : options_(std::move(options)), now_(std::move(now)) {
  if (!is_ocams_format(options_.format) && options_.format != "QUATIMU")
    throw Error("IMU format '" + options_.format + "' is not AMGQUA, AMGEUL, LMGQUA, LMGEUL or QUATIMU");
  try {
    open();
  } catch (const PortLost& e) {
    throw Error(std::string("no oCamS IMU at ") + options_.port + " (" + e.what() + ")");
  }
}

void ImuStream::open() {
  auto port = std::make_unique<ImuPort>(options_.port, options_.baud);
  if (is_ocams_format(options_.format)) {
    port->write(ocams_format_command(options_.format));
  } else {  // a myAHRS+ board: ASCII, continuous, then the format
    port->write(myahrs_command("mode,AC"));
    port->write(myahrs_command("asc_out," + options_.format));
  }
  port_ = std::move(port);
  clock_.reset();
  last_line_ = std::chrono::steady_clock::now();
}

void ImuStream::lose(const std::string& why) {
  port_.reset();
  if (!options_.reconnect) throw Error(options_.port + ": " + why);
  last_try_ = std::chrono::steady_clock::now();
}

std::vector<msg::Imu> ImuStream::read(std::chrono::milliseconds wait) {
  std::vector<msg::Imu> out;
  const auto deadline = std::chrono::steady_clock::now() + wait;
  if (!port_) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_try_ >= std::chrono::milliseconds(100)) {
      last_try_ = now;
      try {
        open();
        ++counters_.reconnects;
      } catch (const PortLost&) {
      }
    }
    if (!port_) {
      std::this_thread::sleep_until(deadline);
      return out;
    }
  }
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    std::optional<std::string> line;
    try {
      line = port_->read_line(std::max(left, std::chrono::milliseconds(0)));
    } catch (const PortLost& e) {
      ++counters_.hangups;
      lose(e.what());
      return out;
    }
    const auto now = std::chrono::steady_clock::now();
    if (!line) {
      if (now - last_line_ >= options_.silence_timeout) {
        ++counters_.silences;
        lose("no line for " + std::to_string(options_.silence_timeout.count()) + " ms");
      }
      return out;
    }
    last_line_ = now;
    try {
      const ImuLine parsed = parse_imu_line(*line);
      if (parsed.kind == ImuLine::Kind::reply) {
        ++counters_.replies;
      } else if (parsed.kind == ImuLine::Kind::error_reply) {
        ++counters_.error_replies;
        counters_.last_bad_line = parsed.reply;
      } else {
        const ImuSample& s = parsed.sample;
        msg::Imu m;
        const Time arrival = now_();
        m.stamp = s.device_ms ? clock_.map(*s.device_ms, arrival) : arrival;
        m.frame = options_.frame;
        m.angular_velocity = s.angular_rate_radps;
        m.linear_acceleration = s.acceleration_m_s2;
        m.gravity_removed = s.gravity_removed;
        m.orientation = s.orientation;
        m.magnetic_field = s.magnetic_field_t;
        out.push_back(m);
        ++counters_.samples;
      }
    } catch (const ImuLineError& e) {
      ++counters_.bad_lines;
      counters_.last_bad_line = e.what();
    }
  }
}

}  // namespace kestrel::ocams
