#!/usr/bin/env python3
"""What the plots of `cncsim compare SCENARIO --out DIR` show, read back from the pixels and the vectors they are
made of, with each architecture's colour and the programmed path's as docs/plots.md gives them:

- path: plots.json gives the path plot's panels (the whole job, then a zoom panel per architecture, titled with
  its number and name) as boxes in pixels. In every panel, the PNG has pixels of each architecture's colour and of
  the programmed path's, and the SVG has line vertices of each of those colours inside the box: no architecture
  and not the programmed path is hidden under another or left out of a zoom.
- each zoom panel's title gives the figures of the architecture's report (ARCH.json): the largest contour error of
  its cutting (non-rapid) moves with the move's line, and when the report's contour error max (every move) is
  larger, that figure with its rapid's line; the same text is in the SVG.
- series_load_angle: the SVG has a horizontal line at 90 on the y axis (read from its tic labels) across the data,
  and the label that names it pull-out.
- velocity: one panel per architecture, titled with its name.

usage: plot_figures.py CNCSIM SOURCE_DIR WORK_DIR SCENARIO_NAME
  SCENARIO_NAME is one of scenarios/compare/*.toml, without .toml.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

from PIL import Image

SVG_NS = "{http://www.w3.org/2000/svg}"
ARCHS = ["fpga-uart", "atmega", "spi-fpga"]  # compare's columns by default, in their order
# A pixel of a line's colour: that colour over at least half of it (MAX_BLEND), the white background or another
# line over the rest, within this RGB distance.
COLOUR_TOLERANCE = 20.0
MAX_BLEND = 0.5
MIN_PIXELS = 40  # a line through a panel leaves a hundred or more; a stray blend of two others, a few
TITLE_ROUNDING_UM = 0.005  # the titles give 2 decimals
REPORT_ROUNDING_UM = 0.0005  # the report's per-move figures 3
MIN_LENGTH_PX = 10.0  # of a colour's lines in the SVG inside a panel


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def hex_rgb(h):
    return tuple(int(h[i:i + 2], 16) for i in (1, 3, 5))


def documented_colours(source):
    """{architecture or 'programmed': (r, g, b)} from docs/plots.md's sentence on the colours ("NAME colour-words
    `#rrggbb`")."""
    with open(os.path.join(source, "docs", "plots.md"), encoding="utf-8") as f:
        text = f.read()
    colours = {}
    for name in ARCHS + ["programmed"]:
        m = re.search(re.escape(name) + r"[a-z ]*? `(#[0-9a-f]{6})`", text)
        if m is None:
            fail(f"docs/plots.md gives no colour for {name}")
        colours[name] = hex_rgb(m.group(1))
    return colours


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"{' '.join(cmd)} exited {r.returncode}: {r.stderr}")


def svg_root(path):
    return ET.parse(path).getroot()


def svg_texts(root):
    """(text, x, y) of every <text> element: gnuplot places it with a transform='translate(x,y)' on its <g>."""
    out = []
    for g in root.iter():
        m = re.search(r"translate\(([-\d.]+),([-\d.]+)\)", g.get("transform", ""))
        for t in g.findall(SVG_NS + "text"):
            x, y = (float(m.group(1)), float(m.group(2))) if m else (0.0, 0.0)
            out.append(("".join(t.itertext()).strip(), x, y))
    return out


def svg_polylines(root):
    """[(rgb, dashed, [[(x, y), ...], ...])] of every <path>: its stroke colour and its subpaths' vertices."""
    out = []
    for p in root.iter(SVG_NS + "path"):
        m = re.match(r"rgb\(\s*(\d+),\s*(\d+),\s*(\d+)\)", p.get("stroke", ""))
        if not m or not p.get("d"):
            continue
        subpaths = []
        for cmd, x, y in re.findall(r"([ML])\s*([-\d.]+),([-\d.]+)", p.get("d")):
            if cmd == "M" or not subpaths:
                subpaths.append([])
            subpaths[-1].append((float(x), float(y)))
        out.append((tuple(int(v) for v in m.groups()), p.get("stroke-dasharray") is not None, subpaths))
    return out


