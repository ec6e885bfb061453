// The track that carries the target when the selected one coasts: a new track's detection where
// the world estimate expects the target.
#include <gtest/gtest.h>

#include <cmath>

#include "sighted_track.hpp"

using namespace kestrel;
using kestrel::aim::sighted_track;

namespace {

msg::Track track(std::uint64_t id, int misses, const Eigen::Vector3d& detection) {
  msg::Track t;
  t.id = id;
  t.age = t.hits = 10;
  t.misses = misses;
  t.state = Eigen::VectorXd::Zero(9);
  t.state.head<3>() = detection;
  if (misses == 0) t.detection = detection;
  return t;
}

// A level camera 3 m up, looking along world +x: camera x right (world -y), y down (world -z),
// z forward (world +x).
geometry::CameraPose level_camera() {
  geometry::CameraPose c;
  c.position_world = Eigen::Vector3d(0.0, 0.0, 3.0);
  c.body_to_world = Eigen::Quaterniond::Identity();
  return c;
}

}  // namespace

TEST(SightedTrack, TakesTheNewTrackWhoseDetectionIsWhereTheTargetIsExpected) {
  const geometry::CameraPose camera = level_camera();
  // The estimate expects the target 5 m ahead at the camera's height; the selected track 7
  // coasts, track 9 sees something 0.3 m from there, track 11 a false alarm 3 m to the side.
  const Eigen::Vector3d predicted = camera.to_world(Eigen::Vector3d(0.0, 0.0, 5.0));
  msg::Tracks tracks;
  tracks.items = {track(7, 3, Eigen::Vector3d(0.0, 0.0, 5.0)), track(9, 0, Eigen::Vector3d(0.3, 0.0, 5.0)),
                  track(11, 0, Eigen::Vector3d(-3.0, 0.0, 5.0))};
  tracks.selected_id = 7;
  const auto within_1m = [&](const Eigen::Vector3d& s) { return (s - predicted).norm() <= 1.0; };
  const msg::Track* found = sighted_track(tracks, camera, 0.5, predicted, within_1m);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found->id, 9u);

  // Of two sightings both expected, the nearer the prediction.
  tracks.items.push_back(track(12, 0, Eigen::Vector3d(0.1, 0.0, 5.0)));
  found = sighted_track(tracks, camera, 0.5, predicted, within_1m);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found->id, 12u);
}

TEST(SightedTrack, NothingWhereTheTargetIsNotExpectedOrOnlyCoastingOrNearTheGround) {
  const geometry::CameraPose camera = level_camera();
  const Eigen::Vector3d predicted = camera.to_world(Eigen::Vector3d(0.0, 0.0, 5.0));
  const auto within_1m = [&](const Eigen::Vector3d& s) { return (s - predicted).norm() <= 1.0; };
  msg::Tracks tracks;
  // A coasting track at the prediction (no detection), a sighting 2 m off.
  tracks.items = {track(7, 2, Eigen::Vector3d(0.0, 0.0, 5.0)), track(9, 0, Eigen::Vector3d(2.0, 0.0, 5.0))};
  EXPECT_EQ(sighted_track(tracks, camera, 0.5, predicted, within_1m), nullptr);

  // Ground clutter where a low target was expected: 2.8 m below the camera is 0.2 m up.
  const Eigen::Vector3d low = camera.to_world(Eigen::Vector3d(0.0, 2.6, 5.0));
  tracks.items = {track(13, 0, Eigen::Vector3d(0.0, 2.8, 5.0))};
  const auto near_low = [&](const Eigen::Vector3d& s) { return (s - low).norm() <= 1.0; };
  EXPECT_EQ(sighted_track(tracks, camera, 0.5, low, near_low), nullptr);
  EXPECT_NE(sighted_track(tracks, camera, 0.0, low, near_low), nullptr);  // a gate at the ground takes it
}
