#!/usr/bin/env python3
"""What `cncsim compare --out DIR` (and `cncsim run --plots DIR`) write, checked:
every SVG is well-formed XML (xmllint) with its title and both axis labels as text; every PNG decodes and is not
blank (Pillow reads its pixels); index.html parses as HTML (xmllint --html) without a message and refers only to
files in its own folder.

With `failing`, one architecture's run fails (fpga-uart's ACK timeout on a 12 s move): it is reported in its
column and on the page, and the other's table column, plots and page are all there.

usage: compare_outputs.py CNCSIM SOURCE_DIR WORK_DIR (compare|run|failing)
"""
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

from PIL import Image

SVG_NS = "{http://www.w3.org/2000/svg}"


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def svg_texts(path):
    """The text of every <text> element (gnuplot writes one per title, label and tic, sometimes in <tspan>s)."""
    root = ET.parse(path).getroot()
    return {"".join(t.itertext()).strip() for t in root.iter(SVG_NS + "text")}


def check_svg(path, plot):
    r = subprocess.run(["xmllint", "--noout", path], capture_output=True, text=True)
    if r.returncode != 0 or r.stderr:
        fail(f"{path} is not well-formed XML: {r.stderr}")
    texts = svg_texts(path)
    for what in ("title", "xlabel", "ylabel"):
        if plot[what] not in texts:
            fail(f"{path}: no text '{plot[what]}' ({what}); texts: {sorted(texts)[:20]}")
    if not re.search(r"\[.+\]", plot["xlabel"]) or not re.search(r"\[.+\]", plot["ylabel"]):
        fail(f"{path}: axis labels without a unit: {plot['xlabel']!r}, {plot['ylabel']!r}")


def check_png(path):
    with Image.open(path) as im:
        im.load()
        rgb = im.convert("RGB")
        w, h = rgb.size
        pixels = list(rgb.getdata())
    background = max(set(pixels[:: max(1, len(pixels) // 5000)]), key=pixels.count)
    drawn = sum(1 for p in pixels if p != background)
    colours = len(set(pixels))
    # A plot with axes, a title and curves covers more than 1 % of the image and uses several colours
    # (anti-aliased lines alone give dozens); a blank or one-colour image fails.
    if drawn < 0.01 * w * h or colours < 8:
        fail(f"{path} looks blank: {drawn} of {w * h} pixels drawn, {colours} colours")


class Refs(HTMLParser):
    def __init__(self):
        super().__init__()
        self.refs = []
        self.external = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("src", "href") and value is not None:
                self.refs.append(value)
        if tag == "link" or tag == "script":
            self.external.append(tag)


def check_html(out):
    page = os.path.join(out, "index.html")
    r = subprocess.run(["xmllint", "--html", "--noout", page], capture_output=True, text=True)
    if r.returncode != 0 or r.stderr or r.stdout:
        fail(f"xmllint --html {page}: {r.stderr}{r.stdout}")
    p = Refs()
    with open(page, encoding="utf-8") as f:
        text = f.read()
    p.feed(text)
    if p.external:
        fail(f"index.html has {p.external}: the page must need nothing but its folder")
    if re.search(r"url\(|@import|@font-face", text):
        fail("index.html's style loads something")
    if not p.refs:
        fail("index.html refers to no file")
    for ref in p.refs:
        if "/" in ref or ":" in ref or ref.startswith(".") or not os.path.isfile(os.path.join(out, ref)):
            fail(f"index.html refers to {ref!r}, not a file in its folder")
    return p.refs


def drawn_colours(svg_path):
    with open(svg_path) as f:
        return {tuple(int(v) for v in m) for m in re.findall(r"rgb\(\s*(\d+),\s*(\d+),\s*(\d+)\)", f.read())}


COLOURS = {"fpga-uart": (0x00, 0x72, 0xb2), "atmega": (0xd5, 0x5e, 0x00), "spi-fpga": (0x00, 0x9e, 0x73)}


ALL_PLOTS = ("path", "contour_error", "following_error", "step_period_x", "step_period_y", "tie_x", "tie_y",
             "velocity", "dead_time")


def check_plots(out, expect_archs, required_plots=ALL_PLOTS):
    with open(os.path.join(out, "plots.json")) as f:
        plots = json.load(f)
    names = {p["name"] for p in plots}
    for required in required_plots:
        if required not in names:
            fail(f"no {required} plot in {out} (has {sorted(names)})")
    for p in plots:
        check_svg(os.path.join(out, p["name"] + ".svg"), p)
        check_png(os.path.join(out, p["name"] + ".png"))
    svgs = {f[:-4] for f in os.listdir(out) if f.endswith(".svg")}
    if svgs != names:
        fail(f"SVGs {sorted(svgs)} != plots.json {sorted(names)}")
    # Same colour per architecture everywhere: each architecture's colour is in the path plot.
    drawn = drawn_colours(os.path.join(out, "path.svg"))
    for a in expect_archs:
        if COLOURS[a] not in drawn:
            fail(f"path.svg does not draw {a} in its colour {COLOURS[a]}")
    return plots


def main():
    cncsim, source, work, mode = sys.argv[1:5]
    out = os.path.join(work, "out")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scenario = os.path.join(source, "scenarios", "compare", "circle_r10.toml")
    archs = ["fpga-uart", "atmega", "spi-fpga"]
    expect_exit = 0
    if mode == "compare":
        cmd = [cncsim, "compare", scenario, "--arch", ",".join(archs), "--out", out]
    elif mode == "failing":
        archs = ["spi-fpga"]
        expect_exit = 1
        cmd = [cncsim, "compare", os.path.join(source, "scenarios", "fpga-uart", "long_move_timeout.toml"),
               "--arch", "fpga-uart,spi-fpga", "--out", out]
    else:
        archs = ["spi-fpga"]
        cmd = [cncsim, "run", scenario, "--set", "scenario.architecture=spi-fpga", "--plots", out, "--progress", "off"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != expect_exit:
        fail(f"{' '.join(cmd)} exited {r.returncode}, not {expect_exit}: {r.stderr}")
    # The failing job is one X move: no Y steps and no gap between moves, so no plot of them.
    plots = check_plots(out, archs, ALL_PLOTS if mode != "failing" else
                        ("path", "contour_error", "following_error", "step_period_x", "tie_x", "velocity"))
    if mode == "failing":
        with open(os.path.join(out, "table.md")) as f:
            status = next(line for line in f if line.startswith("| status"))
        if re.sub(r"\s+", " ", status).strip() != "| status | failed | ok |":
            fail(f"table.md status row: {status}")
        if COLOURS["fpga-uart"] in drawn_colours(os.path.join(out, "path.svg")):
            fail("path.svg draws the failed fpga-uart run: a failed run's figures are no result")
        with open(os.path.join(out, "index.html")) as f:
            page = f.read()
        if not re.search(r"<b>The run failed:</b> ACK timeout at seg 1 .*host\.ack_timeout_s", page):
            fail("index.html does not say why fpga-uart failed")
        check_html(out)
    if mode == "compare":
        for f in ["index.html", "table.md", "table.csv", "table.json"] + [a + ".json" for a in archs] + \
                 [a + ".vcd" for a in archs]:
            if not os.path.isfile(os.path.join(out, f)):
                fail(f"no {f} in {out}")
        refs = check_html(out)
        for p in plots:
            if p["name"] + ".svg" not in refs:
                fail(f"index.html does not show {p['name']}.svg")
    print(f"ok: {len(plots)} plots checked in {out}")
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
