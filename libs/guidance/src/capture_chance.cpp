#include "kestrel/guidance/capture_chance.hpp"

#include <algorithm>
#include <cmath>

namespace kestrel::guidance {

CaptureChance capture_chance(const TargetFutures& futures, const net::NetModel& net, const Launch& launch,
                             const std::vector<Eigen::Vector3d>& launcher_errors, bool seen_at_launch) {
  CaptureChance chance;
  if (futures.empty()) return chance;
  const net::NetParams& p = net.params();
  const net::NetShot shot = net.fire(launch.time_s, launch.launcher, launch.velocity);
  // The net's centre while open, every 30 ms at most (a net several m/s fast crosses a path
  // between two checks otherwise; the paths are linear between their own steps).
  const int checks = std::max(2, static_cast<int>(std::ceil(p.open_for_s / 0.03)) + 1);
  std::vector<double> when(static_cast<std::size_t>(checks));
  std::vector<Eigen::Vector3d> centre(static_cast<std::size_t>(checks));
  for (int k = 0; k < checks; ++k) {
    when[static_cast<std::size_t>(k)] = launch.time_s + p.flight_time_s + p.open_for_s * k / (checks - 1);
    centre[static_cast<std::size_t>(k)] = net.position(shot, when[static_cast<std::size_t>(k)]);
  }
  const double spread = 2.0 * p.radius_m;
  int caught = 0;
  double closeness = 0.0;
  // Seen at the launch: each path's offset from the mean there is known to the launch and taken out.
  const Eigen::Vector3d mean_at = seen_at_launch ? futures.mean(launch.time_s) : Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < futures.size(); ++i) {
    Eigen::Vector3d error = i < launcher_errors.size() ? launcher_errors[i] : Eigen::Vector3d::Zero();
    if (seen_at_launch) error += futures.position(i, launch.time_s) - mean_at;
    double least = INFINITY;
    for (std::size_t k = 0; k < when.size(); ++k)
      least = std::min(least, (futures.position(i, when[k]) - centre[k] - error).norm());
    if (least <= p.radius_m) ++caught;
    closeness += std::exp(-least * least / (2.0 * spread * spread));
  }
  const auto n = static_cast<double>(futures.size());
  chance.probability = caught / n;
  chance.closeness = closeness / n;
  return chance;
}

CaptureChance capture_chance(const TargetFutures& futures, const net::NetModel& net, const Launch& launch,
                             const ReactingTarget& reacting, const std::vector<Eigen::Vector3d>& launcher_errors,
                             bool seen_at_launch) {
  const CaptureChance own = capture_chance(futures, net, launch, launcher_errors, seen_at_launch);
  const double w = reacting.probability;
  if (w <= 0.0 || !reacting.config || !reacting.hunter) return own;
  constexpr std::size_t kStride = 4;  // a quarter of the paths react: the cost is per candidate launch
  const TargetFutures fleeing = reacting_futures(futures, *reacting.config, reacting.hunter, kStride);
  std::vector<Eigen::Vector3d> errors;
  for (std::size_t i = 0; i < launcher_errors.size(); i += kStride) errors.push_back(launcher_errors[i]);
  const CaptureChance fled = capture_chance(fleeing, net, launch, errors, seen_at_launch);
  return {(1.0 - w) * own.probability + w * fled.probability, (1.0 - w) * own.closeness + w * fled.closeness};
}

}  // namespace kestrel::guidance