def length_inside(box, a, b):
    """The length of segment a-b inside the box (Liang-Barsky clipping)."""
    left, top, right, bottom = box
    (x0, y0), (x1, y1) = a, b
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, x0 - left), (dx, right - x0), (-dy, y0 - top), (dy, bottom - y0)):
        if p == 0:
            if q < 0:
                return 0.0
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
    return max(0.0, t1 - t0) * math.hypot(dx, dy)


WHITE = (255, 255, 255)


def blend_of(pixel, colour, other):
    """Whether the pixel is `colour` over at least half of it and `other` over the rest (anti-aliasing: a line's
    edge shares its pixels with the background or the line beneath)."""
    d = [o - c for o, c in zip(other, colour)]
    span = sum(v * v for v in d)
    t = 0.0 if span == 0 else sum((p - c) * v for p, c, v in zip(pixel, colour, d)) / span
    t = min(max(t, 0.0), MAX_BLEND)
    return math.dist(pixel, [c + t * v for c, v in zip(colour, d)]) <= COLOUR_TOLERANCE


def check_path(out, colours, reports):
    with open(os.path.join(out, "plots.json"), encoding="utf-8") as f:
        plot = next((p for p in json.load(f) if p["name"] == "path"), None)
    if plot is None or "panels" not in plot:
        fail("plots.json has no path plot with its panels")
    panels = plot["panels"]
    if len(panels) != 1 + len(ARCHS):
        fail(f"path plot: {len(panels)} panels, expected the whole job and one zoom per architecture "
             f"({len(ARCHS)})")
    for k, (arch, panel) in enumerate(zip(ARCHS, panels[1:])):
        if not panel["title"].startswith(f"{k + 1}: {arch}, "):
            fail(f"zoom panel {k + 1} is titled {panel['title']!r}, not after {arch}")

    with Image.open(os.path.join(out, "path.png")) as im:
        rgb = im.convert("RGB")
    width, height = rgb.size
    pixels = rgb.load()
    root = svg_root(os.path.join(out, "path.svg"))
    lines = svg_polylines(root)
    names = ARCHS + ["programmed"]
    which = {}  # pixel value: the names whose colour it is
    found = []
    for panel in panels:
        box = panel["box_px"]
        left, top, right, bottom = box
        if not (0 <= left < right <= width and 0 <= top < bottom <= height):
            fail(f"panel {panel['title']!r}: box {box} outside the {width}x{height} PNG")
        counts = {n: 0 for n in names}
        for y in range(top, bottom):
            for x in range(left, right):
                p = pixels[x, y]
                if p not in which:
                    which[p] = [n for n in names
                                if any(blend_of(p, colours[n], o) for o in [WHITE] + [colours[m] for m in names])]
                for n in which[p]:
                    counts[n] += 1
        drawn = {n: 0.0 for n in names}
        for stroke, _, subpaths in lines:
            for n in names:
                if stroke == colours[n]:
                    drawn[n] += sum(length_inside(box, sp[i - 1], sp[i]) for sp in subpaths
                                    for i in range(1, len(sp)))
        # A panel names the runs whose path passes outside its window: those, and only those, are not in it.
        away = re.findall(r"([a-z-]+) \([\d.]+ mm\)", panel["title"].partition("not in view:")[2])
        for n in names:
            if n in away:
                if counts[n] >= MIN_PIXELS or drawn[n]:
                    fail(f"panel {panel['title']!r} says {n} is not in view, and draws it: {counts[n]} pixels, "
                         f"{drawn[n]:.1f} px of lines")
                continue
            if counts[n] < MIN_PIXELS:
                fail(f"path.png, panel {panel['title']!r}: {counts[n]} pixels of {n}'s colour "
                     f"{colours[n]} (at least {MIN_PIXELS}); counts {counts}")
            if drawn[n] < MIN_LENGTH_PX:
                fail(f"path.svg, panel {panel['title']!r}: {drawn[n]:.1f} px of {n}'s colour's lines inside "
                     f"{box}; lengths {drawn}")
        found.append((panel["title"][:30], counts, {n: round(v) for n, v in drawn.items()}))

    texts = {t for t, _, _ in svg_texts(root)}
    for k, arch in enumerate(ARCHS):
        title = panels[k + 1]["title"]
        moves = reports[arch]["metrics"]["moves"]
        rows = [r for r in zip(moves["contour_max_um"], moves["line"], moves["rapid"]) if r[0] is not None]
        cut = max((r for r in rows if not r[2]), key=lambda r: r[0])
        expect = [(rf"contour error ([\d.]+) um, line {cut[1]}(?= |$)", cut[0])]
        table_max = reports[arch]["metrics"]["path"]["contour_max_um"]
        if table_max > cut[0] + REPORT_ROUNDING_UM:
            worst = max(rows, key=lambda r: r[0])
            expect.append((rf"all moves: ([\d.]+) um \(rapid, line {worst[1]}\)", table_max))
        elif "all moves:" in title:
            fail(f"zoom panel of {arch}: {title!r} gives a figure of all moves; the report's contour error max "
                 f"{table_max} is its cutting moves' {cut[0]}")
        for pattern, figure in expect:
            m = re.search(pattern, title)
            if m is None or abs(float(m.group(1)) - figure) > TITLE_ROUNDING_UM + REPORT_ROUNDING_UM:
                fail(f"zoom panel of {arch}: title {title!r} has no {pattern!r} of its report's {figure}")
            if m.group(0) not in texts:
                fail(f"path.svg has no text {m.group(0)!r}")
    return found


