#!/usr/bin/env python3
"""The report's feed error against the feed the run's STEP edges give.

Independent of the metrics library: it reads the run's VCD itself, interprets the G-code job itself (G0-G3, G20/G21,
G90/G91, X Y I J F) and measures each cutting move's feed from the edges, then compares it with the report's
per-move feed error (metrics.moves, matched by G-code line).

Edges to moves: the STEP rising edges (while the driver's active-low nENBL is low; DIR gives the sign, high = +
except on atmega, seed 003 sec. 5.2.5: DIR 0 = +) are walked in time order and the net step counts give the tool's
position on the step grid (origin 0,0, steps/mm from the report's scenario section).

- fpga-uart without its ramp, atmega (no planner): a move owns the edges from the end of the move before it until its position
  reaches the move's programmed end on the grid. Feed = programmed path length (an arc by its arc length) / (from
  its first edge to the latest over the axes of last edge + that edge's interval to the one before it, cut at the
  next move's first edge). The report rounds feed error to 1e-4 %: it must agree within 1.5e-4 %. A move whose
  position never lands on its end (an atmega axis that is not counted), or that has an axis with a single edge
  (its period is not in the trace), is not compared.
- spi-fpga (planner: ramps and blended corners) and fpga-uart with its ramps (fpga.ramp trapezoidal or s-curve: a
  planner in step_gen, ramps at every move): the middle half of a move, the edges after the move before's
  middle whose position lies within 0.05 mm of the move's path at 25 % to 75 % of its length (an arc: by angle
  from its start). Feed = path length between the first and last of those positions (projected onto the path) /
  the time between them. Where the move runs at constant feed (the two halves of the middle within 0.5 % of each
  other) the report's achieved feed must be within 1 % of it; a move without such a middle is not compared.

Usage: feed_from_edges.py CNCSIM ARCH WORKDIR [--require-all] SCENARIO...
  Runs each scenario (G-code jobs) on ARCH; each must run ok. --require-all: every cutting move must be compared
  (scenario/feed_from_edges.spi-fpga). invariants.py uses compare_feeds() on the runs it makes over every shipped
  scenario.
"""
import json
import math
import os
import re
import subprocess
import sys

STRICT_PCT = 1.5e-4   # the report's feed_error_pct is rounded to 1e-4 %
PLANNER_REL = 0.01    # with a planner: within 1 % of the edges' own feed
STEADY_REL = 0.005    # a middle whose halves differ by more is not at constant feed
PATH_TOL_MM = 0.05


def read_vcd(path):
    """{name: [(t_in_timescale_units, level)]} for 1-bit wires, and the timescale in ps."""
    ids, changes, t, scale_ps = {}, {}, 0, None
    units = {"fs": 1e-3, "ps": 1.0, "ns": 1e3, "us": 1e6, "ms": 1e9, "s": 1e12}
    with open(path) as f:
        text = f.read()
    head, _, body = text.partition("$enddefinitions")
    m = re.search(r"\$timescale\s+(\d+)\s*(\w+)\s+\$end", head)
    scale_ps = int(m.group(1)) * units[m.group(2)]
    for var in re.finditer(r"\$var\s+\w+\s+1\s+(\S+)\s+(\S+)", head):
        ids[var.group(1)] = var.group(2)
        changes[var.group(2)] = []
    for tok in body.split():
        if tok.startswith("#"):
            t = int(tok[1:])
        elif tok[0] in "01" and tok[1:] in ids:
            changes[ids[tok[1:]]].append((t, tok[0] == "1"))
    return changes, scale_ps


class Levels:
    """Level of one wire at non-decreasing times."""

    def __init__(self, changes):
        self.changes, self.k, self.level = changes, 0, False

    def at(self, t):
        while self.k < len(self.changes) and self.changes[self.k][0] <= t:
            self.level = self.changes[self.k][1]
            self.k += 1
        return self.level


def step_events(changes, scale_ps, arch):
    """[(t_ps, axis, sign)] of every counted STEP rising edge, in time order (x before y at one instant)."""
    events = []
    for axis, name in enumerate(("x", "y")):
        dirs, enbl = Levels(changes["dir_" + name]), Levels(changes["n_enbl_" + name])
        level = False
        for t, v in changes["step_" + name]:
            rising = v and not level
            level = v
            if not rising or enbl.at(t):
                continue
            high = dirs.at(t)
            positive = (not high) if arch == "atmega" else high
            events.append((t * scale_ps, axis, 1 if positive else -1))
    events.sort(key=lambda e: (e[0], e[1]))
    return events


