#include "search.hpp"

#include <cmath>
#include <numbers>

namespace kestrel::aim {

double search_side(double heading_rad, const Eigen::Vector3d& hunter, const Eigen::Vector3d& expected_target) {
  const Eigen::Vector2d to_target = (expected_target - hunter).head<2>();
  // The z of heading x to_target: positive where the target is to the left.
  const double across = std::cos(heading_rad) * to_target.y() - std::sin(heading_rad) * to_target.x();
  return across < 0.0 ? -1.0 : 1.0;
}

Eigen::Vector3d expected_position(const Eigen::Vector3d& last_position, const Eigen::Vector3d& last_velocity,
                                  double elapsed_s) {
  return last_position + last_velocity * elapsed_s;
}

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;

// The side to turn to: where the target's last estimate, flown on since, now is.
double side_of(const LostTarget& lost) {
  return search_side(lost.heading_rad, lost.hunter,
                     expected_position(lost.last_position, lost.last_velocity, lost.since_seen_s));
}
}  // namespace

ComponentSpec HoldSearch::spec() {
  return ComponentSpec("hold", "Holds position and heading")
      .details("The lost target is waited for where it was lost.");
}

ComponentSpec TurnSearch::spec() {
  using C = TurnSearchConfig;
  ConfigSpec<C> c;
  c.param("yaw_rate_deg_s", &C::yaw_rate_deg_s).with_unit("deg/s").range(0.0, 360.0).describe("how fast it turns");
  return ComponentSpec("turn", "Holds position and turns")
      .details(
          "Holds position and turns at yaw_rate_deg_s, to the side where the target's last estimate, flown on at "
          "constant velocity since, lies: a target that passed behind the hunter is found sooner.")
      .config(std::move(c));
}

TurnSearch::TurnSearch(const ComponentInit& init) : cfg_(init.config<TurnSearchConfig>()) {}

void TurnSearch::begin(const LostTarget& lost) { side_ = side_of(lost); }

SearchStep TurnSearch::step(double, std::optional<double>) const {
  return {std::nullopt, side_ * cfg_.yaw_rate_deg_s * kDegree};
}

ComponentSpec BackOffSearch::spec() {
  using C = BackOffConfig;
  ConfigSpec<C> c;
  c.param("distance_m", &C::distance_m)
      .with_unit("m")
      .range(0.5, 100.0)
      .describe("horizontal distance of the standoff from where the target was last seen");
  c.param("height_m", &C::height_m)
      .with_unit("m")
      .range(-100.0, 100.0)
      .describe("height of the standoff above where the target was last seen");
  c.param("turn_after_s", &C::turn_after_s)
      .with_unit("s")
      .range(-1.0, 1000.0)
      .describe(
          "this long into the loss with nothing seen, hold and turn at yaw_rate_deg_s as `turn` does; < 0: hold the "
          "standoff");
  c.param("yaw_rate_deg_s", &C::yaw_rate_deg_s)
      .with_unit("deg/s")
      .range(0.0, 360.0)
      .describe("how fast it turns, after turn_after_s");
  return ComponentSpec("back_off", "Backs off from where the target was lost, facing it")
      .details(
          "Flies to a standoff distance_m back from where the target was last seen, along the line to the hunter, "
          "height_m above it, facing it: from farther away the camera sees more, above and below as well as to the "
          "sides. A target that passed behind the hunter, or fled out of range, is not found there: after "
          "turn_after_s the hunter turns as `turn` does.")
      .config(std::move(c));
}

BackOffSearch::BackOffSearch(const ComponentInit& init) : cfg_(init.config<BackOffConfig>()) {}

void BackOffSearch::begin(const LostTarget& lost) {
  Eigen::Vector2d away = (lost.hunter - lost.last_position).head<2>();
  if (away.norm() < 1e-3) away = -Eigen::Vector2d(std::cos(lost.heading_rad), std::sin(lost.heading_rad));
  away.normalize();
  standoff_.position.head<2>() = lost.last_position.head<2>() + cfg_.distance_m * away;
  standoff_.position.z() = std::max(lost.min_altitude_m, lost.last_position.z() + cfg_.height_m);
  standoff_.yaw = std::atan2(-away.y(), -away.x());
  side_ = side_of(lost);
}

SearchStep BackOffSearch::step(double lost_for_s, std::optional<double> turn_after_s) const {
  const double turn_after = turn_after_s.value_or(cfg_.turn_after_s);
  if (turn_after >= 0.0 && lost_for_s >= turn_after) return {std::nullopt, side_ * cfg_.yaw_rate_deg_s * kDegree};
  return {standoff_, 0.0};
}

}  // namespace kestrel::aim
