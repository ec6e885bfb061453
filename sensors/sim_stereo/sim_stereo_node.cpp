// The `sim_stereo` node: a simulated stereo camera that renders the world with MRPT's off-screen
// EGL renderer. Defaults are the WithRobot oCamS-1CGN-U at 640x480.
#include <algorithm>
#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plugin.hpp>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "kestrel/camera_rig/camera_rig.hpp"
#include "sensor_noise.hpp"
#include "stereo_renderer.hpp"
#include "world_scene.hpp"

namespace kestrel::sim {

// The WithRobot oCamS-1CGN-U at 640x480 (the rig's defaults).
struct SimStereoConfig {
  sensors::CameraRigConfig rig;
  double noise_sigma = 1.5;
  bool color = false;
  std::int64_t supersample = 1;
  SceneOptions scene;
  std::string mount_frame = "hunter";
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
    sensors::declare_camera_rig(c, &C::rig);
    c.param("noise_sigma", &C::noise_sigma).range(0.0, 50.0).with_unit("grey levels").describe("Gaussian image noise");
    c.param("color", &C::color).describe("publish BGR images instead of 8-bit grey");
    c.param("mount_frame", &C::mount_frame)
        .describe(
            "frame of the vehicle carrying the camera, when `pose` is connected: the id of the node publishing its "
            "state, which names its /tf frame in recordings and the live view");
    c.param("supersample", &C::supersample)
        .range(1, 4)
        .describe(
            "render k x k samples per pixel and average them, as a sensor integrates light over a pixel: edges then "
            "fall between pixels instead of on whole ones (2: about twice the render time)");
    c.param("clutter_count", &C::scene, &SceneOptions::clutter_count)
        .range(0, 500)
        .describe("trees and buildings in the background");
    c.choice("clutter_layout", &C::scene, &SceneOptions::clutter_layout,
             {{"scattered", ClutterLayout::scattered}, {"band", ClutterLayout::band}})
        .describe(
            "scattered: between clutter_min_range_m and clutter_max_range_m of the world origin, where it can hide an "
            "intruder; band: between clutter_band_near_m and clutter_band_far_m in front of the camera, across its "
            "view, so an intruder nearer than the band is seen against it and never hidden");
    c.param("clutter_tree_fraction", &C::scene, &SceneOptions::clutter_tree_fraction)
        .range(0.0, 1.0)
        .describe("share of the clutter that is trees (trunk and canopy); the rest are buildings");
    c.param("clutter_min_range_m", &C::scene, &SceneOptions::clutter_min_range_m)
        .range(0.0, 500.0)
        .with_unit("m")
        .describe("scattered: clutter's nearest distance from the world origin");
    c.param("clutter_max_range_m", &C::scene, &SceneOptions::clutter_max_range_m)
        .range(0.0, 500.0)
        .with_unit("m")
        .describe("scattered: clutter's farthest distance");
    c.param("clutter_band_near_m", &C::scene, &SceneOptions::clutter_band_near_m)
        .range(0.0, 500.0)
        .with_unit("m")
        .describe("band: nearest depth of the clutter's footprint in front of the camera's fixed pose");
    c.param("clutter_band_far_m", &C::scene, &SceneOptions::clutter_band_far_m)
        .range(0.0, 500.0)
        .with_unit("m")
        .describe("band: farthest depth");
    c.param("scene_seed", &C::scene, &SceneOptions::seed)
        .at_least(0)
        .describe("lays out the world and its textures; the run seed drives the noise");
    c.rule("clutter_min_range_m <= clutter_max_range_m", {"clutter_min_range_m", "clutter_max_range_m"},
           [](const C& k) { return k.scene.clutter_min_range_m <= k.scene.clutter_max_range_m; });
    c.rule("clutter_band_near_m <= clutter_band_far_m", {"clutter_band_near_m", "clutter_band_far_m"},
           [](const C& k) { return k.scene.clutter_band_near_m <= k.scene.clutter_band_far_m; });
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
    const auto vehicle = ctx.get(kPose);
    const geometry::CameraPose camera = rig_.pose(vehicle ? &*vehicle : nullptr);
    msg::GroundTruth truth;
    truth.stamp = stamp;
    if (const auto intruders = ctx.get(kIntruders)) {
      truth = rig_.seen(*intruders, stamp, camera);
      if (std::any_of(truth.objects.begin(), truth.objects.end(), [&](const auto& o) { return inside_band(o); }))
        ++frames_inside_band_;
      for (const auto& o : truth.objects) {
        const double yaw =
            o.velocity_world.head<2>().norm() > 0.1 ? std::atan2(o.velocity_world.y(), o.velocity_world.x()) : 0.0;
        scene_.set_intruder(o.id, o.position_world, yaw);
      }
    }
    scene_.hide_unplaced_intruders();

