#!/usr/bin/env python3
"""Import recorded drone flights from public repositories into intruder CSVs.

Each output file is a CSV with the header ``t,x,y,z`` (seconds, metres) in a
right-handed, z-up world frame, sampled at 20 Hz, starting at t = 0, recentred
so that the horizontal bounding-box centre is at x = y = 0 and the lowest point
is at z = 0.  The kestrel intruder plays it with ``file:`` and linear
interpolation (see plugins/intruder_trajectory); the benchmark places and lifts
it.

Only the Python 3 standard library is used (numpy is not required).

Sources (repository, commit, path, licence and kind) are listed in SOURCES
below and in README.md.  The raw files are read straight out of git with
``git show <commit>:<path>``, so a clone of each repository is needed.  The
required option ``--repos`` names a folder holding clones of the repositories,
in any of these layouts::

    <repos>/<owner>+<name>/repo      (bare or with .git inside)
    <repos>/<owner>+<name>
    <repos>/<owner>/<name>
    <repos>/<name>

e.g. ``git clone https://github.com/PX4/flight-review-rs <repos>/PX4/flight-review-rs``.

Usage::

    python3 bench/flights/import_flights.py --repos DIR          # writes into bench/flights/
    python3 bench/flights/import_flights.py --repos DIR --out DIR --stats

Conversion, per source:

* Parse the native format (ULog for PX4 v1.x, sdlog2 ".px4log" for old PX4,
  CSV for the Gazebo/PX4-SITL runs).  The ULog and sdlog2 readers below were
  written from the published format descriptions (docs.px4.io "ULog File
  Format"; the sdlog2 FMT message layout) and read only what is needed here.
* Frame: PX4 logs are NED (x north, y east, z down); they become
  x = north, y = -east (west), z = -down (up).  The Gazebo ENU frame is already
  right-handed and z-up and is kept as it is.
* The noisy height of the 2016 sdlog2 log is smoothed over 0.5 s (z only).
* Airborne part only: from the land detector where the log has one, intersected
  with "more than 0.5 m above the pre-take-off ground level"; data gaps over
  1 s end a flight; leading/trailing stretches slower than 0.2 m/s are trimmed.
* Resample to 20 Hz by linear interpolation, cut flights longer than 60 s into
  equal segments of 30-60 s, drop anything shorter than 20 s, recentre, write
  with 3 decimals.
"""

import argparse
import bisect
import csv
import io
import math
import os
import struct
import subprocess
import sys

RATE_HZ = 20.0
MIN_SEGMENT_S = 20.0
MAX_SEGMENT_S = 60.0
AIRBORNE_HEIGHT_M = 0.5
STILL_SPEED_MPS = 0.2
MAX_GAP_S = 1.0

# --------------------------------------------------------------------------------------------
# Sources.  'smooth_z_s' (optional) smooths z with a centred moving average of that length.
# --------------------------------------------------------------------------------------------
SOURCES = [
    dict(name='px4_fmuv2_gps_2016',
         repo='dronecrew/px4tools', commit='ff33b269c58691a6f2de9de006f73c5bdda60658',
         paths=['test/log/01_07_59.px4log'], fmt='px4log',
         licence='BSD-3-Clause (repository LICENSE)',
         kind='autopilot estimate (PX4 EKF, GPS, outdoor; PX4FMU-v2 hardware)',
         smooth_z_s=0.5,
         note='PX4 sdlog2 log used as a test fixture by px4tools; LPOS (local NED) at ~80 Hz. '
              'Its height estimate jitters by up to 1 m from sample to sample, so z (only) is '
              'smoothed with a centred 0.5 s moving average.'),
    dict(name='px4_fmuv6c_lowbatt',
         repo='PX4/flight-review-rs', commit='0b1d5ee209e3b4ccfb30d91b675a9f7e8c484ad8',
         paths=['crates/converter/tests/fixtures/battery_brownout.ulg'], fmt='ulog',
         licence='MIT (repository README/Cargo); fixture is a real flight (commit 9ca6321 '
                 '"real-world ULog fixtures"); PX4 Flight Review public logs are CC-BY 4.0',
         kind='autopilot estimate (PX4 EKF2, Pixhawk 6C hardware)',
         note='Slow manual/position-mode flight ending in a low-battery landing; '
              'vehicle_local_position at 10 Hz.'),
] + [
    dict(name='px4sitl_gazebo_%s' % k,
         repo='mzahana/drone_trajectories', commit='479b4144033d053922bad98b5c096c2e9bc4ea3f',
         paths=['trajectories/gazebo/%s_df_resampled.csv' % k], fmt='xyz_csv',
         licence='BSD-3-Clause (repository LICENSE)',
         kind='SITL (PX4 autopilot flying in Gazebo; released at 10 Hz)',
         note='One of the PX4-Gazebo flights of the VECTOR paper (Drones 9(1):8, 2025); '
              'the repository does not say what C/I/R stand for.')
    for k in ('C1', 'C2', 'C3', 'I1', 'I2', 'R1')
]


