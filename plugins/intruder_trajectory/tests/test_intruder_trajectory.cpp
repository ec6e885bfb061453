// Intruder trajectories against hand-computed positions, and the intruder node in a graph.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "evader.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "trajectory.hpp"

using namespace kestrel;
using namespace kestrel::intruder;

namespace {

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = 1e-9) {
  EXPECT_NEAR((a - b).norm(), 0.0, tol) << "got " << a.transpose() << ", expected " << b.transpose();
}

// Central differences of position must match the reported velocity.
void expect_consistent_velocity(const Trajectory& traj, double t) {
  const double h = 1e-5;
  const Eigen::Vector3d numeric = (traj.at(t + h).position - traj.at(t - h).position) / (2 * h);
  expect_near(traj.at(t).velocity, numeric, 1e-5);
}

std::filesystem::path write_csv(const std::string& name, const std::string& text) {
  const auto file = kestrel::testing::scratch_path(name);
  std::ofstream(file) << text;
  return file;
}

}  // namespace

TEST(FigureEight, LiesInThePlaneNormalToTheOpticalAxis) {
  const auto camera = geometry::level_camera({0, 0, 2}, 0.0);  // looking along world +x
  const FigureEight f(camera, 5.0, 1.0, 0.5, 12.0);
  expect_near(f.at(0.0).position, {5, 0, 2});                  // centre
  expect_near(f.at(3.0).position, {5, -1, 2});                 // quarter: 1 m right
  expect_near(f.at(1.5).position, {5, -std::sqrt(0.5), 1.5});  // 0.5 m down
  expect_near(f.at(4.5).position, {5, -std::sqrt(0.5), 2.5});  // 0.5 m up
  expect_near(f.at(12.0).position, f.at(0.0).position);        // periodic
  for (double t : {0.0, 1.0, 2.7, 8.1}) {
    EXPECT_NEAR(camera.to_camera(f.at(t).position).z(), 5.0, 1e-12);
    expect_consistent_velocity(f, t);
  }
  const auto turned = geometry::level_camera({0, 0, 2}, M_PI / 2);  // looking along world +y
  expect_near(FigureEight(turned, 2.5, 1.0, 0.5, 12.0).at(0.0).position, {0, 2.5, 2});
}

TEST(StraightLine, HoldsOrBouncesAtTheEnd) {
  const StraightLine hold({0, 0, 0}, {4, 0, 0}, 2.0, false);
  expect_near(hold.at(1.0).position, {2, 0, 0});
  expect_near(hold.at(1.0).velocity, {2, 0, 0});
  expect_near(hold.at(3.0).position, {4, 0, 0});
  expect_near(hold.at(3.0).velocity, {0, 0, 0});
  const StraightLine bounce({0, 0, 0}, {4, 0, 0}, 2.0, true);
  expect_near(bounce.at(3.0).position, {2, 0, 0});
  expect_near(bounce.at(3.0).velocity, {-2, 0, 0});
  expect_near(bounce.at(5.0).position, {2, 0, 0});
  expect_near(bounce.at(5.0).velocity, {2, 0, 0});
}

// A line of 6 m at 2 m/s with 2 m/s^2 at the ends: 1 s up to speed over 1 m, 2 s at speed over
// 4 m, 1 s down to rest over 1 m; a pass takes 4 s.
TEST(StraightLine, WithAnAccelerationItStartsAndTurnsAsAMultirotorCan) {
  const StraightLine line({0, 0, 0}, {6, 0, 0}, 2.0, true, 2.0);
  expect_near(line.at(0.0).position, {0, 0, 0});
  expect_near(line.at(0.0).velocity, {0, 0, 0});
  expect_near(line.at(0.5).position, {0.25, 0, 0});
  expect_near(line.at(0.5).velocity, {1, 0, 0});
  expect_near(line.at(2.0).position, {3, 0, 0});
  expect_near(line.at(2.0).velocity, {2, 0, 0});
  expect_near(line.at(3.5).position, {5.75, 0, 0});
  expect_near(line.at(3.5).velocity, {1, 0, 0});
  expect_near(line.at(4.0).position, {6, 0, 0});  // at rest at the end...
  expect_near(line.at(4.0).velocity, {0, 0, 0});
  expect_near(line.at(4.5).position, {5.75, 0, 0});  // ...and back
  expect_near(line.at(4.5).velocity, {-1, 0, 0});
  expect_near(line.at(8.0).position, {0, 0, 0});
  // Position and velocity agree (velocity is the derivative), and no step exceeds the acceleration.
  for (double t = 0.0; t < 16.0; t += 0.01) {
    const State a = line.at(t), b = line.at(t + 0.01);
    EXPECT_NEAR((b.position - a.position).x() / 0.01, 0.5 * (a.velocity + b.velocity).x(), 1e-6) << t;
    EXPECT_LE((b.velocity - a.velocity).norm() / 0.01, 2.0 + 1e-6) << t;
  }
  // Too short to reach the speed: a triangle, peaking at sqrt(a L) = 1 m/s over 0.5 m.
  const StraightLine short_line({0, 0, 0}, {0.5, 0, 0}, 2.0, false, 2.0);
  expect_near(short_line.at(0.5).velocity, {1, 0, 0});
  expect_near(short_line.at(1.0).position, {0.5, 0, 0});
  expect_near(short_line.at(5.0).position, {0.5, 0, 0});
  expect_near(short_line.at(5.0).velocity, {0, 0, 0});
}

