#pragma once
// Intruder trajectories: the paths a simulated intruder flies, as position and velocity at any
// time. Pure functions of time (and of a seed for the random one), so runs reproduce.
#include <Eigen/Core>
#include <filesystem>
#include <istream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "kestrel/geometry/frames.hpp"

namespace kestrel::intruder {

struct State {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< world, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< world, m/s
};

class Trajectory {
 public:
  virtual ~Trajectory() = default;
  virtual State at(double t) const = 0;
};

/// The paper's figure-8 (a 1:2 Lissajous curve) in the plane normal to a camera's optical axis,
/// `distance` metres in front of it: x_c = half_width sin(wt), y_c = half_height sin(2wt).
class FigureEight final : public Trajectory {
 public:
  FigureEight(const geometry::CameraPose& camera, double distance, double half_width, double half_height,
              double period);
  State at(double t) const override;

 private:
  geometry::CameraPose camera_;
  double distance_, half_width_, half_height_, omega_;
};

/// A straight line from `start` to `end` at `speed`; then it holds, or flies back and forth.
/// With `acceleration` > 0 it flies as a multirotor can: from rest, up to speed, and down to rest
/// at the end (a trapezoidal profile, triangular when the line is too short to reach the speed).
/// With 0 it is at full speed throughout and turns instantly.
class StraightLine final : public Trajectory {
 public:
  StraightLine(const Eigen::Vector3d& start, const Eigen::Vector3d& end, double speed, bool bounce,
               double acceleration = 0.0);
  State at(double t) const override;

 private:
  /// Distance along the line and speed, `tau` seconds into a pass from rest to rest.
  std::pair<double, double> pass(double tau) const;

  Eigen::Vector3d start_, direction_;
  double length_, speed_;
  bool bounce_;
  double acceleration_;
  double top_speed_ = 0.0, pass_time_ = 0.0;  ///< with acceleration: the profile's peak and duration
};

/// Smooth random manoeuvres around a centre: on each axis a sum of sinusoids with random
/// frequencies and phases, scaled to stay inside a box and under a speed limit.
class RandomManoeuvre final : public Trajectory {
 public:
  /// Manoeuvres of 1 / max_frequency_hz to 30 s; 0 for max_acceleration: no bound but the box's
  /// and the speed's.
  RandomManoeuvre(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extent, double max_speed,
                  std::uint64_t seed, double max_acceleration = 0.0, double max_frequency_hz = 0.25);
  State at(double t) const override;

 private:
  struct Wave {
    double amplitude, omega, phase;
  };
  Eigen::Vector3d centre_;
  std::vector<Wave> waves_[3];
};

/// Jinks: a cruise at constant speed, turned by bang-bang lateral and vertical accelerations at
/// their limit, each held a random time in [min_hold, max_hold]; a multirotor dodging. A turn
/// keeps the speed (the lateral acceleration is normal to the velocity); the climb rate stays
/// within half the speed. Leaving its box, it turns and climbs back towards the centre.
/// Integrated once on a 10 ms grid from a seed, on demand, so that at(t) is a pure function of t.
class Jink final : public Trajectory {
 public:
  Jink(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extent, double speed, double max_acceleration,
       double min_hold, double max_hold, std::uint64_t seed);
  State at(double t) const override;

 private:
  struct Sample {
    State state;
    Eigen::Vector3d acceleration;  ///< held until the next sample
  };
  void extend_to(std::size_t k) const;

  Eigen::Vector3d centre_, half_extent_;
  double speed_, max_acceleration_, min_hold_, max_hold_;
  mutable std::mt19937_64 rng_;
  mutable std::vector<Sample> samples_;
  mutable double lateral_ = 0.0, vertical_ = 0.0;  ///< the current manoeuvre, in units of the limit
  mutable double hold_until_ = 0.0;
};

/// Playback of a recorded flight: CSV with a header and rows t,x,y,z (seconds, world metres),
/// interpolated linearly; holds the last point, or loops.
class RecordedFlight final : public Trajectory {
 public:
  /// Throws kestrel::Error naming the file and line of the first problem.
  RecordedFlight(const std::filesystem::path& csv, bool loop);
  /// The same from a stream; `label` names it in error messages.
  RecordedFlight(std::istream& csv, const std::string& label, bool loop);
  State at(double t) const override;
  double duration() const { return times_.back() - times_.front(); }

 private:
  void read(std::istream& csv, const std::string& label);

  std::vector<double> times_;
  std::vector<Eigen::Vector3d> points_;
  bool loop_;
};

/// Another trajectory placed in the world: turned by `yaw` (radians, about the world's z axis
/// through the origin), then moved by `offset`, and flown `time_scale` times as fast
/// (position(t) = R p(time_scale t) + offset; velocities scale with it).
class Placed final : public Trajectory {
 public:
  Placed(std::unique_ptr<Trajectory> inner, const Eigen::Vector3d& offset, double yaw, double time_scale);
  State at(double t) const override;

 private:
  std::unique_ptr<Trajectory> inner_;
  Eigen::Matrix3d rotation_;
  Eigen::Vector3d offset_;
  double time_scale_;
};

}  // namespace kestrel::intruder