# --------------------------------------------------------------------------------------------
# Reading raw files out of git.
# --------------------------------------------------------------------------------------------
def find_git_dir(root, repo):
    owner, name = repo.split('/')
    for cand in (os.path.join(root, owner + '+' + name, 'repo'), os.path.join(root, owner + '+' + name),
                 os.path.join(root, owner, name), os.path.join(root, name)):
        for d in (os.path.join(cand, '.git'), cand):
            if os.path.isdir(d) and os.path.exists(os.path.join(d, 'HEAD')):
                return d
    return None


def git_blob(root, repo, commit, path):
    d = find_git_dir(root, repo)
    if d is None:
        raise SystemExit('no clone of %s under %s: git clone https://github.com/%s %s/%s'
                         % (repo, root, repo, root, repo))
    return subprocess.run(['git', '--git-dir', d, 'show', '%s:%s' % (commit, path)],
                          check=True, stdout=subprocess.PIPE).stdout


# --------------------------------------------------------------------------------------------
# ULog (PX4 >= 1.5).  File = 16-byte header ("ULog" 0x01 0x12 0x35, version, start time), then
# messages: uint16 size, uint8 type, payload.  'F' defines a format "name:type field;...",
# 'A' subscribes (multi_id, msg_id, name), 'D' carries data (msg_id + packed fields).
# --------------------------------------------------------------------------------------------
ULOG_TYPES = {'int8_t': ('b', 1), 'uint8_t': ('B', 1), 'int16_t': ('h', 2), 'uint16_t': ('H', 2),
              'int32_t': ('i', 4), 'uint32_t': ('I', 4), 'int64_t': ('q', 8), 'uint64_t': ('Q', 8),
              'float': ('f', 4), 'double': ('d', 8), 'bool': ('?', 1), 'char': ('c', 1)}


def read_ulog(blob, topics):
    """Return {(topic, multi_id): [dict(field -> value)]} for the requested fields."""
    if blob[:7] != b'ULog\x01\x12\x35':
        raise ValueError('not a ULog file')
    formats, subs, out = {}, {}, {}

    def size_of(t):
        count = 1
        if t.endswith(']'):
            t, n = t[:-1].split('[')
            count = int(n)
        if t in ULOG_TYPES:
            return ULOG_TYPES[t][1] * count
        return sum(size_of(ft) for ft, _ in formats[t]) * count

    def offsets(name):
        off, table = 0, {}
        for ft, fn in formats[name]:
            if ft in ULOG_TYPES:
                table[fn] = (off, '<' + ULOG_TYPES[ft][0])
            off += size_of(ft)
        return table

    pos = 16
    while pos + 3 <= len(blob):
        size, mtype = struct.unpack_from('<HB', blob, pos)
        pos += 3
        body = blob[pos:pos + size]
        pos += size
        if len(body) < size:
            break
        if mtype == ord('F'):
            name, fields = body.decode('ascii', 'replace').split(':', 1)
            formats[name] = [tuple(f.split(' ', 1)) for f in fields.split(';') if f]
        elif mtype == ord('A'):
            multi, msg_id = struct.unpack_from('<BH', body, 0)
            name = body[3:].decode('ascii', 'replace')
            if name in topics:
                table = offsets(name)
                subs[msg_id] = (name, multi, [(f, table[f]) for f in topics[name] if f in table])
                out.setdefault((name, multi), [])
        elif mtype == ord('D') and size >= 2:
            msg_id, = struct.unpack_from('<H', body, 0)
            if msg_id in subs:
                name, multi, fields = subs[msg_id]
                try:
                    out[(name, multi)].append({f: struct.unpack_from(c, body, 2 + o)[0]
                                               for f, (o, c) in fields})
                except struct.error:
                    pass  # a damaged message
    return out


