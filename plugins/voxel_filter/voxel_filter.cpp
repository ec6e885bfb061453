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
    return NodeSpec("voxel_filter", "Depth pass-through then voxel-grid down-sampling (PCL)")
        .details(
            "Points whose camera z lies outside [min_depth_m, max_depth_m] are dropped (PCL PassThrough); the "
            "rest are replaced by the centroid of each occupied voxel (PCL VoxelGrid).")
        .input(kCloud, "camera-frame points")
        .output(kFiltered, "one point per occupied voxel")
        .param(param("leaf_size_m", 0.1).range(0.001, 10.0).with_unit("m").describe("voxel edge (paper: 0.1 m)"))
        .param(param("max_depth_m", 10.0)
                   .range(0.0, 1000.0)
                   .with_unit("m")
                   .describe("farthest camera z kept (paper: 10 m)"))
        .param(param("min_depth_m", 0.0).range(0.0, 1000.0).with_unit("m").describe("nearest camera z kept"))
        .param(param("min_points_per_voxel", 1).range(1, 100000).describe("voxels with fewer points are dropped"));
  }

  explicit VoxelFilter(NodeInit& init) {
    options_.leaf_size_m = init.param<double>("leaf_size_m");
    options_.max_z_m = init.param<double>("max_depth_m");
    options_.min_z_m = init.param<double>("min_depth_m");
    options_.min_points_per_voxel = init.param<int>("min_points_per_voxel");
    if (options_.min_z_m >= options_.max_z_m) throw Error("min_depth_m must be below max_depth_m");
  }

  void process(Context& ctx) override {
    const auto in = ctx.get(kCloud);
    if (!in->points) throw Error("point cloud message without points");
    msg::PointCloud out;
    out.stamp = in->stamp;
    out.frame = in->frame;
    out.points = downsample(*in->points, options_);
    ctx.publish(kFiltered, std::move(out));
  }

 private:
  VoxelOptions options_;
};
KESTREL_REGISTER_NODE(VoxelFilter)

}  // namespace kestrel::voxel
