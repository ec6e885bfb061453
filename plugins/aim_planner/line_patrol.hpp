#pragma once
// A target that flies a line back and forth (a patrol) turns round at each end, slowing to rest
// there. Chased across the line at its cruise, it crosses the net's opening in a tenth of a
// second; waited for beyond an end, facing along the line, it comes straight at the net and stops
// where the net opens. The patrol is found from the recent sightings: their principal direction,
// how far they lie off it, and the ends where the target was seen to turn.
#include <Eigen/Core>
#include <array>
#include <deque>
#include <optional>

namespace kestrel::aim {

struct LinePatrolConfig {
  double window_s = 8.0;         ///< the sightings the line is fitted to
  double min_length_m = 3.0;     ///< a shorter line is no patrol worth waiting at the end of
  double max_residual_m = 0.12;  ///< RMS distance of the sightings off the line (a figure-8 0.5 m high lies 0.18 m off)
  double turn_m = 1.0;           ///< a turn at an end: the target came from and went back this far
  double max_gap_s = 0.5;        ///< ... seen all the while, without a longer break
  int min_sightings = 45;
};

/// The line fitted to the sightings: centre + s direction, s in [-half_length, half_length].
struct PatrolLine {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit
  double half_length_m = 0.0;
  double rms_residual_m = 0.0;
  std::array<bool, 2> turned{};    ///< a turn seen at the end towards -direction [0], +direction [1]
  double deceleration_m_s2 = 0.0;  ///< how hard it brakes into its turns (the median of those seen)
  double cruise_speed_m_s = 0.0;   ///< its speed along the line between the turns
  Eigen::Vector3d end(int index) const { return centre + (index == 0 ? -half_length_m : half_length_m) * direction; }
  /// The distance of a point from the line (infinite beyond an end where it turned by more than
  /// `slack_m`).
  double distance(const Eigen::Vector3d& p, double slack_m) const;
  /// Where a target at `position` with `velocity` is `tau` seconds on: along the line it speeds up
  /// to its cruise, brakes as its turns showed (at most `max_deceleration_m_s2`) to rest at the end
  /// it flies towards, and turns back, as a patrol does; across the line it keeps its offset.
  Eigen::Vector3d predict(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, double tau,
                          double max_deceleration_m_s2) const;
};

class LinePatrol {
 public:
  explicit LinePatrol(const LinePatrolConfig& config) : cfg_(config) {}
  /// A sighting at time t (s, increasing). The line is fitted again.
  void add(double t, const Eigen::Vector3d& sighting);
  /// The patrol, once the sightings lie on a line long enough and the target has turned at an end;
  /// kept, once found, until reset().
  const std::optional<PatrolLine>& line() const { return line_; }
  /// The time of the newest sighting (none before the first).
  std::optional<double> last_sighting_s() const;
  void reset();

 private:
  void fit();
  std::optional<PatrolLine> fit_window() const;

  LinePatrolConfig cfg_;
  struct Sighting {
    double t;
    Eigen::Vector3d position;
  };
  std::deque<Sighting> window_;
  std::optional<PatrolLine> line_;
};

/// Where to wait for a patrol: beyond the end `end_index`, facing along the line, `standoff_m`
/// out from it (horizontally), so that the end is straight ahead of the camera.
/// Returns the point to look from; the aim pose puts the end at x_E^d as seen from there.
Eigen::Vector3d patrol_lookout(const PatrolLine& line, int end_index, double standoff_m);

}  // namespace kestrel::aim
