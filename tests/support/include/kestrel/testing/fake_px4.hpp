#pragma once
// A PX4 autopilot as far as a companion's MAVLink tests need one, on a thread of its own over
// loopback UDP: it sends heartbeats (2 Hz) and a fixed state (50 Hz) to a udpin port, plays PX4's
// offboard rules as sim_autopilot does (OffboardRules: offboard only with a setpoint stream, hold
// when it stops, an ack for each command), and records what it received. `silence(from, to)`
// stops its heartbeats for a while (a radio link lost).
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>
#include <vector>

#include "kestrel/mavlink/connection_url.hpp"
#include "kestrel/mavlink/frame.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/udp_transport.hpp"
#include "offboard_rules.hpp"

namespace kestrel::testing {

class FakePx4 {
 public:
  using Clock = std::chrono::steady_clock;
  struct Received {
    double t;  ///< seconds since the fake started
    mavlink::Frame frame;
  };

  explicit FakePx4(std::uint16_t port)
      : link_(mavlink::parse_connection_url("udpout://127.0.0.1:" + std::to_string(port))),
        start_(Clock::now()),
        thread_([this] { run(); }) {}
  ~FakePx4() {
    stop_ = true;
    thread_.join();
  }

  void silence(double from_s, double to_s) {
    silent_from_ = from_s;
    silent_to_ = to_s;
  }
  std::vector<Received> received() const {
    std::lock_guard lock(mutex_);
    return received_;
  }
  bool offboard() const { return offboard_; }
  bool armed() const { return armed_; }
  std::uint64_t bad_frames() const {
    std::lock_guard lock(mutex_);
    return parser_.counts().bad_checksum + parser_.counts().bad_flags;
  }

 private:
  double now() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  void run() {
    mavlink::FrameWriter px4({1, mavlink::mav::comp_autopilot1});
    std::vector<std::uint8_t> buffer(2048);
    double next_heartbeat = 0.0, next_state = 0.0;
    while (!stop_) {
      const double t = now();
      if (t >= next_heartbeat) {
        next_heartbeat = t + 0.5;
        if (!(t >= silent_from_ && t < silent_to_)) link_.send(px4.encode(rules_.heartbeat()));
      }
      if (t >= next_state) {
        next_state = t + 0.02;
        mavlink::LocalPositionNed p;
        p.z = -2.0f;
        link_.send(px4.encode(p));
        link_.send(px4.encode(mavlink::AttitudeQuaternion{}));
      }
      const std::size_t n = link_.receive(buffer, std::chrono::milliseconds(5));
      std::vector<mavlink::Frame> frames;
      {
        std::lock_guard lock(mutex_);
        frames = parser_.feed(std::span(buffer.data(), n));
        for (const auto& f : frames) received_.push_back({t, f});
      }
      for (const auto& f : frames)
        if (const auto answer = rules_.on_frame(f, t, false).ack) link_.send(px4.encode(*answer));
      rules_.step(t);  // PX4 leaves offboard when the setpoints stop (COM_OF_LOSS_T, 0.5 s here)
      offboard_ = rules_.mode() == sim_autopilot::FlightMode::offboard;
      armed_ = rules_.armed();
    }
  }

  mavlink::UdpTransport link_;
  Clock::time_point start_;
  mutable std::mutex mutex_;
  mavlink::FrameParser parser_;
  std::vector<Received> received_;
  sim_autopilot::OffboardRules rules_;  // the fake's thread's only
  std::atomic<bool> offboard_{false}, armed_{false}, stop_{false};
  std::atomic<double> silent_from_{1e9}, silent_to_{1e9};
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace kestrel::testing
