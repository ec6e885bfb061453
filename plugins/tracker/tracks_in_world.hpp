#pragma once
// Tracks kept in the world instead of the camera frame, for a tracker on a camera that moves.
// In the camera frame a target's track moves with the camera's own rotation: a hunter that pitches
// at 2 rad/s moves a target 5 m ahead by 10 m/s across the frame, the track's filter learns that
// velocity, the next pitch back leaves its prediction outside the association gate, and the track
// breaks. In the world the target moves only as it flies. The tracker takes each frame's
// detections to the world with the camera's pose at the capture, tracks there, and publishes the
// tracks in that frame's camera frame again, as its consumers expect.
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/tracks.hpp>

namespace kestrel::tracking {

/// A track kept in the world, as seen from `camera`: its position, and each further 3-vector
/// block of its state (velocity, acceleration: world motion in the camera's axes), its
/// covariance likewise, and its detection. States whose size is not a multiple of 3 keep their
/// last entries as they are.
msg::Track track_in_camera(msg::Track world, const geometry::CameraPose& camera);

}  // namespace kestrel::tracking
