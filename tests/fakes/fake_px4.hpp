#pragma once
// A PX4 autopilot as far as a companion's MAVLink tests need one, on a thread of its own over
// loopback UDP: it sends heartbeats (2 Hz) and its state (50 Hz) to a udpin port, follows PX4's
// offboard rule (the mode is granted only with setpoints arriving, at least 10 in the last half
// second), arms on COMPONENT_ARM_DISARM, acknowledges each command, and records what it received.
// `silence(from, to)` stops its heartbeats for a while (a radio link lost).
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>
#include <vector>

#include "connection_url.hpp"
#include "frame.hpp"
#include "frame_parser.hpp"
#include "messages.hpp"
#include "udp_transport.hpp"

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
        if (!(t >= silent_from_ && t < silent_to_)) {
          mavlink::Heartbeat hb;
          hb.type = mavlink::mav::type_quadrotor;
          hb.autopilot = mavlink::mav::autopilot_px4;
          hb.base_mode =
              mavlink::mav::mode_flag_custom_mode_enabled | (armed_ ? mavlink::mav::mode_flag_safety_armed : 0);
          hb.custom_mode = offboard_ ? 6u << 16 : 3u << 16;  // offboard, or position
          hb.system_status = mavlink::mav::state_active;
          link_.send(px4.encode(hb));
        }
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
      for (const auto& f : frames) {
        if (f.is<mavlink::SetPositionTargetLocalNed>() || f.is<mavlink::SetAttitudeTarget>())
          setpoint_times_.push_back(t);
        if (f.is<mavlink::CommandLong>()) answer(px4, f.as<mavlink::CommandLong>(), t);
      }
      // PX4 leaves offboard when the setpoints stop (COM_OF_LOSS_T, 0.5 s here).
      if (offboard_ && (setpoint_times_.empty() || t - setpoint_times_.back() > 0.5)) offboard_ = false;
    }
  }

  void answer(mavlink::FrameWriter& px4, const mavlink::CommandLong& c, double t) {
    mavlink::CommandAck ack;
    ack.command = c.command;
    ack.result = mavlink::mav::result_accepted;
    if (c.command == mavlink::mav::cmd_do_set_mode && c.param2 == 6.0f) {
      std::size_t recent = 0;
      for (const double s : setpoint_times_) recent += t - s <= 0.5 ? 1 : 0;
      if (recent >= 10)
        offboard_ = true;
      else
        ack.result = mavlink::mav::result_temporarily_rejected;
    } else if (c.command == mavlink::mav::cmd_component_arm_disarm) {
      armed_ = c.param1 == 1.0f;
    }
    link_.send(px4.encode(ack));
  }

  mavlink::UdpTransport link_;
  Clock::time_point start_;
  mutable std::mutex mutex_;
  mavlink::FrameParser parser_;
  std::vector<Received> received_;
  std::vector<double> setpoint_times_;
  std::atomic<bool> offboard_{false}, armed_{false}, stop_{false};
  std::atomic<double> silent_from_{1e9}, silent_to_{1e9};
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace kestrel::testing
