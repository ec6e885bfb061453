#include "mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kestrel::sim {

namespace {

using mrpt::opengl::TTriangle;

mrpt::math::TPoint3Df point(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

// One quad (a, b, c, d counter-clockwise seen from outside) as two triangles with UVs.
void add_quad(mrpt::opengl::CSetOfTexturedTriangles& mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const Eigen::Vector3d& c, const Eigen::Vector3d& d, float u_max, float v_max) {
  const Eigen::Vector3d n = (b - a).cross(d - a).normalized();
  const mrpt::math::TVector3Df normal(static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z()));
  auto make = [&](const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, float u0, float v0,
                  float u1, float v1, float u2, float v2) {
    TTriangle t(point(p0), point(p1), point(p2), normal, normal, normal);
    t.u(0) = u0, t.v(0) = v0, t.u(1) = u1, t.v(1) = v1, t.u(2) = u2, t.v(2) = v2;
    for (int i = 0; i < 3; ++i) t.vertices[static_cast<std::size_t>(i)].setColor(mrpt::img::TColor(255, 255, 255));
    mesh.insertTriangle(t);
  };
  make(a, b, c, 0, 0, u_max, 0, u_max, v_max);
  make(a, c, d, 0, 0, u_max, v_max, 0, v_max);
}

}  // namespace

void add_box(mrpt::opengl::CSetOfTexturedTriangles& mesh, const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
             const Eigen::Matrix3d& rotation, bool inward, double tile) {
  const Eigen::Vector3d h = size / 2.0;
  // Texture repeats across a face of extents a x b.
  const auto repeats = [tile](double a, double b) {
    return tile > 0.0 ? std::pair{static_cast<float>(a / tile), static_cast<float>(b / tile)} : std::pair{1.0f, 1.0f};
  };
  const auto [xu, xv] = repeats(size.y(), size.z());
  const auto [yu, yv] = repeats(size.x(), size.z());
  const auto [zu, zv] = repeats(size.x(), size.y());
  // Mirroring y reverses every face's winding, so the faces look inward.
  const double mirror = inward ? -1.0 : 1.0;
  auto corner = [&](double sx, double sy, double sz) {
    return Eigen::Vector3d(centre + rotation * Eigen::Vector3d(sx * h.x(), mirror * sy * h.y(), sz * h.z()));
  };
  // Faces: +x, -x, +y, -y, +z, -z (corners counter-clockwise seen from outside).
  add_quad(mesh, corner(1, -1, -1), corner(1, 1, -1), corner(1, 1, 1), corner(1, -1, 1), xu, xv);
  add_quad(mesh, corner(-1, 1, -1), corner(-1, -1, -1), corner(-1, -1, 1), corner(-1, 1, 1), xu, xv);
  add_quad(mesh, corner(1, 1, -1), corner(-1, 1, -1), corner(-1, 1, 1), corner(1, 1, 1), yu, yv);
  add_quad(mesh, corner(-1, -1, -1), corner(1, -1, -1), corner(1, -1, 1), corner(-1, -1, 1), yu, yv);
  add_quad(mesh, corner(-1, -1, 1), corner(1, -1, 1), corner(1, 1, 1), corner(-1, 1, 1), zu, zv);
  add_quad(mesh, corner(-1, 1, -1), corner(1, 1, -1), corner(1, -1, -1), corner(-1, -1, -1), zu, zv);
}

void add_disc(mrpt::opengl::CSetOfTexturedTriangles& mesh, const Eigen::Vector3d& centre, double radius,
              double thickness, int sides) {
  const Eigen::Vector3d up(0, 0, thickness / 2);
  auto rim = [&](int k) {
    const double a = 2.0 * M_PI * k / sides;
    return Eigen::Vector3d(centre + radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0));
  };
  for (int k = 0; k < sides; ++k) {
    const Eigen::Vector3d p0 = rim(k), p1 = rim(k + 1);
    // Top and bottom fans, and the edge.
    add_quad(mesh, centre + up, p0 + up, p1 + up, centre + up, 1.0f, 1.0f);
    add_quad(mesh, centre - up, p1 - up, p0 - up, centre - up, 1.0f, 1.0f);
    add_quad(mesh, p0 - up, p1 - up, p1 + up, p0 + up, 1.0f, 0.1f);
  }
}

void add_tiled_ground(mrpt::opengl::CSetOfTexturedTriangles& mesh, double half_extent, double tile, double z) {
  // Patches of several tiles, the texture repeating across each (GL_REPEAT, OpenGL's default):
  // the same picture as one quad per tile, with a sixty-fourth of the triangles to transform
  // and clip (the software renderer's cost grew with their number).
  const double patch = tile * 8;
  for (double x = -half_extent; x < half_extent - 1e-9; x += patch)
    for (double y = -half_extent; y < half_extent - 1e-9; y += patch) {
      const double x1 = std::min(x + patch, half_extent), y1 = std::min(y + patch, half_extent);
      add_quad(mesh, {x, y, z}, {x1, y, z}, {x1, y1, z}, {x, y1, z}, static_cast<float>((x1 - x) / tile),
               static_cast<float>((y1 - y) / tile));
    }
}

}  // namespace kestrel::sim
