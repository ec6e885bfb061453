// The `euclidean_clusterer` node: Euclidean cluster extraction as PCL does it; the centroid of
// every cluster with 20 to 200 points is a detection (paper, section 2.2).
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/plot/line_plot.hpp>
#include <kestrel/plugin.hpp>

#include "clustering.hpp"

namespace kestrel::clustering {

class EuclideanClusterer final : public Node {
 public:
  static constexpr Input<msg::PointCloud> kCloud{"cloud"};
  static constexpr Output<msg::Detections> kDetections{"detections"};

  struct Config {
    ClusterOptions clusters;  // the paper's 0.5 m, 20 and 200 points
    std::int64_t snapshot_frame = 30;
  };

  static NodeSpec spec() {
    ConfigSpec<Config> c;
    c.choice("method", &Config::clusters, &ClusterOptions::method,
             {{"grid", ClusterOptions::Method::grid}, {"pcl", ClusterOptions::Method::pcl}})
        .describe(
            "grid: a hash grid, the same clusters as PCL's in a fraction of the time; pcl: PCL's "
            "EuclideanClusterExtraction on a kd-tree");
    c.param("tolerance_m", &Config::clusters, &ClusterOptions::tolerance_m)
        .range(0.001, 100.0)
        .with_unit("m")
        .describe("cluster distance (paper: 0.5 m)");
    c.param("min_points", &Config::clusters, &ClusterOptions::min_points)
        .range(1, 10000000)
        .describe("smallest cluster kept (paper: 20)");
    c.param("max_points", &Config::clusters, &ClusterOptions::max_points)
        .range(1, 10000000)
        .describe("largest cluster kept (paper: 200)");
    c.param("depth_noise_px", &Config::clusters, &ClusterOptions::depth_noise_px)
        .range(0.0, 16.0)
        .with_unit("px")
        .describe(
            "stereo's disparity noise between neighbours: along the depth axis the tolerance widens to tolerance_m "
            "+ z^2 * depth_noise_px / (fx * b) at depth z, so that a far object whose points spread in depth stays "
            "one cluster; needs a stereo cloud; 0: the same tolerance everywhere (paper)");
    c.param("snapshot_frame", &Config::snapshot_frame)
        .at_least(-1)
        .describe("cloud index drawn as clusters.png with --report; -1 = none");
    c.rule("min_points <= max_points", {"min_points", "max_points"},
           [](const Config& k) { return k.clusters.min_points <= k.clusters.max_points; });
    return NodeSpec("euclidean_clusterer",
                    "Euclidean clusters (as PCL finds them); each cluster's centroid is a detection")
        .details(
            "Points closer than tolerance_m join one cluster. Clusters with fewer than min_points or more than "
            "max_points points are dropped: they are unlikely to be a drone (paper: 0.5 m, 20, 200). Beyond "
            "the paper's range, depth_noise_px widens the tolerance along the depth axis as stereo's depth error "
            "grows (z^2). With "
            "--report, frame `snapshot_frame` is drawn as clusters.png (front and top views).")
        .input(kCloud, "filtered camera-frame points")
        .output(kDetections, "cluster centroids with point count and extent")
        .config(std::move(c));
  }

  explicit EuclideanClusterer(NodeInit& init) : cfg_(init.config<Config>()) {}

  void process(Context& ctx) override {
    const auto in = ctx.get(kCloud);
    if (!in->points) throw Error("point cloud message without points");
    const Clusters clusters = find_clusters(in->points, cfg_.clusters, in->focal_baseline_px_m);
    if (clouds_++ == cfg_.snapshot_frame && ctx.keeps_artifacts())
      ctx.add_artifact("clusters.png", draw(*in->points, clusters), "filtered cloud and its clusters");
    msg::Detections out;
    out.stamp = in->stamp;
    out.frame = in->frame;
    out.items = clusters.detections;
    ctx.publish(kDetections, std::move(out));
  }

 private:
  // Front (x, y) and top (x, z) views: all points grey, kept clusters in colour, centroids ringed.
  static std::string draw(const pcl::PointCloud<pcl::PointXYZ>& cloud, const Clusters& c) {
    plot::Panel front{"filtered cloud, front view (camera frame)", "x [m]", "-y [m] (up)", {}};
    plot::Panel top{"filtered cloud, top view", "x [m]", "z [m] (depth)", {}};
    plot::Series all_front{"all points", {}, {}, plot::Series::Style::points, {170, 170, 170}, 1};
    plot::Series all_top = all_front;
    for (const auto& p : cloud) {
      all_front.x.push_back(p.x);
      all_front.y.push_back(-p.y);
      all_top.x.push_back(p.x);
      all_top.y.push_back(p.z);
    }
    front.series.push_back(all_front);
    top.series.push_back(all_top);
    for (std::size_t k = 0; k < c.indices.size(); ++k) {
      plot::Series f{"cluster " + std::to_string(k + 1) + " (" + std::to_string(c.indices[k].size()) + " pts)",
                     {},
                     {},
                     plot::Series::Style::points,
                     plot::palette(k + 1),
                     2};
      plot::Series t = f;
      for (int i : c.indices[k]) {
        const auto& p = cloud[static_cast<std::size_t>(i)];
        f.x.push_back(p.x);
        f.y.push_back(-p.y);
        t.x.push_back(p.x);
        t.y.push_back(p.z);
      }
      front.series.push_back(f);
      top.series.push_back(t);
    }
    return plot::render_png({front, top}, 1000, 420);
  }

  Config cfg_;
  std::int64_t clouds_ = 0;
};
KESTREL_REGISTER_NODE(EuclideanClusterer)

}  // namespace kestrel::clustering
