#pragma once
// A vehicle's recent states, to read its pose at the instant a sensor saw something. A camera frame
// taken at t comes out of the detection chain tens of milliseconds later (a hundred on a loaded
// companion computer), when the vehicle has moved and turned on: taking a detection to the world
// with the newest pose then puts it where the camera was not looking (at 1 rad/s of yaw and 0.1 s
// of lag, 0.6 m off at 6 m). ROS's tf2 buffer answers the same question for every frame.
#include <deque>
#include <kestrel/messages/vehicle_state.hpp>
#include <optional>

namespace kestrel::vehicle {

class StateHistory {
 public:
  /// Keeps the states of the last `span_s` seconds before the newest.
  explicit StateHistory(double span_s = 2.0);

  /// A state older than one kept already is put in its place; one with the stamp of a kept state
  /// replaces it.
  void add(const msg::VehicleState& state);
  bool empty() const { return states_.empty(); }
  std::size_t size() const { return states_.size(); }

  /// The state at `stamp`: between two kept states, position, velocity and body rates are
  /// interpolated linearly and the attitude along the shortest arc (slerp); later than the newest,
  /// the newest (never extrapolated); earlier than the oldest, the oldest. Empty: nothing kept.
  std::optional<msg::VehicleState> at(Time stamp) const;

 private:
  Time span_;
  std::deque<msg::VehicleState> states_;  // by stamp, oldest first
};

}  // namespace kestrel::vehicle
