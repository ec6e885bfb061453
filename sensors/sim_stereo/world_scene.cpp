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
  std::uniform_real_distribution<double> range(options.clutter_min_range_m, options.clutter_max_range_m);
  std::uniform_real_distribution<double> bearing(-options.clutter_bearing_deg, options.clutter_bearing_deg);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto trunks = textured(bark_style(), seed_ * 7 + 3, 128);
  auto canopies = textured(foliage_style(), seed_ * 7 + 4);
  auto buildings = textured(concrete_style(), seed_ * 7 + 5);
  for (int i = 0; i < options.clutter_count; ++i) {
    const double r = range(rng), b = bearing(rng) * M_PI / 180.0;
    const Eigen::Vector3d at(r * std::cos(b), r * std::sin(b), 0.0);
    const Eigen::Matrix3d yaw = Eigen::AngleAxisd(unit(rng) * M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    if (unit(rng) < 0.65) {  // a tree: trunk and canopy
      const double height = 3.0 + 4.0 * unit(rng);
      const double width = 1.8 + 2.0 * unit(rng);
      add_box(*trunks, at + Eigen::Vector3d(0, 0, height * 0.3), {0.35, 0.35, height * 0.6}, yaw);
      add_box(*canopies, at + Eigen::Vector3d(0, 0, height * 0.7), {width, width, height * 0.6}, yaw);
    } else {  // a building
      const Eigen::Vector3d size(3.0 + 6.0 * unit(rng), 3.0 + 6.0 * unit(rng), 3.0 + 5.0 * unit(rng));
      add_box(*buildings, at + Eigen::Vector3d(0, 0, size.z() / 2), size, yaw);
    }
    clutter_.push_back(at);
  }
  scene_->insert(trunks);
  scene_->insert(canopies);
  scene_->insert(buildings);
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
