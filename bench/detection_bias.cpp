// Where each detection's error comes from: a budget of the chain's bias and spread, part by
// part, on rendered frames of the paper's figure-8 (92.8 deg, the drone turned along its path).
//
// For every frame the renderer's depth buffer gives the truth of every pixel: the drone's own
// pixels (its silhouette) and their exact disparities. Three placements then differ by one
// cause each:
//   ideal   the silhouette's centroid at the mean of its true disparities: what a perfect
//           stereo chain would report. ideal - centre is the target itself: the visible
//           surface against the body's centre.
//   mask    the chain's disparity at the silhouette's true centroid: mask - ideal is the
//           disparity's error (noise, bleeding of the background into the match, locking).
//   chain   the chain's disparity at its own mask's centroid: chain - mask is the mask's
//           error (silhouette bleeding shifts the centroid).
// and, for the paper's unrefined chain, the clusters' centroids (voxel quantization and the
// mean of depths taken in depth, not disparity).
//
// Usage: kestrel_detection_bias [--frames N] [--downscale K] [--supersample K] [--background-ratio R]
//                               [--dump DIR] [--markdown FILE] [--json FILE]
// --dump writes a few frames' masks as PNG (masks_DIST_FRAME.png).
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "clustering.hpp"
#include "kestrel/camera_rig/camera_rig.hpp"
#include "kestrel/evaluation/body_axes.hpp"
#include "kestrel/geometry/pinhole.hpp"
#include "object_disparity.hpp"
#include "sensor_noise.hpp"
#include "stereo_matching.hpp"
#include "stereo_renderer.hpp"
#include "trajectory.hpp"
#include "voxel_grid.hpp"
#include "world_scene.hpp"

namespace {

using namespace kestrel;

// Mean and root mean square of a stream of 3D errors (camera frame).
struct Spread {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum_sq = Eigen::Vector3d::Zero();
  int n = 0;
  void add(const Eigen::Vector3d& e) {
    sum += e;
    sum_sq += e.cwiseProduct(e);
    ++n;
  }
  Eigen::Vector3d mean() const { return n ? Eigen::Vector3d(sum / n) : Eigen::Vector3d::Zero(); }
  Eigen::Vector3d rms() const { return n ? Eigen::Vector3d((sum_sq / n).cwiseSqrt()) : Eigen::Vector3d::Zero(); }
};

struct Budget {
  Spread target, disparity, mask, refined, unrefined;
  int frames = 0, found = 0;
};

// The depth buffer's reading against the true depth. MRPT's linearisation of the buffer is off
// by a few per cent (5.36 m read for 5.52 m), so the truth is recovered from the ground plane in
// view: at row v below the horizon, a camera h above it sees depth h * fy / (v - cy).
class DepthTruth {
 public:
  DepthTruth(const cv::Mat& empty_depth, const msg::StereoCalibration& c, double camera_height) {
    for (int v = c.height - 1; v > c.cy + 1; --v) {
      const double truth = camera_height * c.fy / (v - c.cy);
      const double read = empty_depth.at<float>(v, c.width / 2);
      if (truth > 40.0) break;
      if (read_.empty() || read > read_.back()) read_.push_back(read), truth_.push_back(truth);
    }
  }
  double operator()(double read) const {
    const auto it = std::lower_bound(read_.begin(), read_.end(), read);
    if (it == read_.begin() || it == read_.end()) return read;
    const std::size_t k = static_cast<std::size_t>(it - read_.begin());
    const double w = (read - read_[k - 1]) / (read_[k] - read_[k - 1]);
    return truth_[k - 1] + w * (truth_[k] - truth_[k - 1]);
  }

