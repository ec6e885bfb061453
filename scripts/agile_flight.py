#!/usr/bin/env python3
"""Agile intruder flights: the capture benchmark's second generator, for its held-out family `agile`.

  agile_flight.py SEED TOP_SPEED MAX_ACCELERATION FILE [--duration S]
                                        writes one flight as CSV (t,x,y,z: s, world m), as the
                                        intruder's `shape: file` plays it

A point mass within a speed and an acceleration limit that switches every 0.6 to 2.5 s between
manoeuvres the tuning shapes (figure-8, line, random, jink, evade) do not fly:

  turn     a coordinated turn at 60-100 % of the top speed, as tight as the acceleration allows
  dash     a dash at the top speed in any direction, then a full stop
  zigzag   a zigzag about a heading, reversed every 0.25-0.5 s
  spiral   a climbing or sinking turn
  hover    a stop, held

It is fenced into a box 4 to 16 m ahead of the hunter's start (x forward, y left, z up), turning
back when the distance it needs to stop would take it out; it never reacts to the hunter.

Frozen: written before any tuning on what it draws, so that the aim is judged on flights it was not
chosen on. A flight is a pure function of its arguments; tests/scripts/check_agile_flight.sh holds
the digest of a few flights, and a change to them fails it. Change nothing here but its comments: a
new generator is a new family.
"""
import math
import random
import sys

FENCE_LOW = (4.0, -5.0, 1.5)  # m: the box the flight stays in (world; the hunter starts at the origin)
FENCE_HIGH = (16.0, 5.0, 5.0)
STEP_S = 0.01  # integration and output step
RESPONSE_S = 0.15  # how quickly the point mass takes up a wanted velocity (within its acceleration limit)
MANOEUVRES = ("turn", "dash", "zigzag", "spiral", "hover")


def _clip_norm(v, limit):
    n = math.sqrt(sum(x * x for x in v))
    return v if n <= limit or n == 0.0 else [x * limit / n for x in v]


def _heading(v, rng):
    return math.atan2(v[1], v[0]) if math.hypot(v[0], v[1]) > 0.3 else rng.uniform(-math.pi, math.pi)


class _Manoeuvre:
    """One manoeuvre: the velocity it wants at time t after its start."""

    def __init__(self, kind, rng, velocity, top_speed, max_acceleration):
        self.kind = kind
        self.hold_s = rng.uniform(0.6, 2.5)
        heading = _heading(velocity, rng)
        if kind in ("turn", "spiral"):
            self.speed = rng.uniform(0.6, 1.0) * top_speed
            lateral = rng.uniform(0.5, 0.9) * max_acceleration  # centripetal
            self.rate = min(3.0, lateral / max(self.speed, 0.5)) * rng.choice((-1.0, 1.0))
            self.climb = rng.uniform(0.5, 1.5) * rng.choice((-1.0, 1.0)) if kind == "spiral" else 0.0
            self.heading = heading
        elif kind == "dash":
            azimuth, elevation = rng.uniform(-math.pi, math.pi), rng.uniform(-0.3, 0.3)
            self.direction = (math.cos(elevation) * math.cos(azimuth), math.cos(elevation) * math.sin(azimuth),
                              math.sin(elevation))
            self.speed = top_speed
            self.stop_at = rng.uniform(0.4, 0.7) * self.hold_s
        elif kind == "zigzag":
            self.speed = rng.uniform(0.6, 1.0) * top_speed
            self.heading = heading
            self.swing = rng.uniform(0.5, 1.0)  # rad either side of the heading
            self.leg_s = rng.uniform(0.25, 0.5)

    def wanted(self, t):
        if self.kind in ("turn", "spiral"):
            h = self.heading + self.rate * t
            return [self.speed * math.cos(h), self.speed * math.sin(h), self.climb]
        if self.kind == "dash":
            return [self.speed * d for d in self.direction] if t < self.stop_at else [0.0, 0.0, 0.0]
        if self.kind == "zigzag":
            side = 1.0 if int(t / self.leg_s) % 2 == 0 else -1.0
            h = self.heading + side * self.swing
            return [self.speed * math.cos(h), self.speed * math.sin(h), 0.0]
        return [0.0, 0.0, 0.0]


def _fenced(position, velocity, wanted, top_speed, max_acceleration):
    """The wanted velocity turned back on each axis where stopping would leave the fence."""
    out = list(wanted)
    for axis in range(3):
        v = velocity[axis]
        stop = position[axis] + v * abs(v) / (2.0 * max_acceleration)
        margin = 0.5
        if stop > FENCE_HIGH[axis] - margin and out[axis] >= 0.0:
            out[axis] = -0.5 * top_speed if position[axis] > FENCE_HIGH[axis] - margin else min(out[axis], 0.0)
        elif stop < FENCE_LOW[axis] + margin and out[axis] <= 0.0:
            out[axis] = 0.5 * top_speed if position[axis] < FENCE_LOW[axis] + margin else max(out[axis], 0.0)
    return out


def flight(seed, top_speed, max_acceleration, duration_s=40.0):
    """The flight's rows (t, x, y, z), every STEP_S from 0 to duration_s."""
    rng = random.Random(seed * 104729 + 3)
    position = [rng.uniform(5.0, 9.0), rng.uniform(-1.5, 1.5), rng.uniform(2.0, 3.0)]
    velocity = [0.0, 0.0, 0.0]
    manoeuvre, started = None, 0.0
    rows = []
    steps = int(round(duration_s / STEP_S))
    for k in range(steps + 1):
        t = k * STEP_S
        rows.append((t, *position))
        if manoeuvre is None or t - started >= manoeuvre.hold_s:
            manoeuvre = _Manoeuvre(rng.choice(MANOEUVRES), rng, velocity, top_speed, max_acceleration)
            started = t
        wanted = _fenced(position, velocity, _clip_norm(manoeuvre.wanted(t - started), top_speed), top_speed,
                         max_acceleration)
        acceleration = _clip_norm([(w - v) / RESPONSE_S for w, v in zip(wanted, velocity)], max_acceleration)
        velocity = _clip_norm([v + a * STEP_S for v, a in zip(velocity, acceleration)], top_speed)
        position = [p + v * STEP_S for p, v in zip(position, velocity)]
    return rows


def write_csv(path, rows):
    with open(path, "w") as f:
        f.write("t,x,y,z\n")
        for t, x, y, z in rows:
            f.write(f"{t:.2f},{x:.3f},{y:.3f},{z:.3f}\n")


def main(argv):
    import argparse
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("seed", type=int)
    parser.add_argument("top_speed", type=float, help="m/s")
    parser.add_argument("max_acceleration", type=float, help="m/s^2")
    parser.add_argument("file")
    parser.add_argument("--duration", type=float, default=40.0, help="s")
    a = parser.parse_args(argv[1:])
    if not (a.top_speed > 0.0 and a.max_acceleration > 0.0 and a.duration > 0.0):
        raise SystemExit("agile_flight.py: top speed, acceleration and duration must be positive")
    write_csv(a.file, flight(a.seed, a.top_speed, a.max_acceleration, a.duration))


if __name__ == "__main__":
    main(sys.argv)
