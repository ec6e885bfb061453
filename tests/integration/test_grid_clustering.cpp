// The hash-grid clusterer against PCL's EuclideanClusterExtraction: the same clusters, as sets of
// points, on random clouds built to be hard (points a hair either side of the tolerance, dense
// blobs, points on a lattice) and on rendered frames put through the paper's chain.
#include <gmock/gmock.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "clustering.hpp"
#include "grid_clustering.hpp"
#include "kestrel/camera_rig/camera_rig.hpp"
#include "stereo_matching.hpp"
#include "stereo_renderer.hpp"
#include "trajectory.hpp"
#include "voxel_grid.hpp"
#include "world_scene.hpp"

using namespace kestrel;

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using ClusterSets = std::vector<std::vector<int>>;

ClusterSets as_sets(std::vector<std::vector<int>> clusters) {
  for (auto& c : clusters) std::sort(c.begin(), c.end());
  std::sort(clusters.begin(), clusters.end());
  return clusters;
}

ClusterSets clusters_by(clustering::ClusterOptions::Method method, const Cloud::ConstPtr& cloud,
                        clustering::ClusterOptions options) {
  options.method = method;
  return as_sets(clustering::find_clusters(cloud, options).indices);
}

// Blobs of every size and spread, a sprinkling of lone points, a lattice at the voxel pitch,
// and chains of points spaced just under and just over the tolerance.
Cloud::Ptr random_cloud(std::uint32_t seed, double tolerance) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  auto cloud = std::make_shared<Cloud>();
  const int blobs = 1 + static_cast<int>(rng() % 12);
  for (int b = 0; b < blobs; ++b) {
    const Eigen::Vector3f centre(8 * unit(rng) - 4, 4 * unit(rng) - 2, 1 + 9 * unit(rng));
    std::normal_distribution<float> spread(0.0f, 0.02f + 0.4f * unit(rng));
    const int n = 1 + static_cast<int>(rng() % 400);
    for (int i = 0; i < n; ++i)
      cloud->push_back({centre.x() + spread(rng), centre.y() + spread(rng), centre.z() + spread(rng)});
  }
  for (int i = 0, n = static_cast<int>(rng() % 300); i < n; ++i)
    cloud->push_back({10 * unit(rng) - 5, 6 * unit(rng) - 3, 10 * unit(rng)});
  const float pitch = 0.1f;
  for (int i = 0, n = static_cast<int>(rng() % 200); i < n; ++i)
    cloud->push_back({pitch * static_cast<float>(rng() % 40), pitch * static_cast<float>(rng() % 20),
                      5.0f + pitch * static_cast<float>(rng() % 5)});
  for (int chain = 0; chain < 4; ++chain) {
    const float step = static_cast<float>(tolerance) * (chain % 2 ? 1.0f + 1e-6f : 1.0f - 1e-6f);
    const Eigen::Vector3f start(8 * unit(rng) - 4, 4 * unit(rng) - 2, 1 + 9 * unit(rng));
    Eigen::Vector3f direction(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f);
    direction.normalize();
    for (int i = 0; i < 30; ++i) {
      const Eigen::Vector3f p = start + direction * step * static_cast<float>(i);
      cloud->push_back({p.x(), p.y(), p.z()});
    }
  }
  std::shuffle(cloud->begin(), cloud->end(), rng);
  cloud->width = static_cast<std::uint32_t>(cloud->size());
  cloud->height = 1;
  return cloud;
}

}  // namespace

