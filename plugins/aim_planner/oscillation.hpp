#pragma once
// The target as an oscillator, axis by axis: a figure-8, an orbit, a patrol or a line flown back
// and forth swings about a centre, p(t) = c + A cos(omega t) + B sin(omega t). Fitted to the last
// `window_s` of sightings (least squares for c, A and B on a grid of omega), it predicts the turn
// that the constant-velocity and constant-acceleration predictions cannot: on the capture
// benchmark's figure-8s at 3-6 m/s the position 0.55 s ahead comes within 0.4 m 99 % of the time,
// against 10 % at constant velocity (docs/control.md). An axis is taken to oscillate only where the
// sinusoid fits its sightings at least `min_improvement` times better than a parabola (constant
// acceleration) does; elsewhere there is no fit and the caller predicts as it would without one.
#include <Eigen/Core>
#include <array>
#include <deque>
#include <limits>
#include <optional>

namespace kestrel::aim {

struct OscillationConfig {
  double window_s = 2.5;         ///< the sightings the fit uses
  double min_omega_rad_s = 0.5;  ///< the grid of angular frequencies, from
  double max_omega_rad_s = 8.0;  ///< to
  double min_improvement = 2.0;  ///< the sinusoid's mean squared residual, times this, below the parabola's
  int min_sightings = 15;        ///< fewer in the window: no fit
};

/// One axis's oscillation, p(t) = centre + a cos(omega (t - t_ref)) + b sin(omega (t - t_ref)), with
/// t_ref the newest sighting's time.
struct AxisOscillation {
  double centre = 0.0, a = 0.0, b = 0.0;
  double omega_rad_s = 0.0;
  double rms_residual_m = 0.0;
};

class OscillationPredictor {
 public:
  explicit OscillationPredictor(const OscillationConfig& config);
  /// A sighting at time t (s, increasing); the fit is made again.
  void add(double t, const Eigen::Vector3d& sighting);
  /// Each axis's oscillation, none where the sightings are too few or no sinusoid fits them better than a
  /// parabola.
  const std::array<std::optional<AxisOscillation>, 3>& axes() const { return axes_; }
  /// An oscillating axis's position `tau` seconds after the newest sighting.
  static double position_after(const AxisOscillation& axis, double tau);
  /// Where the target is expected `tau` seconds after the newest sighting: on the oscillating axes,
  /// the oscillation's prediction; on the others, `elsewhere`'s (the caller's own prediction).
  Eigen::Vector3d predict(double tau, Eigen::Vector3d elsewhere) const;

 private:
  void fit();

  OscillationConfig cfg_;
  struct Sighting {
    double t;
    Eigen::Vector3d position;
  };
  std::deque<Sighting> window_;
  std::array<std::optional<AxisOscillation>, 3> axes_;
};

/// The aim that waits at the centre of a wide swing: a figure-8 or a line flown back and forth
/// faster than the hunter can turn with is caught where it comes through, not chased. On each axis
/// that oscillates by min_amplitude_m to max_amplitude_m, as a sinusoid within max_residual_m
/// (RMS; a line flown back and forth at a cruise is no sinusoid, and its crossing is mistimed),
/// the target's position is replaced by the swing's centre and its velocity by zero; elsewhere
/// they are the target's own.
struct SwingAim {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  std::array<bool, 3> waiting{};  ///< the axes aimed at the swing's centre
};
struct SwingBounds {
  double min_amplitude_m = 1.0;
  double max_amplitude_m = 4.0;
  double max_residual_m = 0.1;
  /// The fastest swing waited for (its peak speed, sqrt(sum (amplitude omega)^2) over the swinging
  /// axes): a faster one crosses the net's opening too quickly for the timing the fit gives, and is
  /// followed, which brings the relative speed down.
  double max_speed_m_s = std::numeric_limits<double>::infinity();
};
SwingAim swing_centre_aim(const OscillationPredictor& oscillation, const Eigen::Vector3d& position,
                          const Eigen::Vector3d& velocity, const SwingBounds& bounds);

}  // namespace kestrel::aim
