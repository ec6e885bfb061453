// Time of each stage of the paper's detection chain at 640x480 on rendered frames (rendering
// itself excluded), the whole chain's frame rate, and OpenCV SGBM alone on the same frames.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "clustering.hpp"
#include "depth_pipeline.hpp"
#include "stereo_matching.hpp"
#include "stereo_renderer.hpp"
#include "striped_matcher.hpp"
#include "trajectory.hpp"
#include "voxel_grid.hpp"
#include "world_scene.hpp"

namespace {

using namespace kestrel;

struct Frames {
  msg::StereoCalibration calibration;
  std::vector<std::pair<cv::Mat, cv::Mat>> pairs;
};

// Ten frames of the intruder's figure-8 at 5 m, seen by the oCamS (fx 452 px), rendered once.
const Frames& frames() {
  static const Frames f = [] {
    Frames out;
    out.calibration.fx = out.calibration.fy = sim::focal_from_hfov(640, 70.6);
    out.calibration.cx = 319.5;
    out.calibration.cy = 239.5;
    sim::SceneOptions options;
    options.clutter_count = 0;
    sim::WorldScene world(options);
    sim::StereoRenderer renderer(out.calibration);
    const auto camera = geometry::level_camera({0, 0, 2}, 0.0);
    const intruder::FigureEight path(camera, 5.0, 1.0, 0.5, 12.0);
    for (int i = 0; i < 10; ++i) {
      world.set_intruder(1, path.at(i * 0.4).position, 0.0);
      cv::Mat l, r, lg, rg;
      renderer.render(world.scene(), camera, l, r);
      cv::cvtColor(l, lg, cv::COLOR_BGR2GRAY);
      cv::cvtColor(r, rg, cv::COLOR_BGR2GRAY);
      out.pairs.emplace_back(lg, rg);
    }
    return out;
  }();
  return f;
}

stereo::MatcherOptions matcher_options(int mode) {
  stereo::MatcherOptions o;  // the stereo_depth node's defaults
  if (mode == 1) o.mode = stereo::MatcherOptions::Mode::sgbm_3way;
  if (mode == 2) {
    o.algorithm = stereo::MatcherOptions::Algorithm::bm;
    o.block_size = 15;
  }
  return o;
}

const char* mode_name(int mode) { return mode == 0 ? "sgbm" : mode == 1 ? "sgbm_3way" : "bm"; }

void BM_OpenCvMatcherAlone(benchmark::State& state) {
  const auto matcher = stereo::make_matcher(matcher_options(static_cast<int>(state.range(0))));
  frames();  // rendered before timing: the first benchmark to run must not count the renderer's start
  std::size_t i = 0;
  cv::Mat disparity;
  for (auto _ : state) {
    const auto& [l, r] = frames().pairs[i++ % frames().pairs.size()];
    matcher->compute(l, r, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
  state.SetLabel(mode_name(static_cast<int>(state.range(0))));
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_OpenCvMatcherAlone)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

// SGBM's 5-path mode matched as 1, 2 or 4 strips in parallel (stereo_depth's `strips`; 2 by
// default), with the node's 48 rows of overlap.
void BM_StripedSgbm(benchmark::State& state) {
  stereo::StripedMatcher matcher(matcher_options(0), static_cast<int>(state.range(0)), 48);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [l, r] = frames().pairs[i++ % frames().pairs.size()];
    const cv::Mat disparity = matcher.compute(l, r);
    benchmark::DoNotOptimize(disparity.data);
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StripedSgbm)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StereoDepthStage(benchmark::State& state) {
  const auto matcher = stereo::make_matcher(matcher_options(static_cast<int>(state.range(0))));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [l, r] = frames().pairs[i++ % frames().pairs.size()];
    const auto cloud = stereo::reproject(stereo::compute_disparity(*matcher, l, r), frames().calibration, 0.5, 15.0);
    benchmark::DoNotOptimize(cloud->size());
  }
  state.SetLabel(mode_name(static_cast<int>(state.range(0))));
}
BENCHMARK(BM_StereoDepthStage)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

// stereo_depth's foreground segmentation (the paper graph's settings) on the frames' disparities.
void BM_ForegroundMask(benchmark::State& state) {
  static const auto disparities = [] {
    const auto matcher = stereo::make_matcher(matcher_options(0));
    std::vector<cv::Mat> out;
    for (const auto& [l, r] : frames().pairs) out.push_back(stereo::compute_disparity(*matcher, l, r));
    return out;
  }();
  stereo::ForegroundOptions options;
  options.gap_m = 0.5;
  std::size_t i = 0;
  for (auto _ : state) {
    const cv::Mat mask = stereo::foreground_mask(disparities[i++ % disparities.size()], frames().calibration, options);
    benchmark::DoNotOptimize(mask.data);
  }
}
BENCHMARK(BM_ForegroundMask)->Unit(benchmark::kMillisecond)->UseRealTime();

std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> clouds() {
  const auto matcher = stereo::make_matcher(matcher_options(0));
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> out;
  for (const auto& [l, r] : frames().pairs)
    out.push_back(stereo::reproject(stereo::compute_disparity(*matcher, l, r), frames().calibration, 0.5, 15.0));
  return out;
}

void BM_VoxelFilterStage(benchmark::State& state) {
  static const auto input = clouds();
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const auto& c = input[i++ % input.size()];
    points += c->size();
    benchmark::DoNotOptimize(voxel::downsample(*c, {})->size());
  }
  state.counters["points_in"] = static_cast<double>(points) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_VoxelFilterStage)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ClustererStage(benchmark::State& state) {
  static const auto input = [] {
    std::vector<pcl::PointCloud<pcl::PointXYZ>::ConstPtr> out;
    for (const auto& c : clouds()) out.push_back(voxel::downsample(*c, {}));
    return out;
  }();
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    const auto& c = input[i++ % input.size()];
    points += c->size();
    benchmark::DoNotOptimize(clustering::find_clusters(c, {}).detections.size());
  }
  state.counters["points_in"] = static_cast<double>(points) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ClustererStage)->Unit(benchmark::kMillisecond)->UseRealTime();