def programmed_moves(job, feed_per_s):
    """[(line, kind, start, end, center, ccw, feed_mm_per_min)] of the XY moves of a G-code job."""
    pos, kind, feed, inch, absolute, moves = (0.0, 0.0), 0, 0.0, False, True, []
    with open(job, encoding="utf-8-sig") as f:
        for number, raw in enumerate(f.read().splitlines(), 1):
            line = re.sub(r"\([^)]*\)", "", raw.split(";")[0]).upper()
            words = {}
            motion = None
            for letter, value in re.findall(r"([A-Z])\s*([-+]?\d*\.?\d+)", line):
                v = float(value)
                if letter == "G":
                    g = int(round(v))
                    if g in (0, 1, 2, 3):
                        motion = g
                    elif g in (20, 21):
                        inch = g == 20
                    elif g in (90, 91):
                        absolute = g == 90
                else:
                    words[letter] = v
            k = 25.4 if inch else 1.0
            if "F" in words:
                feed = words["F"] * k * (60.0 if feed_per_s else 1.0)
            if motion is not None:
                kind = motion
            if "X" not in words and "Y" not in words:
                continue
            x = words.get("X", pos[0] / k if absolute else 0.0) * k
            y = words.get("Y", pos[1] / k if absolute else 0.0) * k
            end = (x, y) if absolute else (pos[0] + x, pos[1] + y)
            center = (pos[0] + words.get("I", 0.0) * k, pos[1] + words.get("J", 0.0) * k)
            if end != pos or kind in (2, 3):
                moves.append((number, kind, pos, end, center if kind in (2, 3) else None, kind == 3, feed))
            pos = end
    return moves


def arc_sweep(start, end, center, ccw):
    a0 = math.atan2(start[1] - center[1], start[0] - center[0])
    a1 = math.atan2(end[1] - center[1], end[0] - center[0])
    sweep = a1 - a0
    if ccw:
        while sweep <= 1e-12:
            sweep += 2 * math.pi
    else:
        while sweep >= -1e-12:
            sweep -= 2 * math.pi
    return sweep


def path_length(move):
    _, _, start, end, center, ccw, _ = move
    if center is None:
        return math.dist(start, end)
    return math.dist(start, center) * abs(arc_sweep(start, end, center, ccw))


def along(move, p):
    """(path coordinate of p in mm, distance of p from the path) for a line or an arc."""
    _, _, start, end, center, ccw, _ = move
    if center is None:
        length = math.dist(start, end)
        u = ((end[0] - start[0]) / length, (end[1] - start[1]) / length)
        s = (p[0] - start[0]) * u[0] + (p[1] - start[1]) * u[1]
        off = abs((p[0] - start[0]) * u[1] - (p[1] - start[1]) * u[0])
        return s, off
    r = math.dist(start, center)
    a0 = math.atan2(start[1] - center[1], start[0] - center[0])
    a = math.atan2(p[1] - center[1], p[0] - center[0])
    turn = (a - a0) if ccw else (a0 - a)
    turn %= 2 * math.pi
    return r * turn, abs(math.dist(p, center) - r)


def positions(events, spm):
    """[(t_ps, (x_mm, y_mm))] after every instant with edges."""
    out, count = [], [0, 0]
    for i, (t, axis, sign) in enumerate(events):
        count[axis] += sign
        if i + 1 < len(events) and events[i + 1][0] == t:
            continue
        out.append((t, (count[0] / spm[0], count[1] / spm[1])))
    return out


def strict_feeds(events, moves, spm):
    """{line: feed_mm_per_min} from the edges, for fpga-uart and atmega."""
    out, k, count = {}, 0, [0, 0]
    spans = []  # (move, first index, end index) into events
    for move in moves:
        target = [round(move[3][0] * spm[0]), round(move[3][1] * spm[1])]
        first = k
        if count == target and move[4] is None:
            spans.append((move, first, k))  # no step on the grid
            continue
        while k < len(events):
            t = events[k][0]
            while k < len(events) and events[k][0] == t:  # every edge of this instant
                count[events[k][1]] += events[k][2]
                k += 1
            if count == target:
                break
        if count != target:
            break  # the tool never landed on this move's end: the rest is not attributable
        spans.append((move, first, k))
    for i, (move, first, end) in enumerate(spans):
        if move[1] == 0 or end - first < 2:
            continue
        per_axis = [[e[0] for e in events[first:end] if e[1] == a] for a in (0, 1)]
        if any(len(times) == 1 for times in per_axis):
            continue
        t_end = max(times[-1] + times[-1] - times[-2] for times in per_axis if times)
        if i + 1 < len(spans) and spans[i + 1][2] > spans[i + 1][1]:
            t_end = min(t_end, events[spans[i + 1][1]][0])
        out[move[0]] = path_length(move) / ((t_end - events[first][0]) * 1e-12) * 60.0
    return out


