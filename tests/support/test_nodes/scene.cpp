// A scene whose answer is known, for the evaluators and the trajectory plot: one intruder on a
// smooth path, its ground truth, detections and a track that sit at a fixed offset from it, and
// nodes that hold messages back for a while (a slow chain under the realtime executor).
#include "scene.hpp"

#include <chrono>
#include <cmath>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/plugin.hpp>
#include <thread>

namespace kestrel::test {

class SceneSource final : public Node {
 public:
  static constexpr Output<msg::GroundTruth> kTruth{"truth"};
  static constexpr Output<msg::Detections> kDetections{"detections"};
  static constexpr Output<msg::Tracks> kTracks{"tracks"};

  static NodeSpec spec() {
    return NodeSpec("scene_source", "One intruder with its ground truth, detections and a track at known offsets")
        .details(
            "Frame k is captured at k / rate_hz (its stamp, whatever the clock says when it is published). The "
            "intruder is at scene_position(k) in the camera frame; the detection and the track sit at "
            "scene_position(k) + "
            "offset_m.")
        .output(kTruth, "ground truth of frame k")
        .output(kDetections, "one detection per frame, none every miss_every-th frame")
        .output(kTracks, "one selected track (id 7) per frame")
        .param(param("rate_hz", 50.0).with_unit("Hz").range(0.001, 1e6).describe("frames per second"))
        .param(param("count", 30).at_least(1).describe("frames to publish"))
        .param(param("offset_m", std::vector<double>{0.0, 0.0, 0.0}).describe("detection and track error"))
        .param(param("miss_every", 0)
                   .at_least(0)
                   .describe("frames k with k % miss_every == miss_every - 1 have no "
                             "detection; 0 = never"));
  }

  explicit SceneSource(NodeInit& init)
      : count_(init.param<std::int64_t>("count")),
        period_s_(1.0 / init.param<double>("rate_hz")),
        miss_every_(init.param<std::int64_t>("miss_every")) {
    const auto offset = init.param<std::vector<double>>("offset_m");
    if (offset.size() != 3) throw Error("offset_m needs three values");
    offset_ = {offset[0], offset[1], offset[2]};
    init.set_rate(init.param<double>("rate_hz"));
  }

  void tick(Context& ctx) override {
    const Time stamp = from_seconds(static_cast<double>(next_) * period_s_);
    const Eigen::Vector3d p = scene_position(next_);

    msg::GroundTruth truth;
    truth.stamp = stamp;
    truth.objects.push_back({1, p, p, Eigen::Vector3d::Zero(), true});
    ctx.publish(kTruth, std::move(truth));

    msg::Detections detections;
    detections.stamp = stamp;
    if (scene_detects(next_, miss_every_))
      detections.items.push_back({p + offset_, Eigen::Vector3d::Constant(0.5), 50, 1.0});
    ctx.publish(kDetections, std::move(detections));

    msg::Tracks tracks;
    tracks.stamp = stamp;
    msg::Track track;
    track.id = 7;
    track.age = track.hits = static_cast<int>(next_) + 1;
    track.state = Eigen::VectorXd::Zero(9);
    track.state.head<3>() = p + offset_;
    track.covariance = Eigen::MatrixXd::Identity(9, 9);
    tracks.items.push_back(track);
    tracks.selected_id = 7;
    ctx.publish(kTracks, std::move(tracks));

    if (++next_ == count_) ctx.end_of_stream();
  }

 private:
  std::int64_t count_;
  double period_s_;
  std::int64_t miss_every_;
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
  std::int64_t next_ = 0;
};
KESTREL_REGISTER_NODE(SceneSource)

// Holds each message for delay_ms of wall-clock time, then republishes it unchanged.
template <class T, const char* kName>
class Delay final : public Node {
 public:
  static constexpr Input<T> kIn{"in"};
  static constexpr Output<T> kOut{"out"};
  static NodeSpec spec() {
    return NodeSpec(kName, "Sleeps (wall clock) before republishing each message unchanged")
        .input(kIn, "messages")
        .output(kOut, "the same messages, late")
        .param(param("delay_ms", 20.0).range(0.0, 10000.0).with_unit("ms").describe("sleep per message"));
  }
  explicit Delay(NodeInit& init) : delay_(init.param<double>("delay_ms")) {}
  void process(Context& ctx) override {
    std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(delay_));
    ctx.publish(kOut, ctx.get(kIn));
  }

 private:
  double delay_;
};

inline constexpr char kDetectionsDelay[] = "detections_delay";
inline constexpr char kTracksDelay[] = "tracks_delay";
using DetectionsDelay = Delay<msg::Detections, kDetectionsDelay>;
using TracksDelay = Delay<msg::Tracks, kTracksDelay>;
KESTREL_REGISTER_NODE(DetectionsDelay)
KESTREL_REGISTER_NODE(TracksDelay)

}  // namespace kestrel::test
