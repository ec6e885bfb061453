// The `setpoint_step` node: a trajectory setpoint that holds one position, then steps to another,
// the classic input for tuning and checking a position controller. For failsafe tests it can
// also publish setpoints that are not finite numbers during a window.
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/plugin.hpp>
#include <limits>

namespace kestrel::setpoints {

struct SetpointStepConfig {
  double rate_hz = 50.0;
  Eigen::Vector3d position_m{0.0, 0.0, 2.0};
  double yaw_deg = 0.0;
  Eigen::Vector3d step_m{0.0, 0.0, 0.0};
  double step_yaw_deg = 0.0;
  double step_at_s = 5.0;
  double fault_at_s = -1.0;
  double fault_for_s = 0.0;
};

class SetpointStep final : public Node {
 public:
  static constexpr Output<msg::TrajectorySetpoint> kSetpoint{"setpoint"};

  static NodeSpec spec() {
    using C = SetpointStepConfig;
    ConfigSpec<C> c;
    c.param("rate_hz", &C::rate_hz).with_unit("Hz").range(0.1, 10000.0).describe("publication rate");
    c.param("position_m", &C::position_m).with_unit("m").describe("position held first (world, z up)");
    c.param("yaw_deg", &C::yaw_deg).with_unit("deg").range(-360.0, 360.0).describe("heading held first");
    c.param("step_m", &C::step_m).with_unit("m").range(-1000.0, 1000.0).describe("added to position_m at step_at_s");
    c.param("step_yaw_deg", &C::step_yaw_deg)
        .with_unit("deg")
        .range(-360.0, 360.0)
        .describe("added to yaw_deg at step_at_s");
    c.param("step_at_s", &C::step_at_s).with_unit("s").at_least(0.0).describe("time of the step");
    c.param("fault_at_s", &C::fault_at_s)
        .with_unit("s")
        .describe("from this time the setpoint is NaN (a failsafe test); negative: never");
    c.param("fault_for_s", &C::fault_for_s).with_unit("s").at_least(0.0).describe("how long the NaNs last");
    return NodeSpec("setpoint_step", "A position setpoint that holds, then steps (optionally NaN for a while)")
        .details(
            "Publishes position_m and yaw_deg, then from step_at_s on position_m + step_m and yaw_deg + step_yaw_deg, "
            "with zero velocity and acceleration. Between fault_at_s and fault_at_s + fault_for_s every field is "
            "NaN, to check that a controller keeps non-finite setpoints away from the motors.")
        .output(kSetpoint, "the setpoint (world frame)")
        .config(std::move(c));
  }

  explicit SetpointStep(NodeInit& init) : cfg_(init.config<SetpointStepConfig>()) { init.set_rate(cfg_.rate_hz); }

  void tick(Context& ctx) override {
    const double t = to_seconds(ctx.now());
    msg::TrajectorySetpoint sp;
    sp.stamp = ctx.now();
    const bool stepped = t >= cfg_.step_at_s;
    sp.position = cfg_.position_m + (stepped ? cfg_.step_m : Eigen::Vector3d::Zero());
    sp.yaw = (cfg_.yaw_deg + (stepped ? cfg_.step_yaw_deg : 0.0)) * M_PI / 180.0;
    if (cfg_.fault_at_s >= 0.0 && t >= cfg_.fault_at_s && t < cfg_.fault_at_s + cfg_.fault_for_s) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      sp.position.setConstant(nan);
      sp.velocity.setConstant(nan);
      sp.acceleration.setConstant(nan);
      sp.yaw = sp.yaw_rate = nan;
    }
    ctx.publish(kSetpoint, std::move(sp));
  }

 private:
  SetpointStepConfig cfg_;
};
KESTREL_REGISTER_NODE(SetpointStep)

}  // namespace kestrel::setpoints
