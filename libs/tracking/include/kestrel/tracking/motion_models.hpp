#pragma once
// The motion models an estimate can predict with, all on the paper's 9-state [p v a] (world
// frame, kestrel/tracking/constant_acceleration.hpp), so that an IMM can mix them state for state:
//
//   constant_velocity      a = 0; white-noise acceleration of intensity q (m^2/s^3) drives v.
//                          Per axis F = [[1, dt, 0], [0, 1, 0], [0, 0, 0]],
//                          Q = q [[dt^3/3, dt^2/2, 0], [dt^2/2, dt, 0], [0, 0, 0]].
//   constant_acceleration  the paper's model: white-noise jerk of intensity q (m^2/s^5).
//   coordinated_turn       the horizontal acceleration turns with the velocity at a constant rate w
//                          (a constant turn, Bar-Shalom, Li, Kirubarajan, "Estimation with
//                          Applications to Tracking and Navigation", 11.7, written on [p v a] so that
//                          it learns its acceleration as the constant-acceleration model does);
//                          w is read from the state, w = (v x a)_z / |v_xy|^2, and held over the
//                          step, so F(w) stays linear. A centripetal acceleration flies the circle;
//                          at w = 0 it is constant acceleration. The vertical axis is constant
//                          acceleration; white-noise jerk q (m^2/s^5) covers the turn rate's changes.
#include <string_view>

#include "kestrel/tracking/constant_acceleration.hpp"

namespace kestrel::tracking {

enum class MotionModel { constant_velocity, constant_acceleration, coordinated_turn };

/// "cv", "ca", "ct".
std::string_view motion_model_name(MotionModel model);

/// The turn rate a coordinated turn reads from the state (rad/s, positive to the left); 0 below
/// `min_speed` m/s horizontally, where a heading means nothing, and at most `max_rate` in magnitude.
double turn_rate(const State& x, double min_speed = 0.5, double max_rate = 3.14159);

/// The transition of a model over dt from the state x (only the turn reads x: its rate).
Covariance model_transition(MotionModel model, const State& x, double dt);
/// The process noise of a model over dt with intensity q (units above).
Covariance model_process_noise(MotionModel model, double dt, double q);

}  // namespace kestrel::tracking