TEST(RandomManoeuvre, StaysInItsBoxUnderItsSpeedLimitAndReproduces) {
  const Eigen::Vector3d centre(5, 0, 2), half(1.0, 1.5, 0.75);
  const RandomManoeuvre a(centre, half, 3.0, 42), b(centre, half, 3.0, 42), c(centre, half, 3.0, 43);
  double max_speed = 0;
  for (double t = 0; t < 600; t += 0.05) {
    const State s = a.at(t);
    for (int i = 0; i < 3; ++i) EXPECT_LE(std::abs(s.position[i] - centre[i]), half[i] + 1e-9);
    max_speed = std::max(max_speed, s.velocity.norm());
    expect_near(s.position, b.at(t).position, 0.0);
  }
  EXPECT_LE(max_speed, 3.0 + 1e-9);
  EXPECT_GT(max_speed, 0.3);  // it does manoeuvre
  EXPECT_GT((a.at(10).position - c.at(10).position).norm(), 1e-3);
  expect_consistent_velocity(a, 17.3);
}

TEST(RandomManoeuvre, KeepsUnderItsAccelerationLimit) {
  // Quick manoeuvres (up to 0.5 Hz) in a wide box: without a limit they would pull more than 5 m/s^2.
  const Eigen::Vector3d centre(5.5, 0, 2), half(2.5, 1.5, 0.75);
  double unlimited = 0, limited = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const RandomManoeuvre free(centre, half, 3.0, seed, 0.0, 0.5), bounded(centre, half, 3.0, seed, 5.0, 0.5);
    for (double t = 0; t < 120; t += 0.01) {
      // Acceleration by central differences of the velocity.
      const auto accel = [&](const RandomManoeuvre& m) {
        return ((m.at(t + 1e-4).velocity - m.at(t - 1e-4).velocity) / 2e-4).norm();
      };
      unlimited = std::max(unlimited, accel(free));
      limited = std::max(limited, accel(bounded));
      EXPECT_LE(bounded.at(t).velocity.norm(), 3.0 + 1e-9);
    }
  }
  EXPECT_LE(limited, 5.0 + 1e-6);
  EXPECT_GT(limited, 2.0);    // it still manoeuvres hard
  EXPECT_GT(unlimited, 5.0);  // the limit did something
}

// Jinks at 6 m/s and 5 m/s^2: the speed holds, the acceleration stays within its limit on
// each of the two axes it acts on, it turns back into its box (leaving it by no more than a
// turn's diameter, 2 v^2 / a), it does jink, and the same seed flies the same path.
TEST(Jink, CruisesAtItsSpeedTurnsWithinItsLimitAndStaysNearItsBox) {
  const Eigen::Vector3d centre(8, 0, 3), half(4.0, 6.0, 1.0);
  const double v = 6.0, a = 5.0, turn = 2.0 * v * v / a;
  const Jink jink(centre, half, v, a, 0.5, 2.0, 7), same(centre, half, v, a, 0.5, 2.0, 7),
      other(centre, half, v, a, 0.5, 2.0, 8);
  double max_accel = 0.0, turned = 0.0;
  Eigen::Vector3d previous = jink.at(0.0).velocity;
  for (double t = 0.005; t < 120.0; t += 0.05) {
    const State s = jink.at(t);
    EXPECT_NEAR(s.velocity.norm(), v, 0.02) << t;
    EXPECT_LE(std::abs(s.velocity.z()), 0.5 * v + 1e-9);
    for (int i = 0; i < 2; ++i) EXPECT_LE(std::abs(s.position[i] - centre[i]), half[i] + turn) << t;
    EXPECT_LE(std::abs(s.position.z() - centre.z()), half.z() + v * v / (8.0 * a) + 0.05) << t;
    const Eigen::Vector3d accel = (jink.at(t + 0.002).velocity - jink.at(t - 0.002).velocity) / 0.004;
    max_accel = std::max(max_accel, accel.norm());
    turned += std::acos(std::clamp(previous.normalized().dot(s.velocity.normalized()), -1.0, 1.0));
    previous = s.velocity;
    expect_near(s.position, same.at(t).position, 0.0);
  }
  EXPECT_LE(max_accel, std::sqrt(2.0) * a + 0.1);
  EXPECT_GT(max_accel, 0.9 * a);
  EXPECT_GT(turned, 20.0);  // radians over two minutes: it jinks
  EXPECT_GT((jink.at(30.0).position - other.at(30.0).position).norm(), 0.5);
  expect_consistent_velocity(jink, 17.305);
  EXPECT_THROW(jink.at(4000.0), Error);
}

