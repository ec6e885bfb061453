// The `sim_stereo` node: a simulated stereo camera that renders the world with MRPT's off-screen
// EGL renderer. Defaults are the WithRobot oCamS-1CGN-U at 640x480.
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <opencv2/imgproc.hpp>

#include "stereo_renderer.hpp"
#include "world_scene.hpp"

namespace kestrel::sim {

class SimStereo final : public Node {
 public:
  static constexpr Input<msg::GroundTruth> kIntruders{"intruders"};
  static constexpr Input<msg::VehicleState> kPose{"pose"};
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};

  static NodeSpec spec() {
    return NodeSpec("sim_stereo", "Simulated stereo camera: renders rectified image pairs of the world (MRPT, EGL)")
        .details(
            "Renders the left and right images of a textured world (ground, clutter, the intruders as hexacopters) "
            "with MRPT's headless CFBORender, converts them to 8-bit grey and adds Gaussian noise. Intruder states "
            "arrive on `intruders` and are moved to the capture time with their velocity. The camera stands at "
            "camera_position_m / camera_yaw_deg, or rides on the vehicle whose state arrives on `pose` "
            "(mounted at camera_offset_m in its body frame). Each frame comes with ground truth at its capture "
            "time, in the camera and world frames.")
        .input(kIntruders, "true intruder states", {.trigger = Trigger::latest, .optional = true})
        .input(kPose, "pose of the vehicle carrying the camera", {.trigger = Trigger::latest, .optional = true})
        .output(kFrame, "rectified stereo pair with its calibration")
        .output(kTruth, "intruder positions at the capture time (camera and world frames)")
        .param(param("width", 640).range(64, 4096).with_unit("px").describe("image width"))
        .param(param("height", 480).range(48, 4096).with_unit("px").describe("image height"))
        .param(param("fps", 30.0).range(0.1, 240.0).with_unit("Hz").describe("frame rate"))
        .param(param("hfov_deg", 70.6)
                   .range(10.0, 150.0)
                   .with_unit("deg")
                   .describe("horizontal field of view; 70.6 gives the oCamS's rectified fx = 452 px at 640 px "
                             "(the paper states 92.8)"))
        .param(param("baseline_m", 0.12).range(0.01, 2.0).with_unit("m").describe("distance between the cameras"))
        .param(
            param("min_depth_m", 0.5).range(0.05, 100.0).with_unit("m").describe("nearest depth the camera measures"))
        .param(
            param("max_depth_m", 15.0).range(0.1, 1000.0).with_unit("m").describe("farthest depth the camera measures"))
        .param(param("noise_sigma", 1.5).range(0.0, 50.0).with_unit("grey levels").describe("Gaussian image noise"))
        .param(param("color", false).describe("publish BGR images instead of 8-bit grey"))
        .param(param("camera_position_m", std::vector<double>{0.0, 0.0, 2.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("fixed camera position (world), when `pose` is not connected"))
        .param(param("camera_yaw_deg", 0.0).range(-360.0, 360.0).with_unit("deg").describe("fixed camera heading"))
        .param(param("camera_offset_m", std::vector<double>{0.1, 0.0, 0.0})
                   .with_length(3)
                   .with_unit("m")
                   .describe("camera position in the vehicle's body frame, when `pose` is connected"))
        .param(param("clutter_count", 12).range(0, 500).describe("trees and buildings in the background"))
        .param(param("clutter_min_range_m", 12.0)
                   .range(0.0, 500.0)
                   .with_unit("m")
                   .describe("clutter's nearest distance from the world origin"))
        .param(
            param("clutter_max_range_m", 40.0).range(0.0, 500.0).with_unit("m").describe("clutter's farthest distance"))
        .param(param("scene_seed", 1)
                   .at_least(0)
                   .describe("lays out the world and its textures; the run seed drives the noise"));
  }

  explicit SimStereo(NodeInit& init)
      : noise_sigma_(init.param<double>("noise_sigma")),
        color_(init.param<bool>("color")),
        min_depth_(init.param<double>("min_depth_m")),
        max_depth_(init.param<double>("max_depth_m")),
        fixed_camera_(geometry::level_camera(init.param<Eigen::Vector3d>("camera_position_m"),
                                             init.param<double>("camera_yaw_deg") * M_PI / 180.0)),
        offset_(init.param<Eigen::Vector3d>("camera_offset_m")),
        scene_(scene_options(init)),
        renderer_(calibration(init)) {
    if (min_depth_ >= max_depth_) throw Error("min_depth_m must be below max_depth_m");
    calibration_ = calibration(init);
    init.set_rate(init.param<double>("fps"));
  }

  void tick(Context& ctx) override {
    const Time stamp = ctx.now();
    const geometry::CameraPose camera = camera_pose(ctx);
    msg::GroundTruth truth;
    truth.stamp = stamp;
    if (const auto intruders = ctx.get(kIntruders)) {
      const double dt = to_seconds(stamp - intruders->stamp);
      for (const auto& o : intruders->objects) {
        msg::GroundTruthObject now = o;
        now.position_world = o.position_world + o.velocity_world * dt;
        now.position_camera = camera.to_camera(now.position_world);
        now.in_view = in_view(now.position_camera);
        const double yaw =
            o.velocity_world.head<2>().norm() > 0.1 ? std::atan2(o.velocity_world.y(), o.velocity_world.x()) : 0.0;
        scene_.set_intruder(o.id, now.position_world, yaw);
        truth.objects.push_back(now);
      }
    }
    scene_.hide_unplaced_intruders();

    cv::Mat left, right;
    renderer_.render(scene_.scene(), camera, left, right);
    msg::StereoFrame frame;
    frame.stamp = stamp;
    frame.frame_index = frames_++;
    frame.left = finish_image(left, ctx.rng());
    frame.right = finish_image(right, ctx.rng());
    frame.calibration = calibration_;
    ctx.publish(kTruth, std::move(truth));
    ctx.publish(kFrame, std::move(frame));
  }

 private:
  static SceneOptions scene_options(NodeInit& init) {
    SceneOptions o;
    o.clutter_count = static_cast<int>(init.param<std::int64_t>("clutter_count"));
    o.clutter_min_range_m = init.param<double>("clutter_min_range_m");
    o.clutter_max_range_m = std::max(init.param<double>("clutter_max_range_m"), o.clutter_min_range_m);
    o.seed = static_cast<std::uint64_t>(init.param<std::int64_t>("scene_seed"));
    return o;
  }

  static msg::StereoCalibration calibration(NodeInit& init) {
    msg::StereoCalibration c;
    c.width = init.param<int>("width");
    c.height = init.param<int>("height");
    c.fx = c.fy = focal_from_hfov(c.width, init.param<double>("hfov_deg"));
    c.cx = (c.width - 1) / 2.0;
    c.cy = (c.height - 1) / 2.0;
    c.baseline_m = init.param<double>("baseline_m");
    return c;
  }

  geometry::CameraPose camera_pose(Context& ctx) const {
    const auto pose = ctx.get(kPose);
    if (!pose) return fixed_camera_;
    return geometry::camera_on_body(pose->position, pose->orientation, offset_);
  }

  bool in_view(const Eigen::Vector3d& p) const {
    if (p.z() < min_depth_ || p.z() > max_depth_) return false;
    const double u = calibration_.fx * p.x() / p.z() + calibration_.cx;
    const double v = calibration_.fy * p.y() / p.z() + calibration_.cy;
    return u >= 0 && u < calibration_.width && v >= 0 && v < calibration_.height;
  }

  // Grey (unless colour was asked for), plus sensor noise from the node's seeded generator.
  cv::Mat finish_image(const cv::Mat& bgr, std::mt19937_64& rng) const {
    cv::Mat image;
    if (color_)
      image = bgr;
    else
      cv::cvtColor(bgr, image, cv::COLOR_BGR2GRAY);
    if (noise_sigma_ <= 0) return image;
    std::normal_distribution<float> noise(0.f, static_cast<float>(noise_sigma_));
    cv::Mat noisy(image.size(), image.type());
    const int channels = image.channels();
    for (int y = 0; y < image.rows; ++y) {
      const uchar* in = image.ptr<uchar>(y);
      uchar* out = noisy.ptr<uchar>(y);
      for (int x = 0; x < image.cols * channels; ++x) out[x] = cv::saturate_cast<uchar>(in[x] + noise(rng));
    }
    return noisy;
  }

  double noise_sigma_;
  bool color_;
  double min_depth_, max_depth_;
  geometry::CameraPose fixed_camera_;
  Eigen::Vector3d offset_;
  WorldScene scene_;
  StereoRenderer renderer_;
  msg::StereoCalibration calibration_;
  std::uint64_t frames_ = 0;
};
KESTREL_REGISTER_NODE(SimStereo)

}  // namespace kestrel::sim
