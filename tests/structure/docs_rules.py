#!/usr/bin/env python3
"""The documentation's rules:

1. Every relative link of README.md, CONTRIBUTING.md and the Markdown files under docs/ and sim/ resolves: the file
   or folder exists, and an #anchor names a heading of the target (GitHub's slugs).
2. No file in the repository cites what a reader does not have: the design notes and the extractions of the theses
   kept outside it (DESIGN.md, peers.md, toolchain.md, style.md, spec/seed-NNN-*.md) or the issue tracker's issue
   and check numbers.
3. The README stays under 350 lines, and the commands of its quick start run: each fenced `sh` block of the section
   "Quick start" runs with bash -e in a fresh folder that sees the build and the scenarios, exits 0, and leaves the
   files the section says it writes.

Usage: docs_rules.py SOURCE_DIR BUILD_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
CITATION = re.compile(r"DESIGN\.md|peers\.md|toolchain\.md|style\.md|spec/seed-\d+|\bissues?\s+#?\d+|\bchecks?\s*\d+",
                      re.I)
README_MAX_LINES = 350
QUICK_START_OUTPUTS = ["out/my_machine.json", "out/my_machine.vcd", "out/my_compare/index.html",
                       "out/my_compare/table.md", "out/my_compare/path.png", "out/start/scenario.toml",
                       "out/start/machine.toml", "out/start/job.nc"]


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    return {slug(m.group(1)) for m in re.finditer(r"^#+\s+(.*)$", text, re.M)}


def markdown_files(source):
    files = [os.path.join(source, f) for f in ("README.md", "CONTRIBUTING.md")]
    for top in ("docs", "sim"):
        for root, _, names in os.walk(os.path.join(source, top)):
            files += [os.path.join(root, n) for n in names if n.endswith(".md")]
    return files


def check_links(source):
    failures = []
    for md in markdown_files(source):
        with open(md, encoding="utf-8") as f:
            text = re.sub(r"```.*?```", "", f.read(), flags=re.S)
        for target in LINK.findall(text):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, mailto:
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
            where = os.path.relpath(md, source)
            if not os.path.exists(resolved):
                failures.append("rule 1: %s links %s: no such file" % (where, target))
            elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                failures.append("rule 1: %s links %s: no such heading" % (where, target))
    return failures


def check_citations(source, own):
    files = subprocess.run(["git", "ls-files", "-z"], cwd=source, capture_output=True, check=True).stdout
    failures = []
    for rel in files.decode().split("\0"):
        path = os.path.join(source, rel)
        if not rel or os.path.abspath(path) == own or not os.path.isfile(path):
            continue
        try:
            with open(path, encoding="utf-8") as f:
                lines = f.read().splitlines()
        except UnicodeDecodeError:
            continue  # a binary file (a PNG) cites nothing
        for i, line in enumerate(lines, 1):
            m = CITATION.search(line)
            if m:
                failures.append("rule 2: %s:%d cites '%s': %s" % (rel, i, m.group(0), line.strip()[:120]))
    return failures


def check_readme(source, build):
    with open(os.path.join(source, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    failures = []
    lines = readme.count("\n")
    if lines >= README_MAX_LINES:
        failures.append("rule 3: README.md has %d lines, at most %d" % (lines, README_MAX_LINES - 1))
    start = readme.find("## Quick start")
    end = readme.find("\n## ", start + 1)
    blocks = re.findall(r"```sh\n(.*?)```", readme[start:end], re.S) if start >= 0 else []
    if not blocks or not any("cncsim" in b for b in blocks):
        return failures + ["rule 3: the README's quick start has no fenced sh block with a cncsim command"]
    with tempfile.TemporaryDirectory(prefix="cncsim-readme-") as tmp:
        os.symlink(os.path.abspath(build), os.path.join(tmp, "build"))
        os.symlink(os.path.join(os.path.abspath(source), "scenarios"), os.path.join(tmp, "scenarios"))
        for block in blocks:
            run = subprocess.run(["bash", "-e", "-c", block], cwd=tmp, capture_output=True, text=True)
            if run.returncode != 0:
                failures.append("rule 3: the quick start's block exits %d:\n%s\n%s" % (run.returncode, block,
                                                                                     run.stderr[-2000:]))
        for out in QUICK_START_OUTPUTS:
            if not os.path.isfile(os.path.join(tmp, out)):
                failures.append("rule 3: the quick start wrote no %s" % out)
    return failures


def main():
    source, build = sys.argv[1:3]
    failures = check_links(source) + check_citations(source, os.path.abspath(__file__)) + check_readme(source, build)
    print("\n".join(failures) if failures else "every rule holds")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
