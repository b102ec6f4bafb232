#!/usr/bin/env python3
"""Checks the hand-written G-code corpus in this folder against the rules in README.md.

It uses its own small RS274NGC reader (not cncsim's interpreter) and checks these rules:
- the machine position stays within X, Y 0..200 mm and Z -5..+10 mm. The job starts at machine X0 Y0 Z0. Work
  offsets are applied: G54 is zero until G10 L2 P1 sets it, G92 and G92.1 shift and reset, G53 gives machine
  coordinates, and G28/G30 go to machine 0, 0, 0. Arcs are checked at their extreme points as well as their ends;
- every programmed feed is between 100 and 3000 mm/min, with inch feeds converted;
- every arc's end point lies on the circle through its start, within 0.001 mm;
- the last code word is M2 or M30.

It also estimates the machine time: cutting moves at their feed, rapids at --rapid mm/min (default 1200), and dwells, with no
acceleration. Lines that start with "/" (block delete) are checked both skipped and run. The two deliberately
bad files are only checked for the errors they are meant to have.

Usage: python3 check_corpus.py [--rapid MM_PER_MIN] [FILE...]   (default: every job in this folder)
Exit code 0 if every file passes.
"""
import math
import os
import re
import sys

LIMITS = {"X": (0.0, 200.0), "Y": (0.0, 200.0), "Z": (-5.0, 10.0)}
FEED_MIN, FEED_MAX = 100.0, 3000.0
ARC_TOL_MM = 0.001
EPS = 1e-9
BAD_FILES = {"nested_comment_bad.nc", "expressions_params.ngc"}
JOB_EXTENSIONS = (".nc", ".ngc", ".gcode", ".gco")
WORD = re.compile(r"([A-Za-z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")


class CheckError(Exception):
    pass


def strip_comments(line, lineno):
    """Removes (...) comments and everything after ';'. Returns the code and the comment texts."""
    code, comments, depth, buf = [], [], 0, []
    i = 0
    while i < len(line):
        c = line[i]
        if depth == 0 and c == ";":
            comments.append(line[i + 1:])
            break
        if c == "(":
            if depth > 0:
                raise CheckError(f"line {lineno}: nested comment")
            depth = 1
            buf = []
        elif c == ")" and depth == 1:
            depth = 0
            comments.append("".join(buf))
        elif depth:
            buf.append(c)
        else:
            code.append(c)
        i += 1
    if depth:
        raise CheckError(f"line {lineno}: comment not closed")
    return "".join(code), comments


