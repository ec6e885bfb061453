// The `intruder` node: a simulated intruder drone flying a chosen trajectory, published as
// ground truth at a fixed rate.
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/net_capture.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>

#include "evader.hpp"
#include "trajectory.hpp"

namespace kestrel::intruder {

struct IntruderConfig {
  enum class Shape { figure8, line, random, jink, evade, file };
  enum class AtEnd { hold, repeat };
  Shape shape = Shape::figure8;
  double rate_hz = 100.0;
  std::int64_t object_id = 1;
  double start_s = 0.0;
  Eigen::Vector3d camera_position_m{0.0, 0.0, 2.0};
  double camera_yaw_deg = 0.0;
  double distance_m = 5.0;  // the paper flies the figure-8 at 2.5, 5.0 and 7.5 m
  double half_width_m = 1.0;
  double half_height_m = 0.5;
  double period_s = 12.0;
  Eigen::Vector3d line_start_m{5.0, 3.0, 2.0};
  Eigen::Vector3d line_end_m{5.0, -3.0, 2.0};
  double speed_m_s = 1.0;
  double line_acceleration_m_s2 = 0.0;
  Eigen::Vector3d random_centre_m{5.0, 0.0, 2.0};
  Eigen::Vector3d random_half_extent_m{1.0, 1.5, 0.75};
  double max_speed_m_s = 3.0;
  double max_acceleration_m_s2 = 0.0;
  double random_max_frequency_hz = 0.25;
  double jink_speed_m_s = 5.0;
  double jink_acceleration_m_s2 = 4.0;
  double jink_min_hold_s = 0.5;
  double jink_max_hold_s = 2.0;
  double evade_cruise_speed_m_s = 2.0;
  double evade_speed_m_s = 6.0;
  double evade_acceleration_m_s2 = 6.0;
  double evade_flee_radius_m = 6.0;
  double evade_break_radius_m = 2.5;
  double evade_weave_period_s = 1.5;
  double evade_min_height_m = 1.0;
  std::string file;
  Eigen::Vector3d file_offset_m{0.0, 0.0, 0.0};
  double file_yaw_deg = 0.0;
  double file_time_scale = 1.0;
  AtEnd at_end = AtEnd::repeat;
  double ground_z_m = 0.0;
};

class IntruderNode final : public Node {
 public:
  static constexpr Input<msg::GroundTruth> kAlso{"also"};
  static constexpr Input<msg::NetCapture> kCaptured{"captured"};
  static constexpr Input<msg::VehicleState> kHunter{"hunter"};
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};

