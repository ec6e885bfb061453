// The `net_sim` node: the simulated net and the judge of the intercept. Each `fire` order
// launches a net from the hunter's true pose (net_model.hpp); an intruder whose true centre
// comes within the open net's radius is caught, announced on `capture` (the intruder then
// falls). From the hunter's true state and the intruder's ground truth it also measures the true
// aim error, x_E^d - x_E, and reports the closed-loop figures under `control` with plots of the
// flight and of the aim.
#include <fmt/format.h>

#include <cmath>
#include <kestrel/geometry/frames.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/net_capture.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/net_launcher.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <kestrel/plot/line_plot.hpp>
#include <kestrel/plugin.hpp>
#include <limits>
#include <optional>

#include "kestrel/net/net_model.hpp"

namespace kestrel::net {

struct NetSimConfig {
  std::int64_t object_id = 1;
  Eigen::Vector3d camera_offset_m{0.1, 0.0, 0.0};
  Eigen::Vector3d open_point_m{0.0, 1.0, 2.0};
  double flight_time_s = 0.4;
  double radius_m = 0.6;
  double open_for_s = 0.3;
  double gravity_m_s2 = 9.81;
  std::int64_t nets = 0;  // 0: unlimited
  double reload_s = 0.0;
  double end_after_decided_s = -1.0;  // < 0: the run goes on to its duration
  std::string section = "control";
  std::int64_t max_samples = 100000;
};

class NetSimNode final : public Node {
 public:
  static constexpr Input<msg::NetFire> kFire{"fire"};
  static constexpr Input<msg::VehicleState> kHunter{"hunter"};
  static constexpr Input<msg::GroundTruth> kTruth{"truth"};
  static constexpr Output<msg::NetCapture> kCapture{"capture"};
  static constexpr Output<msg::NetLauncher> kLauncher{"launcher"};

  static NodeSpec spec() {
    using C = NetSimConfig;
    ConfigSpec<C> c;
    c.param("object_id", &C::object_id).at_least(0).describe("ground-truth id of the intruder to catch");
    c.param("camera_offset_m", &C::camera_offset_m)
        .with_unit("m")
        .range(-10.0, 10.0)
        .describe("camera and launcher position in the hunter's body frame");
    c.param("open_point_m", &C::open_point_m)
        .with_unit("m")
        .range(-50.0, 50.0)
        .describe("where the net is widest, in the camera frame at launch (the paper's [0, 1, 2])");
    c.param("flight_time_s", &C::flight_time_s).with_unit("s").range(0.05, 10.0).describe("launch to widest opening");
    c.param("radius_m", &C::radius_m).with_unit("m").range(0.01, 10.0).describe("radius of the open net");
    c.param("open_for_s", &C::open_for_s).with_unit("s").range(0.0, 10.0).describe("how long it stays open");
    c.param("gravity_m_s2", &C::gravity_m_s2).with_unit("m/s^2").range(0.0, 100.0).describe("gravity on the net");
    c.param("nets", &C::nets).range(0, 1000).describe("nets the launcher carries; 0: unlimited");
    c.param("reload_s", &C::reload_s)
        .with_unit("s")
        .range(0.0, 3600.0)
        .describe("after a shot, the launcher cannot fire again for this long");
    c.param("end_after_decided_s", &C::end_after_decided_s)
        .with_unit("s")
        .range(-1.0, 3600.0)
        .describe(
            "end the run this long after the engagement is decided (the intruder caught, or the last net spent "
            "without catching it); negative: the run goes on to its duration");
    c.param("section", &C::section).describe("report section of the closed-loop figures");
    c.param("max_samples", &C::max_samples).range(2, 10000000).describe("samples kept for the plots (memory bound)");
    return NodeSpec("net_sim", "Simulated net: flies, opens, catches; judges the intercept")
        .details(
            "A fire order launches the net on a parabola that opens at open_point_m (camera frame at launch) after "
            "flight_time_s; an intruder within radius_m of its centre while open is caught. Reports "
            "control.{aim_rmse_m, "
            "time_to_align_s, time_to_first_fire_s, fire_count, captured, first_shot_captured, time_to_capture_s} from "
            "the true states, "
            "and draws the flight (top view, heights) and the aim error with the shots.")
        .input(kFire, "orders to fire")
        .input(kHunter, "the hunter's true state", {.trigger = Trigger::latest})
        .input(kTruth, "the intruders' ground truth")
        .output(kCapture, "the intruder caught, once")
        .output(kLauncher, "the launcher's state (nets left, ready when), at the start and after each shot")
        .config(std::move(c));
  }

