// The tracking scorer on hand-made tracks whose answer is known: two intruders cross and the
// tracks swap identities, and a target that wanders off, disappears and comes back.
#include <gmock/gmock.h>

#include <cmath>

#include "mot_scoring.hpp"

using namespace kestrel;
using evaluation::TrackingScorer;

namespace {

msg::Track track_at(std::uint64_t id, double x) {
  msg::Track t;
  t.id = id;
  t.state = Eigen::VectorXd::Zero(9);
  t.state.head<3>() = Eigen::Vector3d(x, 0, 5);
  return t;
}

msg::GroundTruthObject object_at(std::uint64_t id, double x) {
  msg::GroundTruthObject o;
  o.id = id;
  o.position_camera = Eigen::Vector3d(x, 0, 5);
  return o;
}

}  // namespace

// Intruders 1 and 2 fly towards each other along x at 3 m/s (0.1 m a frame) and meet at frame 20.
// Track 10 follows intruder 1 and track 20 intruder 2 until the meeting; from frame 21 each
// follows the other intruder. MOT16 keeps a correspondence while it stays within the match
// radius (0.95 m): the old pairs hold until the intruders are 1 m apart at frame 25, when both
// objects change hypothesis: exactly two identity switches, no misses, no false positives.
TEST(TrackingScorer, CountsTheIdentitySwitchesOfTwoCrossingTracks) {
  TrackingScorer scorer(0.95);
  const int frames = 41;
  for (int k = 0; k < frames; ++k) {
    const double a = -2.0 + 0.1 * k, b = 2.0 - 0.1 * k;
    msg::GroundTruth truth;
    truth.stamp = from_seconds(k / 30.0);
    truth.objects = {object_at(1, a), object_at(2, b)};
    msg::Tracks tracks;
    tracks.stamp = truth.stamp;
    tracks.items = {track_at(10, k <= 20 ? a : b), track_at(20, k <= 20 ? b : a)};
    tracks.selected_id = 10;
    scorer.add_frame(tracks, truth, k / 30.0);
  }
  const auto s = scorer.summary();
  EXPECT_EQ(s.mot.idsw, 2u);
  EXPECT_EQ(s.mot.fp, 0u);
  EXPECT_EQ(s.mot.fn, 0u);
  EXPECT_EQ(s.mot.fragmentations, 0u);
  EXPECT_NEAR(s.mot.mota, 1.0 - 2.0 / (2 * frames), 1e-12);
  // IDF1: an object and either track are within the radius together for 25 of the 41 frames.
  EXPECT_NEAR(s.mot.idf1, 25.0 / 41.0, 1e-12);

  // The selected track 10 is scored against the object MOT matched it to: intruder 1 until frame
  // 24, 0.2 m .. 0.8 m from it from frame 21 on, then intruder 2 exactly.
  const double sq = 0.2 * 0.2 + 0.4 * 0.4 + 0.6 * 0.6 + 0.8 * 0.8;
  EXPECT_EQ(s.selected_frames, static_cast<std::uint64_t>(frames));
  EXPECT_NEAR(s.rmse, std::sqrt(sq / frames), 1e-12);
  EXPECT_NEAR(s.rmse_axes.x(), std::sqrt(sq / frames), 1e-12);

  // The aiming saw one switch, at frame 21, when track 10 came nearest to intruder 2.
  EXPECT_EQ(s.target.frames, static_cast<std::uint64_t>(frames));
  EXPECT_EQ(s.target.on, static_cast<std::uint64_t>(frames));
  EXPECT_EQ(s.target.switches, 1u);
  EXPECT_NEAR(s.target.mota(), 1.0 - 1.0 / frames, 1e-12);
}

// One intruder at x = 0 for 10 frames. The target is right for frames 0-2, on a noise track 3 m
// away for frames 3-4, absent for frames 5-6, and back on the intruder for 7-9 (another track id,
// the same intruder: not a switch). Both tracks stay published all along.
TEST(TrackingScorer, ScoresTheTargetOffAndMissing) {
  TrackingScorer scorer(1.0);
  for (int k = 0; k < 10; ++k) {
    msg::GroundTruth truth;
    truth.stamp = from_seconds(k / 30.0);
    truth.objects = {object_at(1, 0.0)};
    msg::Tracks tracks;
    tracks.stamp = truth.stamp;
    tracks.items = {track_at(5, 0.05), track_at(6, 3.0)};
    if (k <= 2) tracks.selected_id = 5;
    if (k == 3 || k == 4) tracks.selected_id = 6;
    if (k >= 7) tracks.selected_id = 5;
    scorer.add_frame(tracks, truth, k / 30.0);
  }
  // A frame with no intruder but a target selected is off target too, and has no truth frame.
  msg::Tracks stray;
  stray.stamp = from_seconds(10 / 30.0);
  stray.items = {track_at(6, 3.0)};
  stray.selected_id = 6;
  msg::GroundTruth empty;
  empty.stamp = stray.stamp;
  scorer.add_frame(stray, empty, 10 / 30.0);

  const auto s = scorer.summary();
  EXPECT_EQ(s.target.frames, 10u);
  EXPECT_EQ(s.target.on, 6u);
  EXPECT_EQ(s.target.off, 3u);
  EXPECT_EQ(s.target.missing, 2u);
  EXPECT_EQ(s.target.switches, 0u);
  EXPECT_NEAR(s.target.mota(), 1.0 - 5.0 / 10.0, 1e-12);
  // Over all tracks: track 6 is a false positive in all 11 frames, intruder 1 is never missed.
  EXPECT_EQ(s.mot.fp, 11u);
  EXPECT_EQ(s.mot.fn, 0u);
  EXPECT_EQ(s.mot.idsw, 0u);
  // The RMSE covers only the frames the selected track matched the intruder.
  EXPECT_EQ(s.selected_frames, 6u);
  EXPECT_NEAR(s.rmse, 0.05, 1e-12);
}

