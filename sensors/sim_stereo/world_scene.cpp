#include "world_scene.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/opengl/CSetOfTexturedTriangles.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <random>

#include "mesh_builder.hpp"
#include "textures.hpp"

namespace kestrel::sim {

namespace {
// Metres over which each clutter texture repeats: its detail keeps the size it has on the ground
// (a texture stretched over a whole canopy blurs to a flat grey that stereo cannot match).
constexpr double kBarkTile = 1.0, kFoliageTile = 2.0, kWallTile = 3.0;

mrpt::opengl::CSetOfTexturedTriangles::Ptr textured(const TextureStyle& style, std::uint64_t seed, int size = 256) {
  auto mesh = mrpt::opengl::CSetOfTexturedTriangles::Create();
  mesh->assignImage(mrpt::img::CImage(make_texture(size, style, seed), mrpt::img::DEEP_COPY));
  mesh->enableTextureLinearInterpolation(true);
  return mesh;
}
}  // namespace

WorldScene::WorldScene(const SceneOptions& options)
    : scene_(mrpt::opengl::COpenGLScene::Create()), drone_shape_(options.drone), seed_(options.seed) {
  auto viewport = scene_->getViewport();
  viewport->setCustomBackgroundColor(mrpt::img::TColorf(0.78f, 0.84f, 0.92f));  // overcast sky: no texture
  viewport->setViewportClipDistances(0.05f, 300.0f);
  auto& light = viewport->lightParameters();
  light.ambient = {0.55f, 0.55f, 0.55f, 1.0f};
  light.diffuse = {0.6f, 0.6f, 0.6f, 1.0f};
  light.direction = {-0.3f, 0.2f, -0.93f};

  // A cloudy sky on a box 250 m away: textured, so stereo matching finds its (near zero)
  // disparity instead of matching sensor noise on a blank background.
  auto sky = textured(sky_style(), seed_ * 7 + 6, 512);
  sky->enableLight(false);
  const double far = 250.0;
  add_box(*sky, {0, 0, far / 2 - 1.0}, {2 * far, 2 * far, far}, Eigen::Matrix3d::Identity(), /*inward=*/true);
  scene_->insert(sky);

  auto ground = textured(grass_style(), seed_ * 7 + 1);
  add_tiled_ground(*ground, options.ground_half_extent_m, 2.0);
  scene_->insert(ground);
  add_clutter(options);
}

void WorldScene::add_clutter(const SceneOptions& options) {
  if (options.clutter_count <= 0) return;
  std::mt19937_64 rng(seed_ * 7 + 2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto trunks = textured(bark_style(), seed_ * 7 + 3, 128);
  auto canopies = textured(foliage_style(), seed_ * 7 + 4);
  auto buildings = textured(concrete_style(), seed_ * 7 + 5);
  for (int i = 0; i < options.clutter_count; ++i) {
    // Two draws place it, once its size is known.
    const double place_a = unit(rng), place_b = unit(rng);
    const Eigen::Matrix3d yaw = Eigen::AngleAxisd(unit(rng) * M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    if (unit(rng) < options.clutter_tree_fraction) {  // a tree: trunk and canopy
      const double height = 3.0 + 4.0 * unit(rng);
      const double width = 1.8 + 2.0 * unit(rng);
      const double radius = width * M_SQRT1_2;
      const Eigen::Vector3d at = clutter_site(options, place_a, place_b, radius);
      add_box(*trunks, at + Eigen::Vector3d(0, 0, height * 0.3), {0.35, 0.35, height * 0.6}, yaw, false, kBarkTile);
      add_box(*canopies, at + Eigen::Vector3d(0, 0, height * 0.7), {width, width, height * 0.6}, yaw, false,
              kFoliageTile);
      clutter_.push_back(at);
      clutter_radii_.push_back(radius);
    } else {  // a building
      const Eigen::Vector3d size(3.0 + 6.0 * unit(rng), 3.0 + 6.0 * unit(rng), 3.0 + 5.0 * unit(rng));
      const double radius = size.head<2>().norm() / 2.0;
      const Eigen::Vector3d at = clutter_site(options, place_a, place_b, radius);
      add_box(*buildings, at + Eigen::Vector3d(0, 0, size.z() / 2), size, yaw, false, kWallTile);
      clutter_.push_back(at);
      clutter_radii_.push_back(radius);
    }
  }
  scene_->insert(trunks);
  scene_->insert(canopies);
  scene_->insert(buildings);
}

Eigen::Vector3d WorldScene::clutter_site(const SceneOptions& options, double a, double b, double radius) {
  if (options.clutter_layout == ClutterLayout::scattered) {
    // As std::uniform_real_distribution maps a and b onto the ranges.
    const double r = a * (options.clutter_max_range_m - options.clutter_min_range_m) + options.clutter_min_range_m;
    const double bearing = b * (2.0 * options.clutter_bearing_deg) - options.clutter_bearing_deg;
    return {r * std::cos(bearing * M_PI / 180.0), r * std::sin(bearing * M_PI / 180.0), 0.0};
  }
  // The band: the object's nearest point at a depth in the band (its centre a footprint radius
  // behind that), then a lateral offset that keeps it in view at that depth, with a metre to
  // spare so that the picture's edges are covered too.
  const ClutterBandView& view = options.band_view;
  const double depth =
      options.clutter_band_near_m + a * (options.clutter_band_far_m - options.clutter_band_near_m) + radius;
  const double half_width = depth * std::tan(view.half_fov_rad) + 1.0;
  const double lateral = (2.0 * b - 1.0) * half_width;
  const double c = std::cos(view.camera_yaw_rad), s = std::sin(view.camera_yaw_rad);
  return {view.camera_position.x() + depth * c - lateral * s, view.camera_position.y() + depth * s + lateral * c, 0.0};
}

void WorldScene::set_intruder(std::uint64_t id, const Eigen::Vector3d& position, double yaw) {
  auto& model = intruders_[id];
  if (!model) {
    model = make_hexacopter(drone_shape_, seed_ * 1000 + id);
    scene_->insert(model);
  }
  model->setVisibility(true);
  model->setPose(mrpt::poses::CPose3D(position.x(), position.y(), position.z(), yaw, 0.0, 0.0));
  placed_[id] = true;
}

void WorldScene::hide_unplaced_intruders() {
  for (auto& [id, model] : intruders_) {
    if (!placed_[id]) model->setVisibility(false);
    placed_[id] = false;
  }
}

}  // namespace kestrel::sim
