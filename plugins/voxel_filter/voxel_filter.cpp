// The `voxel_filter` node: depth pass-through and voxel-grid down-sampling (PCL), the paper's
// section 2.1 with its values (10 m, 0.1 m) as defaults.
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/plugin.hpp>

#include "voxel_grid.hpp"

namespace kestrel::voxel {

class VoxelFilter final : public Node {
 public:
  static constexpr Input<msg::PointCloud> kCloud{"cloud"};
  static constexpr Output<msg::PointCloud> kFiltered{"filtered"};

  static NodeSpec spec() {
    ConfigSpec<VoxelOptions> c;
    c.param("leaf_size_m", &VoxelOptions::leaf_size_m)
        .range(0.001, 10.0)
        .with_unit("m")
        .describe("voxel edge (paper: 0.1 m)");
    c.param("max_depth_m", &VoxelOptions::max_z_m)
        .range(0.0, 1000.0)
        .with_unit("m")
        .describe("farthest camera z kept (paper: 10 m)");
    c.param("min_depth_m", &VoxelOptions::min_z_m).range(0.0, 1000.0).with_unit("m").describe("nearest camera z kept");
    c.param("min_points_per_voxel", &VoxelOptions::min_points_per_voxel)
        .range(1, 100000)
        .describe("voxels with fewer points are dropped");
    c.rule("min_depth_m < max_depth_m", {"min_depth_m", "max_depth_m"},
           [](const VoxelOptions& k) { return k.min_z_m < k.max_z_m; });
    return NodeSpec("voxel_filter", "Depth pass-through then voxel-grid down-sampling (PCL)")
        .details(
            "Points whose camera z lies outside [min_depth_m, max_depth_m] are dropped (PCL PassThrough); the "
            "rest are replaced by the centroid of each occupied voxel (PCL VoxelGrid).")
        .input(kCloud, "camera-frame points")
        .output(kFiltered, "one point per occupied voxel")
        .config(std::move(c));
  }

  explicit VoxelFilter(NodeInit& init) : options_(init.config<VoxelOptions>()) {}

  void process(Context& ctx) override {
    const auto in = ctx.get(kCloud);
    if (!in->points) throw Error("point cloud message without points");
    msg::PointCloud out;
    out.stamp = in->stamp;
    out.frame = in->frame;
    out.focal_baseline_px_m = in->focal_baseline_px_m;  // voxel centroids keep the stereo's depth noise
    out.points = downsample(*in->points, options_);
    ctx.publish(kFiltered, std::move(out));
  }

 private:
  VoxelOptions options_;
};
KESTREL_REGISTER_NODE(VoxelFilter)

}  // namespace kestrel::voxel