  explicit NetSimNode(NodeInit& init) : NetSimNode(init.config<NetSimConfig>()) {}

  void process(Context& ctx) override {
    const auto hunter = ctx.get(kHunter);
    if (!hunter) return;
    const double t = to_seconds(ctx.now());
    const geometry::CameraPose launcher =
        geometry::camera_on_body(hunter->position, hunter->orientation, cfg_.camera_offset_m);
    if (!announced_) {
      announced_ = true;
      publish_launcher(ctx, ctx.now());
    }
    if (ctx.triggered_by(kFire)) {
      // An order the launcher cannot carry out is refused, logged and counted, never lost.
      const bool empty = cfg_.nets > 0 && static_cast<std::int64_t>(fire_times_.size()) >= cfg_.nets;
      if (empty || t < ready_at_) {
        ++refused_;
        ctx.log().warn("fire order at t = {:.2f} s refused: {}", t,
                       empty ? "no net left" : fmt::format("reloading until {:.2f} s", ready_at_));
        return;
      }
      ready_at_ = t + cfg_.reload_s;
      const NetShot shot = model_.fire(t, launcher, hunter->velocity);
      shots_.push_back({shot, fire_times_.size()});
      fire_times_.push_back(t);
      closest_.push_back(std::numeric_limits<double>::infinity());
      closest_straight_.push_back(closest_if_straight(shot));
      launch_geometry_.push_back(launch_geometry(launcher.position_world, hunter->velocity));
      if (!first_fire_) first_fire_ = t;
      publish_launcher(ctx, ctx.now());
      return;
    }
    const auto truth = ctx.get(kTruth);
    const msg::GroundTruthObject* intruder = nullptr;
    for (const auto& o : truth->objects)
      if (o.id == static_cast<std::uint64_t>(cfg_.object_id)) intruder = &o;
    if (!intruder) return;
    const double tt = to_seconds(truth->stamp);
    if (!captured_at_) {
      const Eigen::Vector3d error = cfg_.open_point_m - launcher.to_camera(intruder->position_world);
      if (!aligned_at_ && error.norm() <= cfg_.radius_m) aligned_at_ = tt;
      if (aligned_at_) {
        squared_error_ += error.squaredNorm();
        ++aligned_samples_;
      }
      keep(tt, error.norm(), hunter->position, intruder->position_world);
      // Each shot in flight against the intruder since its last sample (it moved in a straight
      // line meanwhile); the report also keeps by how much a miss missed.
      const double t0 = previous_ ? previous_->first : tt;
      const Eigen::Vector3d from = previous_ ? previous_->second : intruder->position_world;
      for (const auto& [shot, index] : shots_)
        if (const auto caught = model_.sweep(shot, t0, from, tt, intruder->position_world, closest_[index])) {
          captured_at_ = *caught;
          captured_by_ = index;
          ctx.log().info("intruder {} caught at t = {:.3f} s, ({:.2f}, {:.2f}, {:.2f}) m", intruder->id, *caught,
                         intruder->position_world.x(), intruder->position_world.y(), intruder->position_world.z());
          ctx.publish(kCapture, msg::NetCapture{truth->stamp, intruder->id, intruder->position_world});
          break;
        }
      previous_ = {tt, intruder->position_world};
      previous_velocity_ = intruder->velocity_world;
      std::erase_if(shots_, [&](const auto& s) { return model_.spent(s.first, tt); });
      const bool nets_spent = cfg_.nets > 0 && static_cast<std::int64_t>(fire_times_.size()) >= cfg_.nets;
      if (!captured_at_ && !missed_at_ && nets_spent && shots_.empty()) missed_at_ = tt;
    }
    end_once_decided(ctx, t);
  }