 private:
  std::vector<double> read_, truth_;
};

// The left image around the drone, 6 times enlarged: the true silhouette's outline in green,
// the chain's mask in red, both centroids as dots.
cv::Mat draw_masks(const cv::Mat& left, const cv::Mat& truth, const refine::ObjectMask& mask, cv::Point2d true_c,
                   cv::Point2d chain_c) {
  constexpr int k = 6;
  const cv::Rect box = (mask.roi + cv::Size(16, 16) - cv::Point(8, 8)) & cv::Rect(0, 0, left.cols, left.rows);
  cv::Mat grey, out;
  cv::resize(left(box), grey, {}, k, k, cv::INTER_NEAREST);
  cv::cvtColor(grey, out, cv::COLOR_GRAY2BGR);
  const auto overlay = [&](const cv::Mat& full, const cv::Scalar& colour) {
    cv::Mat big;
    cv::resize(full(box), big, {}, k, k, cv::INTER_NEAREST);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(big, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
    cv::drawContours(out, contours, -1, colour, 1);
  };
  cv::Mat full_mask = cv::Mat::zeros(left.size(), CV_8U);
  mask.pixels.copyTo(full_mask(mask.roi));
  overlay(truth, {0, 200, 0});
  overlay(full_mask, {0, 0, 255});
  const auto dot = [&](cv::Point2d p, const cv::Scalar& colour) {
    cv::circle(out, cv::Point2d((p.x - box.x + 0.5) * k, (p.y - box.y + 0.5) * k), 4, colour, cv::FILLED);
  };
  dot(true_c, {0, 200, 0});
  dot(chain_c, {0, 0, 255});
  return out;
}

Budget measure(double distance, int frames, int downscale, int supersample, const refine::BackgroundOptions& background,
               const std::string& dump_dir) {
  sensors::CameraRigConfig rig;  // the paper's camera, 2 m up, looking along world x
  rig.hfov_deg = 92.8;
  const msg::StereoCalibration c = rig.calibration();
  sim::SceneOptions scene;
  scene.clutter_count = 0;
  sim::WorldScene world(scene);
  sim::StereoRenderer renderer(c, supersample);
  stereo::MatcherOptions matcher_options;
  matcher_options.num_disparities = std::max(16, (80 / downscale + 15) / 16 * 16);
  matcher_options.speckle_window_size /= downscale * downscale;
  const auto matcher = stereo::make_matcher(matcher_options);
  const auto camera = rig.pose(nullptr);
  const intruder::FigureEight path(camera, distance, 1.0, 0.5, 12.0);
  sim::SensorNoise camera_noise(1.5, false);  // sim_stereo's defaults
  std::uint64_t noise_seed = 1;
  world.hide_unplaced_intruders();
  const DepthTruth depth_truth(renderer.render_depth(world.scene(), camera), c, 2.0);
  Budget b;
  for (int i = 0; i < frames; ++i) {
    const auto state = path.at(12.0 * i / frames);
    const double yaw = state.velocity.head<2>().norm() > 0.1 ? std::atan2(state.velocity.y(), state.velocity.x()) : 0.0;
    world.set_intruder(1, state.position, yaw);
    const Eigen::Vector3d centre = camera.to_camera(state.position);
    cv::Mat left_bgr, right_bgr;
    renderer.render(world.scene(), camera, left_bgr, right_bgr);
    const cv::Mat depth = renderer.render_depth(world.scene(), camera);
    ++b.frames;

    // The drone's true pixels: near its centre in depth, inside a box around its projection.
    double su = 0, sv = 0, sd = 0;
    int n = 0;
    cv::Mat truth_mask = cv::Mat::zeros(depth.size(), CV_8U);
    const double reach_px = c.fx * 0.7 / centre.z();
    const double pu = c.cx + c.fx * centre.x() / centre.z(), pv = c.cy + c.fy * centre.y() / centre.z();
    for (int v = std::max(0, int(pv - reach_px)); v < std::min(c.height, int(pv + reach_px)); ++v)
      for (int u = std::max(0, int(pu - reach_px)); u < std::min(c.width, int(pu + reach_px)); ++u) {
        const double z = depth_truth(depth.at<float>(v, u));
        if (std::abs(z - centre.z()) > 0.6) continue;
        su += u, sv += v, sd += c.fx * c.baseline_m / z, ++n;
        truth_mask.at<std::uint8_t>(v, u) = 255;
      }
    if (n < 10) continue;
    const double true_u = su / n, true_v = sv / n, true_d = sd / n;
    const Eigen::Vector3d ideal = geometry::from_pixel_disparity(c, {true_u, true_v, true_d});

    // The chain: noisy grey pair, SGBM (at the downscale), voxels, clusters (the one nearest the
    // drone, within 2 m: coarse depth can be a metre out before refinement), the object's mask
    // and its matched disparity at full resolution.
    const cv::Mat left = camera_noise.apply(left_bgr, noise_seed++),
                  right = camera_noise.apply(right_bgr, noise_seed++);
    const auto pair = stereo::downscale(left, right, c, downscale);
    const auto cloud =
        stereo::reproject(stereo::compute_disparity(*matcher, pair.left, pair.right), pair.calibration, 0.5, 15.0);
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr thin = voxel::downsample(*cloud, {});
    const auto clusters = clustering::find_clusters(thin, {});
    const msg::Detection* best = nullptr;
    for (const auto& d : clusters.detections)
      if ((d.position - centre).norm() < 2.0 &&
          (!best || (d.position - centre).norm() < (best->position - centre).norm()))
        best = &d;
    if (!best) continue;
    auto mask = refine::object_mask(*cloud, c, best->position, 0.5 * best->extent, 0.05, 0, 20, downscale);
    if (!mask) continue;
    cv::Mat lf, rf;
    left.convertTo(lf, CV_32F);
    right.convertTo(rf, CV_32F);
    if (background.ratio > 0) refine::drop_background(lf, rf, *mask, background);
    const auto disparity = refine::match_disparity(lf, rf, *mask, {});
    if (!disparity) continue;
    ++b.found;
    const Eigen::Vector3d chain = refine::place(c, *mask, *disparity);
    if (!dump_dir.empty() && i % std::max(1, frames / 4) == 0) {
      const cv::Point2d chain_c(c.cx + c.fx * chain.x() / chain.z(), c.cy + c.fy * chain.y() / chain.z());
      cv::imwrite(fmt::format("{}/masks_{:.1f}m_{:02d}.png", dump_dir, distance, i),
                  draw_masks(left, truth_mask, *mask, {true_u, true_v}, chain_c));
    }
    const Eigen::Vector3d at_true_centroid = geometry::from_pixel_disparity(c, {true_u, true_v, *disparity});
    b.target.add(ideal - centre);
    b.disparity.add(at_true_centroid - ideal);
    b.mask.add(chain - at_true_centroid);
    b.refined.add(chain - centre);
    b.unrefined.add(best->position - centre);
  }
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 48, downscale = 1, supersample = 1;
  refine::BackgroundOptions background;
  std::string dump_dir;
  std::string markdown_path, json_path;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--frames")
      frames = std::stoi(value);
    else if (flag == "--downscale")
      downscale = std::stoi(value);
    else if (flag == "--supersample")
      supersample = std::stoi(value);
    else if (flag == "--background-ratio")
      background.ratio = std::stod(value);
    else if (flag == "--background-radius")
      background.radius_px = std::stoi(value);
    else if (flag == "--dump")
      dump_dir = value;
    else if (flag == "--markdown")
      markdown_path = value;
    else if (flag == "--json")
      json_path = value;
    else {
      std::cerr
          << "usage: kestrel_detection_bias [--frames N] [--downscale K] [--supersample K] [--background-ratio R] "
             "[--dump DIR] [--markdown FILE] [--json FILE]\n";
      return 2;
    }
  }
  nlohmann::json out = {
      {"frames_per_distance", frames}, {"downscale", downscale}, {"distances", nlohmann::json::array()}};
  std::string md = fmt::format(
      "# Where the detection error comes from\n\n{} rendered frames per distance, the paper's figure-8 at 92.8 deg, "
      "matched {}. Body axes (X forward = depth, Y left, Z up), metres: mean (bias) and RMS.\n\n"
      "| distance | part | bias X | bias Y | bias Z | RMS X | RMS Y | RMS Z "
      "|\n|---:|---|---:|---:|---:|---:|---:|---:|\n",
      frames, downscale == 1 ? "at full resolution" : fmt::format("at 1/{} resolution", downscale));
  for (const double distance : {2.5, 5.0, 7.5}) {
    const Budget b = measure(distance, frames, downscale, supersample, background, dump_dir);
    nlohmann::json row = {{"distance_m", distance}, {"frames", b.frames}, {"found", b.found}};
    const std::pair<const char*, const Spread*> parts[] = {{"target: visible surface - centre", &b.target},
                                                           {"disparity: chain's - true", &b.disparity},
                                                           {"mask: chain's centroid - silhouette's", &b.mask},
                                                           {"refined detection - centre", &b.refined},
                                                           {"unrefined cluster centroid - centre", &b.unrefined}};
    for (const auto& [name, s] : parts) {
      const Eigen::Vector3d m = evaluation::bias_in_body_axes(s->mean());
      const Eigen::Vector3d r = evaluation::rms_in_body_axes(s->rms());
      md += fmt::format("| {:.1f} | {} | {:+.3f} | {:+.3f} | {:+.3f} | {:.3f} | {:.3f} | {:.3f} |\n", distance, name,
                        m.x(), m.y(), m.z(), r.x(), r.y(), r.z());
      row[name] = {{"bias_body_m", evaluation::axes_or_null(m)}, {"rms_body_m", evaluation::axes_or_null(r)}};
    }
    out["distances"].push_back(row);
    std::cerr << distance << " m: " << b.found << " of " << b.frames << " frames measured\n";
  }
  std::cout << md;
  if (!markdown_path.empty()) std::ofstream(markdown_path) << md;
  if (!json_path.empty()) std::ofstream(json_path) << out.dump(2) << "\n";
  return 0;
}