TEST(RecordedFlight, InterpolatesHoldsAndLoops) {
  const auto file = write_csv("kestrel-flight.csv", "t,x,y,z\n10,0,0,0\n12,2,0,0\n14,2,4,0\n");
  const RecordedFlight hold(file, false);
  expect_near(hold.at(1.0).position, {1, 0, 0});  // run time 1 s = file time 11 s
  expect_near(hold.at(1.0).velocity, {1, 0, 0});
  expect_near(hold.at(3.0).position, {2, 2, 0});
  expect_near(hold.at(10.0).position, {2, 4, 0});
  const RecordedFlight loop(file, true);
  expect_near(loop.at(5.0).position, {1, 0, 0});  // 5 s = one 4 s loop + 1 s
}

TEST(Placed, TurnsMovesAndSpeedsUpARecordedFlight) {
  const auto file = write_csv("kestrel-placed.csv", "t,x,y,z\n0,1,0,2\n2,3,0,2\n");
  // A quarter turn left, then 10 m ahead: (1, 0) becomes (0, 1), plus the offset; twice as fast.
  const Placed placed(std::make_unique<RecordedFlight>(file, false), {10, 0, 1}, M_PI / 2.0, 2.0);
  expect_near(placed.at(0.0).position, {10, 1, 3});
  expect_near(placed.at(0.5).position, {10, 2, 3});  // 0.5 s here is 1 s of the recording
  expect_near(placed.at(0.5).velocity, {0, 2, 0});   // 1 m/s recorded, turned, twice as fast
  expect_near(placed.at(5.0).position, {10, 3, 3});  // held at the end
  expect_consistent_velocity(placed, 0.3);
}

// A hunter far away, then 5 m away, then 1.5 m behind it wherever it goes: the evader cruises,
// then flees at its top speed, then breaks; within its limits throughout, and the same every time
// for a seed.
TEST(Evader, CruisesFleesAndBreaksWithinItsLimits) {
  EvaderParams p;
  p.centre = {10, 0, 3}, p.half_extent = {8, 8, 1};
  Evader evader(p.centre, p, 3), same(p.centre, p, 3);
  std::set<Evader::Mode> seen;
  double top = 0.0;
  State previous{p.centre, Eigen::Vector3d::Zero()};
  for (int k = 1; k <= 360; ++k) {  // 12 s at 30 Hz
    const double t = k / 30.0;
    const Eigen::Vector3d hunter = t < 3.0   ? Eigen::Vector3d(-30, 0, 3)
                                   : t < 8.0 ? Eigen::Vector3d(5, 0, 3)
                                             : Eigen::Vector3d(previous.position - Eigen::Vector3d(1.5, 0, 0));
    const State s = evader.step(t, hunter);
    expect_near(s.position, same.step(t, hunter).position, 0.0);
    seen.insert(evader.mode());
    if (t < 3.0 || t > 8.1) {
      EXPECT_EQ(evader.mode(), t < 3.0 ? Evader::Mode::cruise : Evader::Mode::break_away) << t;
    }
    top = std::max(top, s.velocity.norm());
    EXPECT_LE(s.velocity.norm(), p.top_speed + 1e-9);
    // 1/30 s apart (at most four of its 10 ms steps), the velocity changes at most by the
    // acceleration limit's worth.
    EXPECT_LE((s.velocity - previous.velocity).norm(), p.max_acceleration * 0.04 + 1e-9) << t;
    EXPECT_GE(s.position.z(), p.min_height - 0.1);
    previous = s;
  }
  EXPECT_EQ(seen.size(), 3u);  // cruise, flee, break
  EXPECT_GT(top, 0.9 * p.top_speed);
  // Without a hunter it only cruises, and stays near its box.
  Evader alone(p.centre, p, 4);
  for (int k = 1; k <= 900; ++k) {
    const State s = alone.step(k / 30.0, std::nullopt);
    EXPECT_EQ(alone.mode(), Evader::Mode::cruise);
    EXPECT_LE(s.velocity.norm(), p.cruise_speed + 1e-9);
    for (int i = 0; i < 3; ++i) EXPECT_LE(std::abs(s.position[i] - p.centre[i]), p.half_extent[i] + 0.5);
  }
}