// Intruder 1 is in view for frames 0-4 and leaves the view for frames 5-9; intruder 2 is in view
// throughout. Track 7 follows intruder 1 all along (coasting out of view), track 8 intruder 2,
// and track 9 is noise. Out of view, intruder 1 is neither missed nor found, and track 7 is not
// a false positive; the noise track is, in every frame.
TEST(TrackingScorer, AnIntruderOutOfViewIsNeitherMissedNorFound) {
  TrackingScorer scorer(1.0);
  for (int k = 0; k < 10; ++k) {
    msg::GroundTruth truth;
    truth.stamp = from_seconds(k / 30.0);
    truth.objects = {object_at(1, -3.0), object_at(2, 1.0)};
    truth.objects[0].in_view = k < 5;
    msg::Tracks tracks;
    tracks.stamp = truth.stamp;
    tracks.items = {track_at(7, -3.1), track_at(8, 1.0), track_at(9, 6.0)};
    tracks.selected_id = 7;
    scorer.add_frame(tracks, truth, k / 30.0);
  }
  const auto s = scorer.summary();
  EXPECT_EQ(s.mot.objects, 15u);  // 2 x 5 in view + 1 x 5
  EXPECT_EQ(s.mot.fn, 0u);
  EXPECT_EQ(s.mot.fp, 10u);  // the noise track only
  EXPECT_EQ(s.mot.idsw, 0u);
  EXPECT_EQ(s.mot.fragmentations, 0u);
  // The target (track 7) stays on intruder 1, seen or not: on target in all 10 frames (each has
  // an intruder in view). Its RMSE covers the 5 frames intruder 1 was scored.
  EXPECT_EQ(s.target.frames, 10u);
  EXPECT_EQ(s.target.on, 10u);
  EXPECT_EQ(s.target.off, 0u);
  EXPECT_EQ(s.target.missing, 0u);
  EXPECT_EQ(s.selected_frames, 5u);
  EXPECT_NEAR(s.rmse, 0.1, 1e-12);
}

// skip_first_s: while the tracker settles, its false tracks, identity changes and misses are not
// scored; from skip_first_s on (inclusive) every frame is.
TEST(TrackingScorer, FramesCapturedBeforeSkipFirstAreNotScored) {
  TrackingScorer scorer(1.0, /*skip_first_s=*/0.5);
  for (int k = 0; k < 10; ++k) {
    msg::GroundTruth truth;
    truth.stamp = from_seconds(0.1 * k);
    truth.objects = {object_at(1, 0.0)};
    msg::Tracks tracks;
    tracks.stamp = truth.stamp;
    if (k < 5) {
      // Settling: a new identity every frame, a false track far away, and a miss at k = 4.
      if (k < 4) tracks.items = {track_at(100 + k, 0.5), track_at(50, 9.0)};
      if (!tracks.items.empty()) tracks.selected_id = tracks.items.back().id;
    } else {
      tracks.items = {track_at(7, 0.25)};
      tracks.selected_id = 7;
    }
    EXPECT_EQ(scorer.add_frame(tracks, truth, 0.1 * k), k >= 5) << k;
  }
  const auto s = scorer.summary();
  EXPECT_EQ(s.mot.frames, 5u);
  EXPECT_EQ(s.mot.objects, 5u);
  EXPECT_EQ(s.mot.fp, 0u);
  EXPECT_EQ(s.mot.fn, 0u);
  EXPECT_EQ(s.mot.idsw, 0u);
  EXPECT_DOUBLE_EQ(s.mot.mota, 1.0);
  EXPECT_EQ(s.selected_frames, 5u);
  EXPECT_NEAR(s.rmse, 0.25, 1e-12);
  EXPECT_EQ(s.target.frames, 5u);
  EXPECT_EQ(s.target.on, 5u);
  EXPECT_EQ(s.target.off + s.target.missing + s.target.switches, 0u);
}