    cv::Mat left, right;
    renderer_.render(scene_.scene(), camera, left, right);
    msg::StereoFrame frame;
    frame.stamp = stamp;
    frame.frame_index = frames_++;
    // Each image's noise seeded from the node's own stream, so lockstep runs reproduce.
    frame.left = noise_.apply(left, ctx.rng()());
    frame.right = noise_.apply(right, ctx.rng()());
    frame.calibration = calibration_;
    frame.mount = rig_.mount(vehicle ? &mount_frame_ : nullptr);
    ctx.publish(kTruth, std::move(truth));
    ctx.publish(kFrame, std::move(frame));
  }

  void finish(Context& ctx) override {
    if (!std::isfinite(band_near_m_)) return;
    // A band meant to stand behind the intruders: say when one flew into or beyond it.
    ctx.set_report_section(
        ctx.id(), ReportSection()
                      .quantity("frames_with_intruder_in_clutter_band", frames_inside_band_)
                      .markdown(fmt::format("Clutter in a band from {:.2f} m: {} frames had an intruder at or beyond "
                                            "its near edge, where clutter can hide it.\n",
                                            band_near_m_, frames_inside_band_)));
    if (frames_inside_band_ > 0)
      ctx.log().warn("{} frames had an intruder at or beyond the clutter band's near edge ({:.2f} m)",
                     frames_inside_band_, band_near_m_);
  }

 private:
  SimStereo(NodeInit& init, const SimStereoConfig& cfg)
      : rig_(cfg.rig),
        mount_frame_(cfg.mount_frame),
        noise_(cfg.noise_sigma, cfg.color),
        scene_(scene_options(cfg)),
        band_near_m_(cfg.scene.clutter_layout == ClutterLayout::band && cfg.scene.clutter_count > 0
                         ? cfg.scene.clutter_band_near_m
                         : std::numeric_limits<double>::infinity()),
        calibration_(rig_.calibration()),
        renderer_(calibration_, static_cast<int>(cfg.supersample)) {
    init.set_rate(rig_.fps);
  }

  // The band is laid out in front of the camera's fixed pose (camera_position_m, camera_yaw_deg).
  static SceneOptions scene_options(const SimStereoConfig& cfg) {
    SceneOptions scene = cfg.scene;
    const msg::StereoCalibration calibration = cfg.rig.calibration();
    scene.band_view.camera_position = cfg.rig.camera_position_m;
    scene.band_view.camera_yaw_rad = cfg.rig.camera_yaw_deg * M_PI / 180.0;
    scene.band_view.half_fov_rad = std::atan2(0.5 * calibration.width, calibration.fx);
    return scene;
  }

  // Depth of an intruder along the fixed camera's axis, against the band's near edge.
  bool inside_band(const msg::GroundTruthObject& o) const {
    const double yaw = rig_.camera_yaw_deg * M_PI / 180.0;
    const Eigen::Vector3d axis(std::cos(yaw), std::sin(yaw), 0.0);
    return o.in_view && (o.position_world - rig_.camera_position_m).dot(axis) >= band_near_m_;
  }

  sensors::CameraRigConfig rig_;
  std::string mount_frame_;
  SensorNoise noise_;
  WorldScene scene_;
  double band_near_m_;
  msg::StereoCalibration calibration_;
  StereoRenderer renderer_;
  std::uint64_t frames_ = 0;
  std::uint64_t frames_inside_band_ = 0;
};
KESTREL_REGISTER_NODE(SimStereo)

}  // namespace kestrel::sim