def ulog_track(blob):
    """Time (s), NED->z-up positions, and landed intervals from a ULog file."""
    fields = ['timestamp', 'x', 'y', 'z', 'xy_valid', 'z_valid']
    data = read_ulog(blob, {'vehicle_local_position': fields,
                            'vehicle_land_detected': ['timestamp', 'landed']})
    lp = sorted(data.get(('vehicle_local_position', 0), []), key=lambda r: r['timestamp'])
    rows = []
    for r in lp:
        if not (r.get('xy_valid', True) and r.get('z_valid', True)
                and all(math.isfinite(r[k]) for k in ('x', 'y', 'z'))):
            continue
        rows.append((r['timestamp'] * 1e-6, r['x'], -r['y'], -r['z']))
    landed = [(r['timestamp'] * 1e-6, bool(r['landed'])) for r in data.get(('vehicle_land_detected', 0), [])]
    return rows, landed


# --------------------------------------------------------------------------------------------
# sdlog2 (".px4log", PX4 before ULog).  Messages start with 0xA3 0x95 and a type byte; type 0x80
# (FMT, 89 bytes) defines other types: type, length, 4-char name, 16-char format, 64-char
# comma-separated labels.  TIME.StartTime (us) stamps the messages that follow it.
# --------------------------------------------------------------------------------------------
SDLOG2_CODES = {'b': 'b', 'B': 'B', 'h': 'h', 'H': 'H', 'i': 'i', 'I': 'I', 'f': 'f', 'n': '4s',
                'N': '16s', 'Z': '64s', 'c': 'h', 'C': 'H', 'e': 'i', 'E': 'I', 'L': 'i', 'M': 'B',
                'q': 'q', 'Q': 'Q'}


def px4log_track(blob):
    fmts = {0x80: ('FMT', 89, '<BB4s16s64s', None)}
    pos, now = 0, None
    rows, landed = [], []
    while pos + 3 <= len(blob):
        if blob[pos] != 0xA3 or blob[pos + 1] != 0x95 or blob[pos + 2] not in fmts:
            pos += 1
            continue
        name, length, code, labels = fmts[blob[pos + 2]]
        if pos + length > len(blob):
            break
        values = struct.unpack_from(code, blob, pos + 3)
        pos += length
        if name == 'FMT':
            mtype, mlen, mname, mfmt, mlabels = values
            mfmt = mfmt.rstrip(b'\0').decode('ascii')
            fmts[mtype] = (mname.rstrip(b'\0').decode('ascii'), mlen,
                           '<' + ''.join(SDLOG2_CODES[c] for c in mfmt),
                           mlabels.rstrip(b'\0').decode('ascii').split(','))
            continue
        rec = dict(zip(labels, values))
        if name == 'TIME':
            now = rec['StartTime'] * 1e-6
        elif now is None:
            continue
        elif name == 'LPOS':
            if all(math.isfinite(rec[k]) for k in ('X', 'Y', 'Z')):
                rows.append((now, rec['X'], -rec['Y'], -rec['Z']))
        elif name == 'STAT':
            landed.append((now, bool(rec['Landed'])))
    return rows, landed


# --------------------------------------------------------------------------------------------
# Text format.
# --------------------------------------------------------------------------------------------
def xyz_csv_track(blob):
    """CSV with columns timestamp,tx,ty,tz,... (seconds, metres, Gazebo ENU)."""
    reader = csv.DictReader(io.StringIO(blob.decode('ascii')))
    return [(float(r['timestamp']), float(r['tx']), float(r['ty']), float(r['tz'])) for r in reader], []


