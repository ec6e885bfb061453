#include "drone_model.hpp"

#include <mrpt/img/CImage.h>

#include <cmath>

#include "mesh_builder.hpp"
#include "textures.hpp"

namespace kestrel::sim {

mrpt::opengl::CSetOfObjects::Ptr make_hexacopter(const DroneShape& shape, std::uint64_t texture_seed) {
  auto frame = mrpt::opengl::CSetOfTexturedTriangles::Create();
  auto rotors = mrpt::opengl::CSetOfTexturedTriangles::Create();

  // Vertical layout, bottom to top: skids, legs, battery, hub, arms and motors, rotor discs.
  const double top = shape.height_m * 0.33;    // rotor plane
  const double bottom = top - shape.height_m;  // skids
  const double hub_h = 0.07;
  add_box(*frame, {0, 0, top - 0.04 - hub_h / 2}, {shape.body_size_m, shape.body_size_m * 0.8, hub_h});
  add_box(*frame, {0, 0, top - 0.04 - hub_h - 0.03}, {0.13, 0.09, 0.06});  // battery and gimbal
  for (int k = 0; k < 6; ++k) {
    const double a = M_PI / 6 + k * M_PI / 3;
    const Eigen::Matrix3d yaw = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d dir(std::cos(a), std::sin(a), 0.0);
    add_box(*frame, dir * (shape.arm_length_m / 2) + Eigen::Vector3d(0, 0, top - 0.035),
            {shape.arm_length_m, 0.025, 0.02}, yaw);
    add_box(*frame, dir * shape.arm_length_m + Eigen::Vector3d(0, 0, top - 0.03), {0.04, 0.04, 0.045}, yaw);
    add_disc(*rotors, dir * shape.arm_length_m + Eigen::Vector3d(0, 0, top), shape.rotor_radius_m, 0.006);
  }
  for (double side : {-1.0, 1.0}) {
    const double y = side * 0.09;
    add_box(*frame, {0.06, y, (bottom + top - 0.11) / 2}, {0.015, 0.015, top - 0.11 - bottom});
    add_box(*frame, {-0.06, y, (bottom + top - 0.11) / 2}, {0.015, 0.015, top - 0.11 - bottom});
    add_box(*frame, {0, y, bottom + 0.0075}, {0.30, 0.02, 0.015});
  }

  const cv::Mat body_texture = make_texture(64, drone_style(), texture_seed);
  TextureStyle blur_style = drone_style();
  blur_style.dark = {60, 60, 60};
  blur_style.light = {200, 200, 200};
  const cv::Mat rotor_texture = make_texture(64, blur_style, texture_seed + 1);
  frame->assignImage(mrpt::img::CImage(body_texture, mrpt::img::DEEP_COPY));
  rotors->assignImage(mrpt::img::CImage(rotor_texture, mrpt::img::DEEP_COPY));
  frame->enableTextureLinearInterpolation(true);
  rotors->enableTextureLinearInterpolation(true);

  auto drone = mrpt::opengl::CSetOfObjects::Create();
  drone->insert(frame);
  drone->insert(rotors);
  return drone;
}

}  // namespace kestrel::sim