TEST(GridClustering, SameClustersAsPclOnRandomClouds) {
  std::mt19937 rng(7);
  int compared = 0, with_clusters = 0;
  for (std::uint32_t seed = 0; seed < 120; ++seed) {
    clustering::ClusterOptions options;
    options.tolerance_m = std::vector<double>{0.5, 0.5, 0.2, 0.05, 1.3}[seed % 5];
    options.min_points = 1 + static_cast<int>(rng() % 30);
    options.max_points = options.min_points + static_cast<int>(rng() % 500);
    const Cloud::ConstPtr cloud = random_cloud(seed, options.tolerance_m);
    const ClusterSets pcl = clusters_by(clustering::ClusterOptions::Method::pcl, cloud, options);
    const ClusterSets grid = clusters_by(clustering::ClusterOptions::Method::grid, cloud, options);
    ASSERT_EQ(grid, pcl) << "seed " << seed << ", tolerance " << options.tolerance_m << ", " << cloud->size()
                         << " points";
    ++compared;
    with_clusters += !pcl.empty();
  }
  EXPECT_EQ(compared, 120);
  EXPECT_GT(with_clusters, 100);  // the comparison is not between empty answers
}

TEST(GridClustering, SameClustersAsPclOnRenderedFrames) {
  // The paper's chain on rendered frames: SGBM, the 0.1 m voxel grid, then both clusterers,
  // with the clutter of trees and poles in view.
  sensors::CameraRigConfig rig;  // the paper's camera, 2 m up, looking along world x
  rig.hfov_deg = 92.8;
  const msg::StereoCalibration calibration = rig.calibration();
  sim::SceneOptions scene;
  scene.clutter_count = 30;
  sim::WorldScene world(scene);
  sim::StereoRenderer renderer(calibration);
  stereo::MatcherOptions matcher_options;
  matcher_options.num_disparities = 80;
  const auto matcher = stereo::make_matcher(matcher_options);
  const auto camera = rig.pose(nullptr);
  int frames = 0, paper_clusters = 0, all_clusters = 0;
  for (const double distance : {2.5, 5.0, 7.5}) {
    const intruder::FigureEight path(camera, distance, 1.0, 0.5, 12.0);
    for (int i = 0; i < 8; ++i) {
      world.set_intruder(1, path.at(i * 1.5).position, 0.0);
      cv::Mat left, right;
      renderer.render(world.scene(), camera, left, right);
      const auto cloud = stereo::reproject(stereo::compute_disparity(*matcher, left, right), calibration, 0.5, 15.0);
      const Cloud::ConstPtr thin = voxel::downsample(*cloud, {});
      for (const auto& options :
           {clustering::ClusterOptions{}, clustering::ClusterOptions{{}, 0.5, 1, 1000000}}) {  // paper; all
        const ClusterSets pcl = clusters_by(clustering::ClusterOptions::Method::pcl, thin, options);
        ASSERT_EQ(clusters_by(clustering::ClusterOptions::Method::grid, thin, options), pcl)
            << distance << " m, frame " << i << ", " << thin->size() << " points";
        (options.max_points == 200 ? paper_clusters : all_clusters) += static_cast<int>(pcl.size());
      }
      ++frames;
    }
  }
  EXPECT_EQ(frames, 24);
  // Not a comparison of empty answers: the drone is found, and the ground and trees make many.
  EXPECT_GT(paper_clusters, 0);
  EXPECT_GT(all_clusters, frames);
}

TEST(GridClustering, CellsAndLoneFarPointsAreHandled) {
  Cloud cloud;
  // Two points in one cell, a third just out of reach, and points no grid cell holds.
  cloud.push_back({0.0f, 0.0f, 0.0f});
  cloud.push_back({0.2f, 0.2f, 0.2f});
  cloud.push_back({0.2f + 0.5f, 0.2f, 0.2f});
  cloud.push_back({std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f});
  cloud.push_back({1e12f, 0.0f, 0.0f});
  const auto clusters = clustering::grid_clusters(cloud, 0.5, 1, 100);
  EXPECT_EQ(clusters, (std::vector<std::vector<int>>{{0, 1}, {2}, {3}, {4}}));
  EXPECT_TRUE(clustering::grid_clusters(cloud, 0.5, 2, 2).size() == 1);
}
