#pragma once
// Which track carries the target this frame when the selected one does not. The tracker follows
// tracks in the camera frame: a hunter that pitches hard (sprinting after a fleeing target) moves
// a target several metres a second across that frame, its track's prediction misses the gate, and
// the next detection starts a new track while the old one coasts. The selector keeps the older,
// coasting track for up to its max_misses, so the selected track has no sighting for many frames
// in a row. The aim estimates the target in the world, where the camera's rotation does not move
// it: a new track's detection that lies where that estimate expects the target is the target.
#include <Eigen/Core>
#include <functional>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/tracks.hpp>

namespace kestrel::aim {

/// The track with a detection this frame (misses == 0), seen from `camera`, whose sighting (world)
/// lies at or above `min_height_m` and where `expected` accepts it; of several, the one nearest
/// `predicted` (world). nullptr when none.
const msg::Track* sighted_track(const msg::Tracks& tracks, const geometry::CameraPose& camera, double min_height_m,
                                const Eigen::Vector3d& predicted,
                                const std::function<bool(const Eigen::Vector3d&)>& expected);

}  // namespace kestrel::aim