  void finish(Context& ctx) override {
    auto maybe = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
    std::optional<double> rmse;
    if (aligned_samples_ > 0) rmse = std::sqrt(squared_error_ / static_cast<double>(aligned_samples_));
    const std::string& s = cfg_.section;
    auto text = [](const std::optional<double>& v, const char* unit) {
      return v ? fmt::format("{:.2f} {}", *v, unit) : std::string("n/a");
    };
    ctx.set_report_section(
        s,
        ReportSection()
            .metric("aim_rmse_m", maybe(rmse), "m", Better::lower)
            .metric("time_to_align_s", maybe(aligned_at_), "s", Better::lower)
            .metric("time_to_first_fire_s", maybe(first_fire_), "s", Better::lower)
            .quantity("fire_count", fire_times_.size() + refused_)
            .quantity("nets", cfg_.nets > 0 ? nlohmann::json(cfg_.nets) : nlohmann::json())
            .metric("nets_used", fire_times_.size(), "", Better::lower)
            .quantity("refused_fires", refused_)
            .quantity("shots", shots_json())
            .metric("captured", captured_at_.has_value(), "", Better::higher)
            .metric("first_shot_captured", captured_by_ == std::optional<std::size_t>(0), "", Better::higher)
            .metric("time_to_capture_s", maybe(captured_at_), "s", Better::lower)
            .markdown(fmt::format(
                "{}. Aligned (true aim error within {:.2f} m) at {}; aim error from then on {} RMS; {} shot(s), "
                "the first at {}.\n",
                captured_at_ ? fmt::format("**Captured** at {:.2f} s", *captured_at_) : std::string("**Not captured**"),
                cfg_.radius_m, text(aligned_at_, "s"), text(rmse, "m"), fire_times_.size(), text(first_fire_, "s"))));
    if (ctx.keeps_artifacts() && t_.size() >= 2) {
      ctx.add_artifact("intercept.png", plot::render_png(flight_panels(), 1000, 320),
                       "hunter and intruder: top view and heights (world frame, true states)");
      ctx.add_artifact("aim_error.png", plot::render_png({aim_panel()}, 1000, 320),
                       "true aim error |x_E^d - x_E| against time, with the shots");
    }
  }

 private:
  explicit NetSimNode(const NetSimConfig& cfg)
      : cfg_(cfg),
        model_(NetParams{cfg.open_point_m, cfg.flight_time_s, cfg.radius_m, cfg.open_for_s, cfg.gravity_m_s2}) {}

  // An engagement decided has nothing more to show: the run may end a little later (the net and
  // the intruder falling, in the plots and the video).
  void end_once_decided(Context& ctx, double now) {
    if (cfg_.end_after_decided_s < 0.0) return;
    const std::optional<double> decided = captured_at_ ? captured_at_ : missed_at_;
    if (decided && now >= *decided + cfg_.end_after_decided_s)
      ctx.end_run(captured_at_ ? fmt::format("the intruder was caught at {:.2f} s", *captured_at_)
                               : fmt::format("the last net missed; spent at {:.2f} s", *missed_at_));
  }

  void publish_launcher(Context& ctx, Time now) {
    const auto used = static_cast<std::int64_t>(fire_times_.size());
    ctx.publish(kLauncher, msg::NetLauncher{now, cfg_.nets > 0 ? cfg_.nets - used : -1, used,
                                            from_seconds(std::max(ready_at_, 0.0))});
  }

  // At the launch, the intruder's distance from the launcher and how fast the two close (along the
  // line of sight): where a miss was fired from. NaN before the intruder is first seen.
  std::pair<double, double> launch_geometry(const Eigen::Vector3d& launcher, const Eigen::Vector3d& velocity) const {
    if (!previous_) return {std::nan(""), std::nan("")};
    const Eigen::Vector3d line = previous_->second - launcher;
    const double range = line.norm();
    return {range, range > 0.0 ? (velocity - previous_velocity_).dot(line) / range : 0.0};
  }

  // How near the open net would have come to the intruder had it flown on at its true velocity at
  // the shot: a miss that this would have caught was lost to the intruder's manoeuvre while the
  // net flew, not to the aim (stops at the first catch, as the net does; inf: nothing seen yet).
  double closest_if_straight(const NetShot& shot) const {
    double closest = std::numeric_limits<double>::infinity();
    if (!previous_) return closest;
    const auto& [t0, p0] = *previous_;
    const double t1 = shot.fired_at + cfg_.flight_time_s + cfg_.open_for_s;
    model_.sweep(shot, shot.fired_at, p0 + (shot.fired_at - t0) * previous_velocity_, t1,
                 p0 + (t1 - t0) * previous_velocity_, closest);
    return closest;
  }