class Machine:
    def __init__(self, rapid_mm_per_min, run_block_delete):
        self.rapid = rapid_mm_per_min
        self.run_block_delete = run_block_delete
        self.pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}   # machine mm
        self.g54 = {"X": 0.0, "Y": 0.0, "Z": 0.0}   # work offset, mm
        self.g92 = {"X": 0.0, "Y": 0.0, "Z": 0.0}   # G92 offset, mm
        self.scale = 1.0                               # G21 mm; G20 25.4
        self.absolute = True                           # G90 / G91
        self.arc_absolute = False                      # G90.1 / G91.1
        self.motion = None
        self.feed = None                               # mm/min
        self.time_s = 0.0
        self.cut_mm = 0.0
        self.rapid_mm = 0.0
        self.dwell_s = 0.0
        self.moves = 0
        self.arcs = 0
        self.last_code_word = None
        self.extent = {k: [math.inf, -math.inf] for k in "XYZ"}
        self.ends = []  # each move: (kind, machine start and end points {X, Y, Z}, arc centre (x, y) or None, line)

    def where(self, lineno):
        return f"line {lineno}"

    def check_point(self, p, lineno, what="end point"):
        for axis, (lo, hi) in LIMITS.items():
            v = p[axis]
            if v < lo - 1e-6 or v > hi + 1e-6:
                raise CheckError(f"{self.where(lineno)}: {what} {axis}{v:.4f} outside machine {lo:g}..{hi:g}")
            self.extent[axis][0] = min(self.extent[axis][0], v)
            self.extent[axis][1] = max(self.extent[axis][1], v)

    def work_to_machine(self, axis, value):
        return value * self.scale + self.g54[axis] + self.g92[axis]

    def machine_to_work(self, axis):
        return (self.pos[axis] - self.g54[axis] - self.g92[axis]) / self.scale

    def target(self, words, machine_coords):
        t = dict(self.pos)
        for axis in "XYZ":
            if axis in words:
                v = words[axis]
                if machine_coords:
                    t[axis] = v * self.scale
                elif self.absolute:
                    t[axis] = self.work_to_machine(axis, v)
                else:
                    t[axis] = self.pos[axis] + v * self.scale
        return t

    def line_move(self, t, rapid, lineno):
        d = math.dist([self.pos[a] for a in "XYZ"], [t[a] for a in "XYZ"])
        self.check_point(t, lineno)
        if d > EPS:
            if rapid:
                self.rapid_mm += d
                self.time_s += d / self.rapid * 60.0
            else:
                if self.feed is None:
                    raise CheckError(f"{self.where(lineno)}: G1 without a feed")
                self.cut_mm += d
                self.time_s += d / self.feed * 60.0
            self.moves += 1
            self.ends.append(("rapid" if rapid else "line", dict(self.pos), t, None, lineno))
        self.pos = t

    def arc_move(self, words, cw, lineno):
        if "R" in words or "K" in words:
            raise CheckError(f"{self.where(lineno)}: this corpus uses I/J arcs only")
        t = self.target(words, False)
        sx, sy = self.pos["X"], self.pos["Y"]
        i, j = words.get("I", 0.0), words.get("J", 0.0)
        if self.arc_absolute:
            cx, cy = self.work_to_machine("X", i), self.work_to_machine("Y", j)
        else:
            cx, cy = sx + i * self.scale, sy + j * self.scale
        r0 = math.hypot(sx - cx, sy - cy)
        r1 = math.hypot(t["X"] - cx, t["Y"] - cy)
        if abs(r0 - r1) > ARC_TOL_MM:
            raise CheckError(f"{self.where(lineno)}: arc end off the circle by {abs(r0 - r1) * 1000:.4f} um")
        a0 = math.atan2(sy - cy, sx - cx)
        a1 = math.atan2(t["Y"] - cy, t["X"] - cx)
        if cw:
            sweep = a0 - a1
        else:
            sweep = a1 - a0
        while sweep <= 1e-12:
            sweep += 2 * math.pi
        # extreme points of the circle inside the sweep
        for k in range(4):
            ang = k * math.pi / 2
            delta = (a0 - ang) if cw else (ang - a0)
            delta %= 2 * math.pi
            if 1e-12 < delta < sweep:
                p = dict(t)
                p["X"], p["Y"] = cx + r0 * math.cos(ang), cy + r0 * math.sin(ang)
                self.check_point(p, lineno, "arc extreme")
        self.check_point(t, lineno)
        length = math.hypot(r0 * sweep, t["Z"] - self.pos["Z"])
        if self.feed is None:
            raise CheckError(f"{self.where(lineno)}: arc without a feed")
        self.cut_mm += length
        self.time_s += length / self.feed * 60.0
        self.moves += 1
        self.arcs += 1
        self.ends.append(("arc_cw" if cw else "arc_ccw", dict(self.pos), t, (cx, cy), lineno))
        self.pos = t

    def block(self, raw, lineno):
        line = raw.strip()
        if not line or line == "%":
            return
        if line.startswith("/"):
            if not self.run_block_delete:
                return
            line = line[1:]
        code, _ = strip_comments(line, lineno)
        code = code.strip()
        if not code:
            return
        if "#" in code or "[" in code:
            raise CheckError(f"{self.where(lineno)}: parameters/expressions")
        if re.search(r"[^A-Za-z0-9.+\-\s]", code):
            raise CheckError(f"{self.where(lineno)}: unexpected character in {code!r}")
        pairs = WORD.findall(code)
        if WORD.sub("", code).strip():
            raise CheckError(f"{self.where(lineno)}: unparsed text in {code!r}")
        gs, ms, words = [], [], {}
        for letter, num in pairs:
            letter = letter.upper()
            v = float(num)
            if letter == "G":
                gs.append(round(v, 1))
            elif letter == "M":
                ms.append(int(v))
            else:
                words[letter] = v
            self.last_code_word = (letter, v)
        # modal settings first
        for g in gs:
            if g == 20:
                self.scale = 25.4
            elif g == 21:
                self.scale = 1.0
            elif g == 90:
                self.absolute = True
            elif g == 91:
                self.absolute = False
            elif g == 90.1:
                self.arc_absolute = True
            elif g == 91.1:
                self.arc_absolute = False
        if "F" in words:
            f = words["F"] * self.scale
            if not FEED_MIN - 1e-9 <= f <= FEED_MAX + 1e-9:
                raise CheckError(f"{self.where(lineno)}: feed {f:.1f} mm/min outside {FEED_MIN:g}..{FEED_MAX:g}")
            self.feed = f
        machine_coords = 53 in gs
        nonmodal = [g for g in gs if g in (4, 10, 28, 30, 92, 92.1, 28.1, 30.1)]
        for g in nonmodal:
            if g == 4:
                p = words.get("P", words.get("S"))
                if p is None:
                    raise CheckError(f"{self.where(lineno)}: G4 without P or S")
                self.time_s += p
                self.dwell_s += p
                return
            if g == 10:
                if words.get("L") != 2 or words.get("P") != 1:
                    raise CheckError(f"{self.where(lineno)}: only G10 L2 P1 is expected")
                for axis in "XYZ":
                    if axis in words:
                        self.g54[axis] = words[axis] * self.scale
                return
            if g in (28, 30):
                if any(a in words for a in "XYZ"):
                    self.line_move(self.target(words, False), True, lineno)  # intermediate point
                    home = dict(self.pos)
                    for a in "XYZ":
                        if a in words:
                            home[a] = 0.0
                else:
                    home = {"X": 0.0, "Y": 0.0, "Z": 0.0}
                self.line_move(home, True, lineno)
                return
            if g == 92:
                for axis in "XYZ":
                    if axis in words:
                        self.g92[axis] = self.pos[axis] - self.g54[axis] - words[axis] * self.scale
                return
            if g == 92.1:
                self.g92 = {"X": 0.0, "Y": 0.0, "Z": 0.0}
                return
        for g in gs:
            if g in (0, 1, 2, 3):
                self.motion = int(g)
        if any(a in words for a in "XYZ"):
            if self.motion is None:
                raise CheckError(f"{self.where(lineno)}: coordinates without a motion mode")
            if self.motion in (0, 1):
                self.line_move(self.target(words, machine_coords), self.motion == 0, lineno)
            else:
                self.arc_move(words, self.motion == 2, lineno)


