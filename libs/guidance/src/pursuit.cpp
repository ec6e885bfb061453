#include "kestrel/guidance/pursuit.hpp"

namespace kestrel::guidance {

namespace {
void declare(ConfigSpec<PursuitConfig>& c) {
  c.param("handover_m", &PursuitConfig::handover_m)
      .with_unit("m")
      .range(0.0, 1000.0)
      .describe("hand over to the terminal phase (align the net, fire) within this distance of the aim pose");
}
}  // namespace

ComponentSpec Pursuit::spec() {
  ConfigSpec<PursuitConfig> c;
  declare(c);
  return ComponentSpec("pursuit", "Pure pursuit: at top speed straight at the aim pose")
      .details(
          "The wanted velocity points from the reference at the aim pose, at the hunter's top speed; within "
          "handover_m the terminal phase aligns the net. Never leads the target.")
      .config(std::move(c));
}

Pursuit::Pursuit(const ComponentInit& init) : cfg_(init.config<PursuitConfig>()) {}

GuidanceCommand Pursuit::command(const Engagement& e) {
  if (within_handover(e, cfg_.handover_m)) return terminal_phase();
  const Eigen::Vector3d r = e.aim.position - e.position;
  return {r.normalized() * e.limits.max_speed, e.aim.yaw, false, std::nullopt};
}

}  // namespace kestrel::guidance
