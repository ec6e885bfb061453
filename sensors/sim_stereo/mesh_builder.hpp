#pragma once
// Textured solids made of triangles, for MRPT's renderer: boxes and flat discs with texture
// coordinates and outward normals.
#include <mrpt/opengl/CSetOfTexturedTriangles.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace kestrel::sim {

/// Adds a box of `size` (x, y, z extents) centred at `centre`, rotated by `rotation`. Each face
/// carries the whole texture once (texture coordinates stay in [0, 1]), or, with `tile` > 0, the
/// texture repeats every `tile` metres, so that its detail has the same size on every box.
/// `inward` turns the faces to be seen from inside (a sky box).
void add_box(mrpt::opengl::CSetOfTexturedTriangles& mesh, const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
             const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity(), bool inward = false, double tile = 0.0);

/// Adds a flat disc (a prism with `sides` faces) of `radius` and `thickness`, axis along z.
void add_disc(mrpt::opengl::CSetOfTexturedTriangles& mesh, const Eigen::Vector3d& centre, double radius,
              double thickness, int sides = 16);

/// Adds a horizontal rectangle at height z whose texture repeats once every `tile` metres (a
/// tiled ground), drawn as a few large patches.
void add_tiled_ground(mrpt::opengl::CSetOfTexturedTriangles& mesh, double half_extent, double tile, double z = 0.0);

}  // namespace kestrel::sim
