// The `sim_stereo` node: a simulated stereo camera that renders the world with MRPT's off-screen
// EGL renderer. Defaults are the WithRobot oCamS-1CGN-U at 640x480.
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/geometry/pinhole.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <opencv2/imgproc.hpp>

#include "stereo_renderer.hpp"
#include "world_scene.hpp"

namespace kestrel::sim {

// The WithRobot oCamS-1CGN-U at 640x480.
struct SimStereoConfig {
  int width = 640;
  int height = 480;
  double fps = 30.0;
  double hfov_deg = 70.6;
  double baseline_m = 0.12;
  double min_depth_m = 0.5;
  double max_depth_m = 15.0;
  double noise_sigma = 1.5;
  bool color = false;
  Eigen::Vector3d camera_position_m{0.0, 0.0, 2.0};
  double camera_yaw_deg = 0.0;
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};
  SceneOptions scene;
};

class SimStereo final : public Node {
 public:
  static constexpr Input<msg::GroundTruth> kIntruders{"intruders"};
  static constexpr Input<msg::VehicleState> kPose{"pose"};
  static constexpr Output<msg::StereoFrame> kFrame{"frame"};
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};

  static NodeSpec spec() {
    using C = SimStereoConfig;
    ConfigSpec<C> c;
    c.param("width", &C::width).range(64, 4096).with_unit("px").describe("image width");
    c.param("height", &C::height).range(48, 4096).with_unit("px").describe("image height");
    c.param("fps", &C::fps).range(0.1, 240.0).with_unit("Hz").describe("frame rate");
    c.param("hfov_deg", &C::hfov_deg)
        .range(10.0, 150.0)
        .with_unit("deg")
        .describe(
            "horizontal field of view; 70.6 gives the oCamS's rectified fx = 452 px at 640 px (the paper "
            "states 92.8)");
    c.param("baseline_m", &C::baseline_m).range(0.01, 2.0).with_unit("m").describe("distance between the cameras");
    c.param("min_depth_m", &C::min_depth_m)
        .range(0.05, 100.0)
        .with_unit("m")
        .describe("nearest depth the camera measures");
    c.param("max_depth_m", &C::max_depth_m)
        .range(0.1, 1000.0)
        .with_unit("m")
        .describe("farthest depth the camera measures");
    c.param("noise_sigma", &C::noise_sigma).range(0.0, 50.0).with_unit("grey levels").describe("Gaussian image noise");
    c.param("color", &C::color).describe("publish BGR images instead of 8-bit grey");
    c.param("camera_position_m", &C::camera_position_m)
        .with_unit("m")
        .describe("fixed camera position (world), when `pose` is not connected");
    c.param("camera_yaw_deg", &C::camera_yaw_deg)
        .range(-360.0, 360.0)
        .with_unit("deg")
        .describe("fixed camera heading");
    c.param("camera_offset_m", &C::camera_offset_m)
        .with_unit("m")
        .describe("camera position in the vehicle's body frame, when `pose` is connected");
    c.param("clutter_count", &C::scene, &SceneOptions::clutter_count)
        .range(0, 500)
        .describe("trees and buildings in the background");
    c.param("clutter_min_range_m", &C::scene, &SceneOptions::clutter_min_range_m)
        .range(0.0, 500.0)
        .with_unit("m")
        .describe("clutter's nearest distance from the world origin");
    c.param("clutter_max_range_m", &C::scene, &SceneOptions::clutter_max_range_m)
        .range(0.0, 500.0)
        .with_unit("m")
        .describe("clutter's farthest distance");
    c.param("scene_seed", &C::scene, &SceneOptions::seed)
        .at_least(0)
        .describe("lays out the world and its textures; the run seed drives the noise");
    c.rule("min_depth_m < max_depth_m", {"min_depth_m", "max_depth_m"},
           [](const C& k) { return k.min_depth_m < k.max_depth_m; });
    c.rule("clutter_min_range_m <= clutter_max_range_m", {"clutter_min_range_m", "clutter_max_range_m"},
           [](const C& k) { return k.scene.clutter_min_range_m <= k.scene.clutter_max_range_m; });
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
        .config(std::move(c));
  }

  explicit SimStereo(NodeInit& init) : SimStereo(init, init.config<SimStereoConfig>()) {}

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
  SimStereo(NodeInit& init, const SimStereoConfig& cfg)
      : noise_sigma_(cfg.noise_sigma),
        color_(cfg.color),
        min_depth_(cfg.min_depth_m),
        max_depth_(cfg.max_depth_m),
        fixed_camera_(geometry::level_camera(cfg.camera_position_m, cfg.camera_yaw_deg * M_PI / 180.0)),
        offset_(cfg.camera_offset_m),
        scene_(cfg.scene),
        calibration_(calibration(cfg)),
        renderer_(calibration_) {
    init.set_rate(cfg.fps);
  }

  static msg::StereoCalibration calibration(const SimStereoConfig& cfg) {
    msg::StereoCalibration c;
    c.width = cfg.width;
    c.height = cfg.height;
    c.fx = c.fy = focal_from_hfov(c.width, cfg.hfov_deg);
    c.cx = (c.width - 1) / 2.0;
    c.cy = (c.height - 1) / 2.0;
    c.baseline_m = cfg.baseline_m;
    return c;
  }

  geometry::CameraPose camera_pose(Context& ctx) const {
    const auto pose = ctx.get(kPose);
    if (!pose) return fixed_camera_;
    return geometry::camera_on_body(pose->position, pose->orientation, offset_);
  }

  bool in_view(const Eigen::Vector3d& p) const {
    if (p.z() < min_depth_ || p.z() > max_depth_) return false;
    const Eigen::Vector3d uvd = geometry::to_pixel_disparity(calibration_, p);
    return geometry::in_image(calibration_, uvd.x(), uvd.y());
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
  msg::StereoCalibration calibration_;
  StereoRenderer renderer_;
  std::uint64_t frames_ = 0;
};
KESTREL_REGISTER_NODE(SimStereo)

}  // namespace kestrel::sim