def y_of(texts, value):
    """The SVG y of `value` on the y axis, from its tic labels: the numbers that share one x, one under another."""
    by_x = {}
    for t, x, y in texts:
        if re.fullmatch(r"-?\d+(\.\d+)?", t):
            by_x.setdefault(round(x), []).append((float(t), y))
    tics = sorted(max(by_x.values(), key=len))
    if len(tics) < 2:
        fail(f"fewer than two y tic labels: {tics}")
    (v0, y0), (v1, y1) = tics[0], tics[-1]
    return y0 + (value - v0) * (y1 - y0) / (v1 - v0)


def check_load_angle(out):
    root = svg_root(os.path.join(out, "series_load_angle.svg"))
    texts = svg_texts(root)
    if not any(t.startswith("pull-out, 90 electrical deg") for t, _, _ in texts):
        fail("series_load_angle.svg has no pull-out label")
    # The tic labels sit a little below the value they mark (baseline): within a few px.
    y90 = y_of(texts, 90.0)
    for stroke, dashed, subpaths in svg_polylines(root):
        for sp in subpaths:
            if stroke == (0, 0, 0) and dashed and len(sp) == 2 and abs(sp[0][1] - y90) < 6 and \
                    abs(sp[1][1] - sp[0][1]) < 0.01 and abs(sp[1][0] - sp[0][0]) > 400:
                return sp[0][1]
    fail(f"series_load_angle.svg: no dashed black line across the data at y = 90 (about {y90:.1f} px)")


def check_velocity(out):
    texts = {t for t, _, _ in svg_texts(svg_root(os.path.join(out, "velocity.svg")))}
    for arch in ARCHS:
        if arch not in texts:
            fail(f"velocity.svg has no panel titled {arch}")


def main():
    cncsim, source, work, name = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "out")
    colours = documented_colours(source)
    run([cncsim, "compare", os.path.join(source, "scenarios", "compare", name + ".toml"), "--arch", ",".join(ARCHS),
         "--out", out])
    reports = {}
    for arch in ARCHS:
        with open(os.path.join(out, arch + ".json"), encoding="utf-8") as f:
            reports[arch] = json.load(f)
    found = check_path(out, colours, reports)
    y90 = check_load_angle(out)
    check_velocity(out)
    for title, counts, vertices in found:
        print(f"{title!r}: pixels {counts}, SVG lines [px] {vertices}")
    print(f"ok: pull-out line at y {y90:.1f} px; velocity panels {ARCHS}")
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