PARSERS = {'ulog': ulog_track, 'px4log': px4log_track, 'xyz_csv': xyz_csv_track}


# --------------------------------------------------------------------------------------------
# Processing.
# --------------------------------------------------------------------------------------------
def clean(rows):
    rows = sorted(rows)
    out = []
    for r in rows:
        if not out or r[0] > out[-1][0] + 1e-6:
            out.append(r)
    return out


def split_at_gaps(rows):
    pieces, cur = [], []
    for r in rows:
        if cur and r[0] - cur[-1][0] > MAX_GAP_S:
            pieces.append(cur)
            cur = []
        cur.append(r)
    if cur:
        pieces.append(cur)
    return pieces


def airborne(rows, landed):
    """The part of a contiguous stream where the vehicle flies."""
    if not rows:
        return rows
    if landed:
        lt = [t for t, _ in landed]

        def is_landed(t):
            i = bisect.bisect_right(lt, t) - 1
            return landed[max(i, 0)][1]
    else:
        def is_landed(t):
            return False
    # Ground level: the median height while the land detector says landed before take-off.
    ground_z = [r[3] for r in rows if is_landed(r[0])]
    if ground_z:
        ground_z.sort()
        ground = ground_z[len(ground_z) // 2]
        flying = [not is_landed(r[0]) and r[3] - ground > AIRBORNE_HEIGHT_M for r in rows]
    else:
        flying = [True] * len(rows)  # no detector and no ground phase: the stream starts in the air
    idx = [i for i, f in enumerate(flying) if f]
    if not idx:
        return []
    return rows[idx[0]:idx[-1] + 1]


def smooth_z(rows, window_s):
    """Centred moving average of z over window_s seconds (native samples), for noisy height."""
    if not window_s:
        return rows
    ts = [r[0] for r in rows]
    out = []
    for i, r in enumerate(rows):
        lo = bisect.bisect_left(ts, r[0] - window_s / 2)
        hi = bisect.bisect_right(ts, r[0] + window_s / 2)
        out.append((r[0], r[1], r[2], sum(q[3] for q in rows[lo:hi]) / (hi - lo)))
    return out


def resample(rows, rate=RATE_HZ):
    t0, t1 = rows[0][0], rows[-1][0]
    n = int(math.floor((t1 - t0) * rate + 1e-9)) + 1
    ts = [r[0] for r in rows]
    out, j = [], 0
    for k in range(n):
        t = t0 + k / rate
        while j + 1 < len(rows) - 1 and ts[j + 1] <= t:
            j += 1
        a, b = rows[j], rows[min(j + 1, len(rows) - 1)]
        f = 0.0 if b[0] == a[0] else min(max((t - a[0]) / (b[0] - a[0]), 0.0), 1.0)
        out.append((k / rate,) + tuple(a[i] + f * (b[i] - a[i]) for i in (1, 2, 3)))
    return out


def speeds(seg, half=2):
    """Speed (m/s) from a central difference over 2*half samples (0.2 s at 20 Hz)."""
    n, dt = len(seg), 1.0 / RATE_HZ
    out = []
    for i in range(n):
        a, b = seg[max(i - half, 0)], seg[min(i + half, n - 1)]
        span = (min(i + half, n - 1) - max(i - half, 0)) * dt
        out.append(math.dist(a[1:], b[1:]) / span if span > 0 else 0.0)
    return out


def trim_still(seg):
    v = speeds(seg)
    moving = [i for i, s in enumerate(v) if s >= STILL_SPEED_MPS]
    if not moving:
        return []
    return seg[moving[0]:moving[-1] + 1]


def split_segments(seg):
    dur = seg[-1][0] - seg[0][0]
    if dur < MIN_SEGMENT_S:
        return []
    n = max(1, int(math.ceil(dur / MAX_SEGMENT_S - 1e-9)))
    per = len(seg) // n
    return [seg[k * per:(k + 1) * per + 1] if k < n - 1 else seg[k * per:] for k in range(n)]


def recentre(seg):
    xs, ys, zs = [p[1] for p in seg], [p[2] for p in seg], [p[3] for p in seg]
    cx, cy, z0 = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, min(zs)
    t0 = seg[0][0]
    return [(p[0] - t0, p[1] - cx, p[2] - cy, p[3] - z0) for p in seg]


def stats(seg):
    dt = 1.0 / RATE_HZ
    v = speeds(seg)
    k = int(round(0.5 / dt))  # 0.5 s second difference
    acc = []
    for i in range(k, len(seg) - k):
        acc.append(math.sqrt(sum(((seg[i + k][j] - 2 * seg[i][j] + seg[i - k][j]) / (k * dt) ** 2) ** 2
                                 for j in (1, 2, 3))))
    sv = sorted(v)
    path = sum(math.dist(seg[i][1:], seg[i + 1][1:]) for i in range(len(seg) - 1))
    box = [max(p[j] for p in seg) - min(p[j] for p in seg) for j in (1, 2, 3)]
    return dict(duration=seg[-1][0] - seg[0][0], path=path, vmax=max(v), vmed=sv[len(sv) // 2],
                amax=max(acc) if acc else 0.0, box=box)


def original_rate(rows):
    if len(rows) < 2:
        return 0.0
    return (len(rows) - 1) / (rows[-1][0] - rows[0][0])


def process(src, root):
    rows, landed = [], []
    for path in src['paths']:
        r, l = PARSERS[src['fmt']](git_blob(root, src['repo'], src['commit'], path))
        rows += r
        landed += l
    rows = clean(rows)
    landed.sort()
    rate = original_rate(rows)
    pieces = split_at_gaps(rows)
    segments = []
    for piece in pieces:
        fly = airborne(piece, landed)
        if len(fly) < 2:
            continue
        fly = smooth_z(fly, src.get('smooth_z_s'))
        seg = trim_still(resample(fly))
        if len(seg) < 2:
            continue
        segments += split_segments(seg)
    return [recentre(s) for s in segments], rate


def write_csv(path, seg):
    with open(path, 'w', newline='\n') as f:
        f.write('t,x,y,z\n')
        for t, x, y, z in seg:
            f.write('%.3f,%.3f,%.3f,%.3f\n' % (t, x + 0.0, y + 0.0, z + 0.0))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--repos', required=True, help='a folder holding clones of the source repositories')
    ap.add_argument('--out', default=here, help='output folder (default: this script\'s folder)')
    ap.add_argument('--only', nargs='*', help='source names to import (default: all)')
    ap.add_argument('--skip', nargs='*', default=[], help='source names not to import')
    ap.add_argument('--stats', action='store_true', help='print a Markdown table of the written files')
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    table = []
    for src in SOURCES:
        if (args.only and src['name'] not in args.only) or src['name'] in args.skip:
            continue
        segments, rate = process(src, args.repos)
        for i, seg in enumerate(segments):
            fname = '%s_%d.csv' % (src['name'], i + 1) if len(segments) > 1 else src['name'] + '.csv'
            write_csv(os.path.join(args.out, fname), seg)
            # Statistics from the file as written (3 decimals), so they describe what is played.
            with open(os.path.join(args.out, fname)) as f:
                written = [tuple(map(float, l.split(','))) for l in f.read().splitlines()[1:]]
            table.append((fname, src, rate, stats(written)))
        print('%-28s %2d segment(s), source rate %.0f Hz' % (src['name'], len(segments), rate), file=sys.stderr)
    if args.stats:
        print('| file | source repository | licence | kind | source rate (Hz) | duration (s) | path (m) '
              '| peak speed (m/s) | median speed (m/s) | peak accel (m/s^2) | box x*y*z (m) |')
        print('|---|---|---|---|---|---|---|---|---|---|---|')
        for fname, src, rate, s in table:
            print('| %s | %s | %s | %s | %.0f | %.1f | %.0f | %.1f | %.1f | %.1f | %.1f x %.1f x %.1f |'
                  % (fname, src['repo'], src['licence'].split(' (')[0], src['kind'].split(' (')[0], rate,
                     s['duration'],
                     s['path'], s['vmax'], s['vmed'], s['amax'], s['box'][0], s['box'][1], s['box'][2]))


if __name__ == '__main__':
    main()