def planner_feeds(events, moves, spm):
    """{line: feed_mm_per_min} over the steady middle half of each cutting move, for spi-fpga."""
    out, k = {}, 0
    pos = positions(events, spm)
    for move in moves:
        length = path_length(move)
        middle = []
        while k < len(pos):
            s, off = along(move, pos[k][1])
            inside = off <= PATH_TOL_MM and 0.25 * length <= s <= 0.75 * length
            if inside:
                middle.append((pos[k][0], s))
            elif middle:
                break
            k += 1
        if move[1] == 0 or len(middle) < 3:
            continue
        half = len(middle) // 2

        def speed(a, b):
            return (b[1] - a[1]) / ((b[0] - a[0]) * 1e-12) * 60.0

        whole = speed(middle[0], middle[-1])
        if abs(speed(middle[0], middle[half]) - speed(middle[half], middle[-1])) > STEADY_REL * whole:
            continue
        out[move[0]] = whole
    return out


def compare_feeds(scenario, arch, report, vcd, require_all):
    """Compares one run's report with its VCD: (lines printed, failures, moves compared, moves not comparable)."""
    with open(scenario) as f:
        toml = f.read()
    job = re.search(r'^job\s*=\s*"([^"]+)"', toml, re.M).group(1)
    name = os.path.relpath(scenario)
    with open(report) as f:
        r = json.load(f)
    spm = r["scenario"]["steps_per_mm"]
    feed_per_s = re.search(r'feed_unit\s*=\s*"mm/s"', toml) is not None
    moves = programmed_moves(os.path.join(os.path.dirname(scenario), job), feed_per_s)
    changes, scale_ps = read_vcd(vcd)
    events = step_events(changes, scale_ps, arch)
    planner = arch == "spi-fpga" or (arch == "fpga-uart" and
                                      re.search(r'^ramp\s*=\s*"(trapezoidal|s-curve)"', toml, re.M) is not None)
    edges = planner_feeds(events, moves, spm) if planner else strict_feeds(events, moves, spm)
    cols = r["metrics"]["moves"]
    feed_of = {move[0]: move[6] for move in moves}
    lines, failures, compared, skipped = [], [], 0, 0
    for line, rapid, error in zip(cols["line"], cols["rapid"], cols["feed_error_pct"]):
        if rapid:
            continue
        if line not in edges or error is None:
            skipped += 1
            if require_all:
                failures.append("%s line %d: %s" % (name, line, "no feed error in the report" if error is None
                                                    else "no steady feed in the edges"))
            continue
        compared += 1
        f = feed_of[line]
        mine = (edges[line] - f) / f * 100.0
        if planner:
            ok = abs(f * (1.0 + error / 100.0) - edges[line]) <= PLANNER_REL * edges[line]
        else:
            ok = abs(error - mine) <= STRICT_PCT
        lines.append("%s line %d: feed error report %+.4f %%, edges %+.4f %% (%.3f mm/min)%s" %
                     (name, line, error, mine, edges[line], "" if ok else "  <-- differs"))
        if not ok:
            failures.append("%s line %d: feed error %+.4f %% against the edges' %+.4f %%" % (name, line, error, mine))
    return lines, failures, compared, skipped


def main():
    args = sys.argv[1:]
    require_all = "--require-all" in args
    args = [a for a in args if a != "--require-all"]
    cncsim, arch, workdir, scenarios = args[0], args[1], args[2], args[3:]
    os.makedirs(workdir, exist_ok=True)
    failures, compared, skipped = [], 0, 0
    for scenario in scenarios:
        name = os.path.basename(scenario)
        report, vcd = (os.path.join(workdir, name + ext) for ext in (".json", ".vcd"))
        for path in (report, vcd):
            if os.path.exists(path):
                os.remove(path)
        run = subprocess.run([cncsim, "run", scenario, "--set", "scenario.architecture=" + arch, "--report", report,
                              "--vcd", vcd, "--progress", "off"], capture_output=True, text=True)
        if run.returncode != 0:
            failures.append("%s: exit %d: %s" % (name, run.returncode, run.stderr.strip()))
            continue
        lines, fails, n, k = compare_feeds(scenario, arch, report, vcd, require_all)
        print("\n".join(lines))
        failures += fails
        compared += n
        skipped += k
    if compared == 0:
        failures.append("no cutting move compared on %s" % arch)
    print("\n".join(failures))
    print("%d moves compared, %d not comparable, %d failures on %s" % (compared, skipped, len(failures), arch))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