  // Each shot: when, how near the net's centre came to the intruder while open (null: the run
  // ended or the intruder was caught by an earlier shot before it opened), and how near it would
  // have come had the intruder flown straight on.
  nlohmann::json shots_json() const {
    auto finite = [](double d) { return std::isfinite(d) ? nlohmann::json(d) : nlohmann::json(); };
    nlohmann::json shots = nlohmann::json::array();
    for (std::size_t i = 0; i < fire_times_.size(); ++i)
      shots.push_back({{"t_s", fire_times_[i]},
                       {"closest_m", finite(closest_[i])},
                       {"closest_straight_m", finite(closest_straight_[i])},
                       {"range_m", finite(launch_geometry_[i].first)},
                       {"closing_m_s", finite(launch_geometry_[i].second)}});
    return shots;
  }

  void keep(double t, double error, const Eigen::Vector3d& hunter, const Eigen::Vector3d& intruder) {
    if (static_cast<std::int64_t>(t_.size()) >= cfg_.max_samples) return;
    t_.push_back(t);
    error_.push_back(error);
    hunter_.push_back(hunter);
    intruder_.push_back(intruder);
  }

  std::vector<plot::Panel> flight_panels() const {
    plot::Series hx{"hunter", {}, {}, plot::Series::Style::line, plot::palette(0), 2};
    plot::Series ix{"intruder", {}, {}, plot::Series::Style::line, plot::palette(1), 2};
    plot::Series hz = hx, iz = ix;
    for (std::size_t i = 0; i < t_.size(); ++i) {
      hx.x.push_back(hunter_[i].x());
      hx.y.push_back(hunter_[i].y());
      ix.x.push_back(intruder_[i].x());
      ix.y.push_back(intruder_[i].y());
      hz.x.push_back(t_[i]);
      hz.y.push_back(hunter_[i].z());
      iz.x.push_back(t_[i]);
      iz.y.push_back(intruder_[i].z());
    }
    return {plot::Panel{"top view", "x [m]", "y [m]", {hx, ix}}, plot::Panel{"height", "t [s]", "z [m]", {hz, iz}}};
  }

  plot::Panel aim_panel() const {
    plot::Series error{"|x_E^d - x_E|", t_, error_, plot::Series::Style::line, plot::palette(0), 2};
    plot::Series radius{"net radius",
                        {t_.front(), t_.back()},
                        {cfg_.radius_m, cfg_.radius_m},
                        plot::Series::Style::line,
                        plot::palette(7),
                        1};
    plot::Series shots{"shots",
                       fire_times_,
                       std::vector<double>(fire_times_.size(), 0.0),
                       plot::Series::Style::points,
                       plot::palette(3),
                       6};
    plot::Panel panel{"true aim error", "t [s]", "m", {error, radius, shots}};
    if (captured_at_)
      panel.series.push_back({"capture", {*captured_at_}, {0.0}, plot::Series::Style::points, plot::palette(2), 10});
    return panel;
  }

  NetSimConfig cfg_;
  NetModel model_;
  std::vector<std::pair<NetShot, std::size_t>> shots_;           ///< in flight, with their index in fire_times_
  std::vector<double> closest_;                                  ///< per shot: nearest approach while open
  std::vector<double> closest_straight_;                         ///< per shot: the same, the intruder flying straight
  std::vector<std::pair<double, double>> launch_geometry_;       ///< per shot: range (m), closing (m/s)
  Eigen::Vector3d previous_velocity_ = Eigen::Vector3d::Zero();  ///< the intruder's at its last sample
  std::optional<std::pair<double, Eigen::Vector3d>> previous_;   ///< the intruder's last sample
  std::vector<double> fire_times_;
  std::optional<double> first_fire_, aligned_at_, captured_at_;
  std::optional<double> missed_at_;         // the last net spent without catching
  std::optional<std::size_t> captured_by_;  // the shot that caught it
  bool announced_ = false;                  // the launcher's first state is out
  double ready_at_ = 0.0;                   // s: no shot before this (reloading)
  std::size_t refused_ = 0;                 // fire orders without a net or while reloading
  double squared_error_ = 0.0;
  std::uint64_t aligned_samples_ = 0;
  std::vector<double> t_, error_;
  std::vector<Eigen::Vector3d> hunter_, intruder_;
};
KESTREL_REGISTER_NODE(NetSimNode)

}  // namespace kestrel::net
