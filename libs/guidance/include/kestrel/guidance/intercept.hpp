#pragma once
// The earliest intercept: the first time within a horizon at which the hunter, within its speed
// and acceleration limits, can be at the aim pose of the target as predicted for that time.
#include <Eigen/Core>
#include <functional>
#include <optional>

#include "kestrel/guidance/guidance.hpp"

namespace kestrel::guidance {

/// True when a double integrator at (p, v), with |a| <= max_acceleration and |v| <= max_speed,
/// can be at `goal` after `tau` seconds: the goal lies within the ball it can reach by
/// accelerating, |goal - (p + v tau)| <= a tau^2 / 2, and no faster than its top speed on
/// average, |goal - p| <= max_speed tau.
bool reachable(const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& goal, double tau,
               const FlightLimits& limits);

struct InterceptPlan {
  double time_s = 0.0;                                         ///< from now
  Eigen::Vector3d point = Eigen::Vector3d::Zero();             ///< the aim pose then (world)
  Eigen::Vector3d arrival_velocity = Eigen::Vector3d::Zero();  ///< the target's velocity then
  double yaw = 0.0;                                            ///< the aim pose's heading then
};

/// The earliest tau in [step, horizon], on a grid of `step`, at which `goal_at(tau)` is reachable
/// from (p, v); none if no time within the horizon is.
std::optional<InterceptPlan> earliest_intercept(const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                                                const std::function<InterceptPlan(double)>& goal_at,
                                                const FlightLimits& limits, double horizon_s, double step_s);

/// The acceleration that brings a double integrator from (p, v) to (goal, goal_velocity) in tau
/// seconds with the least control effort (zero-effort-miss / zero-effort-velocity guidance):
/// a = 6 ZEM / tau^2 - 2 ZEV / tau, ZEM = goal - (p + v tau), ZEV = goal_velocity - v.
Eigen::Vector3d rendezvous_acceleration(const Eigen::Vector3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& goal,
                                        const Eigen::Vector3d& goal_velocity, double tau);

}  // namespace kestrel::guidance