def check_file(path, rapid):
    name = os.path.basename(path)
    text = open(path, encoding="utf-8").read().split("\n")
    if text and text[-1] == "":
        text.pop()
    if name in BAD_FILES:
        return check_bad(name, text)
    results = []
    variants = [False, True] if any(l.strip().startswith("/") for l in text) else [False]
    for run_bd in variants:
        m = Machine(rapid, run_bd)
        for n, l in enumerate(text, 1):
            m.block(l, n)
        if m.last_code_word is None or m.last_code_word[0] != "M" or m.last_code_word[1] not in (2, 30):
            raise CheckError(f"last code word is {m.last_code_word}, not M2 or M30")
        results.append(m)
    m = results[0]
    ext = " ".join(f"{a} {m.extent[a][0]:.3f}..{m.extent[a][1]:.3f}" for a in "XYZ")
    extra = ""
    if len(results) > 1:
        extra = f" (with block-delete lines run: {results[1].time_s:.1f} s)"
    return (f"{name}: {len(text)} lines, {m.moves} moves ({m.arcs} arcs), cut {m.cut_mm:.1f} mm, "
            f"rapid {m.rapid_mm:.1f} mm, dwell {m.dwell_s:.1f} s, est. {m.time_s:.1f} s{extra}; {ext}; "
            f"ends at X{m.pos['X']:.3f} Y{m.pos['Y']:.3f} Z{m.pos['Z']:.3f}")


def check_bad(name, text):
    if name == "nested_comment_bad.nc":
        errors = []
        for n, l in enumerate(text, 1):
            try:
                strip_comments(l, n)
            except CheckError as e:
                errors.append(str(e))
        expected = ["line 3: nested comment", "line 5: comment not closed"]
        if errors != expected:
            raise CheckError(f"expected {expected}, found {errors}")
        return f"{name}: errors as intended: {'; '.join(errors)}"
    first = next(n for n, l in enumerate(text, 1) if "#" in strip_comments(l, n)[0] or "[" in l.split("(")[0])
    return f"{name}: first parameter/expression on line {first}"


def main(argv):
    rapid = 1200.0
    files = []
    it = iter(argv)
    for a in it:
        if a == "--rapid":
            rapid = float(next(it))
        else:
            files.append(a)
    here = os.path.dirname(os.path.abspath(__file__))
    if not files:
        files = sorted(os.path.join(here, f) for f in os.listdir(here) if f.endswith(JOB_EXTENSIONS))
    ok = True
    for f in files:
        try:
            print(check_file(f, rapid))
        except CheckError as e:
            ok = False
            print(f"{os.path.basename(f)}: FAIL: {e}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