// Fleeing, it opens the range: a hunter that stops 5 m away is left behind, and the evader, once
// out of the flee radius, cruises again.
TEST(Evader, FleesOutOfTheFleeRadius) {
  EvaderParams p;
  p.centre = {10, 0, 3}, p.half_extent = {8, 8, 1};
  Evader evader(p.centre, p, 5);
  const Eigen::Vector3d hunter(5, 0, 3);  // 5 m: within the 6 m flee radius
  evader.step(0.1, hunter);
  EXPECT_EQ(evader.mode(), Evader::Mode::flee);
  State s;
  for (int k = 1; k <= 90; ++k) s = evader.step(0.1 + k / 30.0, hunter);
  EXPECT_GT((s.position - hunter).norm(), p.flee_radius - 0.5);
}

TEST(RecordedFlight, BadFilesNameTheFileAndLine) {
  EXPECT_THAT(
      [] { RecordedFlight("/nonexistent/flight.csv", false); },
      ::testing::ThrowsMessage<Error>(::testing::HasSubstr("cannot open trajectory file /nonexistent/flight.csv")));
  const auto bad = write_csv("kestrel-bad.csv", "t,x,y,z\n0,0,0,0\n1,1,oops,0\n");
  EXPECT_THAT([&] { RecordedFlight(bad, false); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr(bad.string() + ":3: expected four numbers")));
  const auto backwards = write_csv("kestrel-backwards.csv", "0,0,0,0\n2,1,1,1\n1,1,1,1\n");
  EXPECT_THAT([&] { RecordedFlight(backwards, false); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr(":3: times must increase")));
  // Finite numbers whose differences overflow: an infinite duration, an infinite speed.
  std::istringstream huge("-1e308,-1e308,0,0\n1e308,1e308,0,0\n");
  EXPECT_THAT([&] { RecordedFlight(huge, "huge.csv", true); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("huge.csv:2: the time is too far")));
  std::istringstream tiny("0,0,0,0\n1e-320,1,0,0\n");
  EXPECT_THAT([&] { RecordedFlight(tiny, "tiny.csv", false); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("tiny.csv:2: the step from the previous row")));
}

TEST(IntruderNode, PublishesTruthAtItsRateAndThePlotIsWritten) {
  PluginHost& host = kestrel::testing::built_plugins();
  const auto dir = kestrel::testing::scratch_path("kestrel-intruder-plot");
  std::filesystem::remove_all(dir);
  const std::string yaml = R"(nodes:
  - {id: intruder, type: intruder, params: {rate_hz: 30, distance_m: 7.5}}
  - {id: plot, type: trajectory_plot}
connections:
  - {from: intruder.truth, to: plot.truth}
duration: 2.0
)";
  auto built = build_graph(GraphSource::from_string(yaml), host.registry());
  ASSERT_TRUE(built.graph) << built.diagnostics.str();
  RunOptions options;
  options.report_dir = dir;
  const auto r = run_graph(*built.graph, host.registry(), options);
  EXPECT_EQ(r.outcome, RunOutcome::completed);
  EXPECT_EQ(r.nodes[0].messages_out, 60u);
  EXPECT_TRUE(std::filesystem::exists(dir / "trajectory.png"));
  std::ifstream csv(dir / "trajectory.csv");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 61);  // header + 60 samples

  // A recorded flight that is missing stops the run before it starts, naming the node.
  auto missing = build_graph(
      GraphSource::from_string("nodes:\n  - {id: i, type: intruder, params: {shape: file, file: /no/such.csv}}\n"),
      host.registry());
  ASSERT_TRUE(missing.graph);
  const auto failed = run_graph(*missing.graph, host.registry());
  EXPECT_EQ(failed.outcome, RunOutcome::failed);
  EXPECT_THAT(failed.errors.at(0), ::testing::HasSubstr("node 'i' (intruder): could not start: cannot open"));
}
