#include "kestrel/vehicle/state_history.hpp"

#include <algorithm>

namespace kestrel::vehicle {

StateHistory::StateHistory(double span_s) : span_(from_seconds(span_s)) {}

void StateHistory::add(const msg::VehicleState& state) {
  const auto later = std::upper_bound(states_.begin(), states_.end(), state.stamp,
                                      [](Time t, const msg::VehicleState& s) { return t < s.stamp; });
  if (later != states_.begin() && std::prev(later)->stamp == state.stamp)
    *std::prev(later) = state;
  else
    states_.insert(later, state);
  const Time oldest_kept = states_.back().stamp - span_;
  while (states_.size() > 1 && states_.front().stamp < oldest_kept) states_.pop_front();
}

std::optional<msg::VehicleState> StateHistory::at(Time stamp) const {
  if (states_.empty()) return std::nullopt;
  if (stamp >= states_.back().stamp) return states_.back();
  if (stamp <= states_.front().stamp) return states_.front();
  const auto after = std::upper_bound(states_.begin(), states_.end(), stamp,
                                      [](Time t, const msg::VehicleState& s) { return t < s.stamp; });
  const msg::VehicleState& a = *std::prev(after);
  const msg::VehicleState& b = *after;
  if (a.stamp == stamp) return a;
  const double f = to_seconds(stamp - a.stamp) / to_seconds(b.stamp - a.stamp);
  msg::VehicleState s;
  s.stamp = stamp;
  s.position = a.position + f * (b.position - a.position);
  s.velocity = a.velocity + f * (b.velocity - a.velocity);
  s.orientation = a.orientation.slerp(f, b.orientation).normalized();
  s.angular_velocity = a.angular_velocity + f * (b.angular_velocity - a.angular_velocity);
  return s;
}

}  // namespace kestrel::vehicle