  static NodeSpec spec() {
    using C = IntruderConfig;
    ConfigSpec<C> c;
    c.choice("shape", &C::shape,
             {{"figure8", C::Shape::figure8},
              {"line", C::Shape::line},
              {"random", C::Shape::random},
              {"jink", C::Shape::jink},
              {"evade", C::Shape::evade},
              {"file", C::Shape::file}})
        .describe("trajectory");
    c.param("rate_hz", &C::rate_hz).with_unit("Hz").range(1.0, 10000.0).describe("state publication rate");
    c.param("object_id", &C::object_id).at_least(0).describe("ground-truth id of this intruder");
    c.param("start_s", &C::start_s).with_unit("s").describe("time into the trajectory at which the run starts");
    c.param("camera_position_m", &C::camera_position_m).with_unit("m").describe("reference camera position (world)");
    c.param("camera_yaw_deg", &C::camera_yaw_deg)
        .with_unit("deg")
        .range(-360, 360)
        .describe("reference camera heading");
    c.param("distance_m", &C::distance_m)
        .with_unit("m")
        .range(0.5, 100.0)
        .describe("figure8: distance of its plane from the camera (paper: 2.5, 5.0, 7.5)");
    c.param("half_width_m", &C::half_width_m).with_unit("m").range(0.0, 50.0).describe("figure8: half width");
    c.param("half_height_m", &C::half_height_m).with_unit("m").range(0.0, 50.0).describe("figure8: half height");
    c.param("period_s", &C::period_s).with_unit("s").range(0.5, 3600.0).describe("figure8: time for one loop");
    c.param("line_start_m", &C::line_start_m).with_unit("m").describe("line: start (world)");
    c.param("line_end_m", &C::line_end_m).with_unit("m").describe("line: end (world)");
    c.param("speed_m_s", &C::speed_m_s).with_unit("m/s").range(0.0, 100.0).describe("line: speed");
    c.param("line_acceleration_m_s2", &C::line_acceleration_m_s2)
        .with_unit("m/s^2")
        .range(0.0, 1000.0)
        .describe(
            "line: acceleration from rest and braking to rest at the ends (0: full speed throughout, "
            "instant turns)");
    c.param("random_centre_m", &C::random_centre_m)
        .with_unit("m")
        .describe("random and jink: centre of the box it stays in (world)");
    c.param("random_half_extent_m", &C::random_half_extent_m)
        .with_unit("m")
        .range(0.0, 100.0)
        .describe("random and jink: half size of that box (jink: it turns back when outside)");
    c.param("max_speed_m_s", &C::max_speed_m_s).with_unit("m/s").range(0.0, 100.0).describe("random: speed limit");
    c.param("max_acceleration_m_s2", &C::max_acceleration_m_s2)
        .with_unit("m/s^2")
        .range(0.0, 1000.0)
        .describe("random: acceleration limit; 0: only the box and the speed bound it");
    c.param("random_max_frequency_hz", &C::random_max_frequency_hz)
        .with_unit("Hz")
        .range(0.03, 10.0)
        .describe("random: the quickest manoeuvre's frequency (its period is the shortest)");
    c.param("jink_speed_m_s", &C::jink_speed_m_s).with_unit("m/s").range(0.1, 100.0).describe("jink: cruise speed");
    c.param("jink_acceleration_m_s2", &C::jink_acceleration_m_s2)
        .with_unit("m/s^2")
        .range(0.0, 100.0)
        .describe("jink: the lateral and vertical acceleration of each jink (bang-bang, at this limit)");
    c.param("jink_min_hold_s", &C::jink_min_hold_s)
        .with_unit("s")
        .range(0.01, 60.0)
        .describe("jink: the shortest time a manoeuvre is held");
    c.param("jink_max_hold_s", &C::jink_max_hold_s)
        .with_unit("s")
        .range(0.01, 60.0)
        .describe("jink: the longest time a manoeuvre is held (flights last at most 3600 s)");
    c.rule("jink_min_hold_s <= jink_max_hold_s", {"jink_min_hold_s", "jink_max_hold_s"},
           [](const C& k) { return k.jink_min_hold_s <= k.jink_max_hold_s; });
    c.param("evade_cruise_speed_m_s", &C::evade_cruise_speed_m_s)
        .with_unit("m/s")
        .range(0.0, 100.0)
        .describe("evade: speed between random waypoints in its box (random_centre_m, random_half_extent_m)");
    c.param("evade_speed_m_s", &C::evade_speed_m_s)
        .with_unit("m/s")
        .range(0.1, 100.0)
        .describe("evade: top speed, fleeing and breaking");
    c.param("evade_acceleration_m_s2", &C::evade_acceleration_m_s2)
        .with_unit("m/s^2")
        .range(0.1, 100.0)
        .describe("evade: acceleration limit");
    c.param("evade_flee_radius_m", &C::evade_flee_radius_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe("evade: with the hunter this close, it flees at top speed, weaving");
    c.param("evade_break_radius_m", &C::evade_break_radius_m)
        .with_unit("m")
        .range(0.0, 1000.0)
        .describe("evade: with the hunter this close, it breaks hard across the hunter's line of sight");
    c.param("evade_weave_period_s", &C::evade_weave_period_s)
        .with_unit("s")
        .range(0.1, 60.0)
        .describe("evade: one weave left and right while fleeing");
    c.param("evade_min_height_m", &C::evade_min_height_m)
        .with_unit("m")
        .range(-1000.0, 1000.0)
        .describe("evade: it never flies lower (world z)");
    c.rule("evade_break_radius_m <= evade_flee_radius_m", {"evade_break_radius_m", "evade_flee_radius_m"},
           [](const C& k) { return k.evade_break_radius_m <= k.evade_flee_radius_m; });
    c.param("file", &C::file).describe("file: CSV of t,x,y,z (s, world m)");
    c.param("file_offset_m", &C::file_offset_m)
        .with_unit("m")
        .describe("file: moves the recorded flight by this, after turning it (world = R(file_yaw_deg) p + offset)");
    c.param("file_yaw_deg", &C::file_yaw_deg)
        .with_unit("deg")
        .range(-360.0, 360.0)
        .describe("file: turns the recorded flight about the world's z axis through the origin");
    c.param("file_time_scale", &C::file_time_scale)
        .range(0.01, 100.0)
        .describe("file: plays the recording this many times as fast (2: twice the speed, half the time)");
    c.choice("at_end", &C::at_end, {{"hold", C::AtEnd::hold}, {"repeat", C::AtEnd::repeat}})
        .describe("line and file: after the end, hold the last point or go again (line: back and forth)");
    c.param("ground_z_m", &C::ground_z_m).with_unit("m").describe("height of the ground a caught intruder falls to");
    c.rule("file is set when shape = file", {"shape", "file"},
           [](const C& k) { return k.shape != C::Shape::file || !k.file.empty(); });
    return NodeSpec("intruder",
                    "A simulated intruder flying a figure-8, a line, random manoeuvres, jinks, evasions of its hunter "
                    "or a recorded flight")
        .details(
            "Publishes the intruder's world position and velocity. position_camera is given relative to the "
            "reference camera (camera_position_m, camera_yaw_deg), which also places the figure-8: in the plane "
            "normal to that camera's optical axis, distance_m in front of it. A camera model that moves "
            "republishes ground truth in its own frame. `evade` reacts to the hunter's true state on `hunter` (a "
            "delayed edge: the hunter reacts to it in turn); unconnected, it only cruises.")
        .input(kAlso, "other intruders' truth, published together with this one (chain intruders to fly several)",
               {.trigger = Trigger::latest, .optional = true})
        .input(kCaptured, "a net caught an intruder: if it is this one, it stops flying and falls to the ground",
               {.trigger = Trigger::latest, .optional = true})
        .input(kHunter, "evade: the hunter's true state, which it evades",
               {.trigger = Trigger::latest, .optional = true})
        .output(kTruth, "the intruder's true state (and those arriving on `also`)")
        .config(std::move(c));
  }

  explicit IntruderNode(NodeInit& init) : IntruderNode(init, init.config<IntruderConfig>()) {}

  void tick(Context& ctx) override {
    const State s = caught(ctx) ? falling(to_seconds(ctx.now())) : flying(ctx, start_ + to_seconds(ctx.now()));
    msg::GroundTruth truth;
    truth.stamp = ctx.now();
    msg::GroundTruthObject object;
    object.id = id_;
    object.position_world = s.position;
    object.velocity_world = s.velocity;
    object.position_camera = camera_.to_camera(s.position);
    truth.objects.push_back(object);
    if (const auto others = ctx.get(kAlso)) {
      // Move the others to this tick's time with their velocity, so all objects share one stamp.
      const double dt = to_seconds(ctx.now() - others->stamp);
      for (auto o : others->objects) {
        if (o.id == id_) throw Error("two intruders share object_id " + std::to_string(id_));
        o.position_world += o.velocity_world * dt;
        o.position_camera = camera_.to_camera(o.position_world);
        truth.objects.push_back(o);
      }
    }
    ctx.publish(kTruth, std::move(truth));
  }

 private:
  using Shape = IntruderConfig::Shape;

  IntruderNode(NodeInit& init, const IntruderConfig& cfg)
      : id_(static_cast<std::uint64_t>(cfg.object_id)),
        start_(cfg.start_s),
        ground_z_(cfg.ground_z_m),
        camera_(geometry::level_camera(cfg.camera_position_m, cfg.camera_yaw_deg * M_PI / 180.0)) {
    const bool repeat = cfg.at_end == IntruderConfig::AtEnd::repeat;
    switch (cfg.shape) {
      case Shape::figure8:
        trajectory_ =
            std::make_unique<FigureEight>(camera_, cfg.distance_m, cfg.half_width_m, cfg.half_height_m, cfg.period_s);
        break;
      case Shape::line:
        trajectory_ = std::make_unique<StraightLine>(cfg.line_start_m, cfg.line_end_m, cfg.speed_m_s, repeat,
                                                     cfg.line_acceleration_m_s2);
        break;
      case Shape::random:
        trajectory_ =
            std::make_unique<RandomManoeuvre>(cfg.random_centre_m, cfg.random_half_extent_m, cfg.max_speed_m_s,
                                              init.seed(), cfg.max_acceleration_m_s2, cfg.random_max_frequency_hz);
        break;
      case Shape::jink:
        trajectory_ =
            std::make_unique<Jink>(cfg.random_centre_m, cfg.random_half_extent_m, cfg.jink_speed_m_s,
                                   cfg.jink_acceleration_m_s2, cfg.jink_min_hold_s, cfg.jink_max_hold_s, init.seed());
        break;
      case Shape::evade:
        evader_.emplace(cfg.random_centre_m,
                        EvaderParams{cfg.random_centre_m, cfg.random_half_extent_m, cfg.evade_cruise_speed_m_s,
                                     cfg.evade_speed_m_s, cfg.evade_acceleration_m_s2, cfg.evade_flee_radius_m,
                                     cfg.evade_break_radius_m, cfg.evade_weave_period_s, cfg.evade_min_height_m},
                        init.seed());
        break;
      case Shape::file:
        trajectory_ = std::make_unique<Placed>(std::make_unique<RecordedFlight>(cfg.file, repeat), cfg.file_offset_m,
                                               cfg.file_yaw_deg * M_PI / 180.0, cfg.file_time_scale);
        break;
    }
    init.set_rate(cfg.rate_hz);
  }

  State flying(Context& ctx, double t) {
    if (!evader_) return trajectory_->at(t);
    std::optional<Eigen::Vector3d> hunter;
    if (const auto h = ctx.get(kHunter)) hunter = h->position;
    return evader_->step(t, hunter);
  }

  // Caught in a net (a capture for this id has arrived): tangled, it drops from where it was caught.
  bool caught(Context& ctx) {
    if (!caught_at_)
      if (const auto capture = ctx.get(kCaptured); capture && capture->object_id == id_) {
        caught_at_ = to_seconds(capture->stamp);
        caught_where_ = capture->position_world;
      }
    return caught_at_.has_value();
  }

  State falling(double t) const {
    const double tau = std::max(0.0, t - *caught_at_);
    State s;
    s.position = caught_where_;
    s.position.z() = std::max(ground_z_, caught_where_.z() - 0.5 * 9.81 * tau * tau);
    s.velocity = Eigen::Vector3d(0.0, 0.0, s.position.z() > ground_z_ ? -9.81 * tau : 0.0);
    return s;
  }

  std::uint64_t id_;
  double start_;
  double ground_z_;
  std::optional<double> caught_at_;
  Eigen::Vector3d caught_where_ = Eigen::Vector3d::Zero();
  geometry::CameraPose camera_;
  std::unique_ptr<Trajectory> trajectory_;
  std::optional<Evader> evader_;  // evade: flown step by step against the hunter
};
KESTREL_REGISTER_NODE(IntruderNode)

}  // namespace kestrel::intruder
