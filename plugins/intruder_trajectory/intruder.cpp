// The `intruder` node: a simulated intruder drone flying a chosen trajectory, published as
// ground truth at a fixed rate.
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/plugin.hpp>

#include "trajectory.hpp"

namespace kestrel::intruder {

class IntruderNode final : public Node {
 public:
  static constexpr Input<msg::GroundTruth> kAlso{"also"};
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};

  static NodeSpec spec() {
    return NodeSpec("intruder",
                    "A simulated intruder flying a figure-8, a line, random manoeuvres or a recorded flight")
        .details(
            "Publishes the intruder's world position and velocity. position_camera is given relative to the "
            "reference camera (camera_position_m, camera_yaw_deg), which also places the figure-8: in the plane "
            "normal to that camera's optical axis, distance_m in front of it. A camera model that moves "
            "republishes ground truth in its own frame.")
        .input(kAlso, "other intruders' truth, published together with this one (chain intruders to fly several)",
               {.trigger = Trigger::latest, .optional = true})
        .output(kTruth, "the intruder's true state (and those arriving on `also`)")
        .param(
            param("shape", std::string("figure8")).one_of({"figure8", "line", "random", "file"}).describe("trajectory"))
        .param(param("rate_hz", 100.0).with_unit("Hz").range(1.0, 10000.0).describe("state publication rate"))
        .param(param("object_id", 1).at_least(0).describe("ground-truth id of this intruder"))
        .param(param("start_s", 0.0).with_unit("s").describe("time into the trajectory at which the run starts"))
        .param(param("camera_position_m", std::vector<double>{0.0, 0.0, 2.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("reference camera position (world)"))
        .param(param("camera_yaw_deg", 0.0).with_unit("deg").range(-360, 360).describe("reference camera heading"))
        .param(param("distance_m", 5.0)
                   .with_unit("m")
                   .range(0.5, 100.0)
                   .describe("figure8: distance of its plane from the camera (paper: 2.5, 5.0, 7.5)"))
        .param(param("half_width_m", 1.0).with_unit("m").range(0.0, 50.0).describe("figure8: half width"))
        .param(param("half_height_m", 0.5).with_unit("m").range(0.0, 50.0).describe("figure8: half height"))
        .param(param("period_s", 12.0).with_unit("s").range(0.5, 3600.0).describe("figure8: time for one loop"))
        .param(param("line_start_m", std::vector<double>{5.0, 3.0, 2.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("line: start (world)"))
        .param(param("line_end_m", std::vector<double>{5.0, -3.0, 2.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("line: end (world)"))
        .param(param("speed_mps", 1.0).with_unit("m/s").range(0.0, 100.0).describe("line: speed"))
        .param(param("random_centre_m", std::vector<double>{5.0, 0.0, 2.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("random: centre of the box it stays in (world)"))
        .param(param("random_half_extent_m", std::vector<double>{1.0, 1.5, 0.75})
                   .with_length(3)
                   .with_unit("m")
                   .range(0.0, 100.0)
                   .describe("random: half size of that box"))
        .param(param("max_speed_mps", 3.0).with_unit("m/s").range(0.0, 100.0).describe("random: speed limit"))
        .param(param("file", std::string("")).describe("file: CSV of t,x,y,z (s, world m)"))
        .param(param("at_end", std::string("repeat"))
                   .one_of({"hold", "repeat"})
                   .describe("line and file: after the end, hold the last point or go again (line: back and forth)"));
  }

  explicit IntruderNode(NodeInit& init)
      : id_(static_cast<std::uint64_t>(init.param<std::int64_t>("object_id"))),
        start_(init.param<double>("start_s")),
        camera_(geometry::level_camera(init.param<Eigen::Vector3d>("camera_position_m"),
                                       init.param<double>("camera_yaw_deg") * M_PI / 180.0)) {
    const std::string shape = init.param<std::string>("shape");
    const bool repeat = init.param<std::string>("at_end") == "repeat";
    if (shape == "figure8") {
      trajectory_ =
          std::make_unique<FigureEight>(camera_, init.param<double>("distance_m"), init.param<double>("half_width_m"),
                                        init.param<double>("half_height_m"), init.param<double>("period_s"));
    } else if (shape == "line") {
      trajectory_ = std::make_unique<StraightLine>(init.param<Eigen::Vector3d>("line_start_m"),
                                                   init.param<Eigen::Vector3d>("line_end_m"),
                                                   init.param<double>("speed_mps"), repeat);
    } else if (shape == "random") {
      trajectory_ = std::make_unique<RandomManoeuvre>(init.param<Eigen::Vector3d>("random_centre_m"),
                                                      init.param<Eigen::Vector3d>("random_half_extent_m"),
                                                      init.param<double>("max_speed_mps"), init.seed());
    } else {
      const std::string file = init.param<std::string>("file");
      if (file.empty()) throw Error("shape 'file' needs the 'file' parameter (a CSV of t,x,y,z)");
      trajectory_ = std::make_unique<RecordedFlight>(file, repeat);
    }
    init.set_rate(init.param<double>("rate_hz"));
  }

  void tick(Context& ctx) override {
    const State s = trajectory_->at(start_ + to_seconds(ctx.now()));
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
  std::uint64_t id_;
  double start_;
  geometry::CameraPose camera_;
  std::unique_ptr<Trajectory> trajectory_;
};
KESTREL_REGISTER_NODE(IntruderNode)

}  // namespace kestrel::intruder