// The chain one frame after another on one thread of control (SGBM's own threads aside).
void BM_WholeChain(benchmark::State& state) {
  const auto matcher = stereo::make_matcher(matcher_options(static_cast<int>(state.range(0))));
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [l, r] = frames().pairs[i++ % frames().pairs.size()];
    const auto cloud = stereo::reproject(stereo::compute_disparity(*matcher, l, r), frames().calibration, 0.5, 15.0);
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr thin = voxel::downsample(*cloud, {});
    benchmark::DoNotOptimize(clustering::find_clusters(thin, {}).detections.size());
  }
  state.SetLabel(mode_name(static_cast<int>(state.range(0))));
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WholeChain)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The chain as the paper graph's stereo_depth runs it: SGBM's 5-path mode in 2 strips, the
// foreground segmentation (gap 0.5 m), then the voxel grid and the clusters; at full resolution,
// or matched on half-resolution images (`downscale: 2`, coarse-to-fine; the refiner, which
// measures each object at full resolution afterwards, is not in this loop). Compared in
// scripts/bench with OpenCV's sgbm_3way alone on the same frames.
// The chain as the stereo_depth node runs it (its DepthPipeline: matching in strips and the
// paper graph's foreground segmentation), then voxels and clusters: 0 at full resolution, 1
// coarse-to-fine (matched at half resolution), 2 coarse-to-fine with the regions that stand out
// matched again at full resolution (`fine_regions`).
void BM_NodeChain(benchmark::State& state) {
  const auto variant = static_cast<int>(state.range(0));
  stereo::DepthOptions depth;
  depth.downscale = variant == 0 ? 1 : 2;
  depth.fine_regions = variant == 2;
  stereo::ForegroundOptions paper;
  paper.gap_m = 0.5;
  stereo::DepthPipeline pipeline(matcher_options(0), paper, depth);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [l, r] = frames().pairs[i++ % frames().pairs.size()];
    const auto cloud = pipeline.compute(l, r, frames().calibration).points;
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr thin = voxel::downsample(*cloud, {});
    benchmark::DoNotOptimize(clustering::find_clusters(thin, {}).detections.size());
  }
  state.SetLabel(variant == 0 ? "full resolution" : variant == 1 ? "coarse-to-fine" : "coarse-to-fine, fine regions");
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NodeChain)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The chain with matching on half-resolution images (stereo_depth's `downscale: 2`).
void BM_WholeChainHalfResolution(benchmark::State& state) {
  stereo::MatcherOptions o = matcher_options(0);
  o.num_disparities = 64;  // 112 / 2, rounded up to a multiple of 16
  const auto matcher = stereo::make_matcher(o);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [l, r] = frames().pairs[i++ % frames().pairs.size()];
    const auto half = stereo::downscale(l, r, frames().calibration, 2);
    const auto cloud =
        stereo::reproject(stereo::compute_disparity(*matcher, half.left, half.right), half.calibration, 0.5, 15.0);
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr thin = voxel::downsample(*cloud, {});
    benchmark::DoNotOptimize(clustering::find_clusters(thin, {}).detections.size());
  }
  state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WholeChainHalfResolution)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
