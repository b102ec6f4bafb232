#!/usr/bin/env python3
"""The source layout's rules, checked on the tree (docs/development.md "Layout"):

1. Nothing under sim/scenario includes a SystemC header, directly or through the headers it includes.
2. The scenario library (cnc_scenario) links neither SystemC nor the simulator (cnc_sim): LINK_CLOSURE lists every
   target and library it links, as CMake resolved them.
3. No source file under sim/ outside the registry (sim/architectures/registry.hpp) and the architectures' own folders
   (sim/architectures/<name>/) spells an architecture's name: shared code asks the Architecture interface instead.
   The names come from `cncsim keys` (the allowed values of scenario.architecture); a name that is also a plain word
   (a carriage model is "ideal" too, grbl a firmware) counts only as a quoted string.

Usage: layout_rules.py CNCSIM SOURCE_DIR LINK_CLOSURE_FILE
"""
import os
import re
import subprocess
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
SYSTEMC = ("systemc", "systemc.h", "tlm", "tlm.h")
# Where quoted includes resolve: the source roots the build's include paths name.
ROOTS = ("sim", "models")
# Names that are plain words too, counted only as quoted strings; with the files where the quoted word is another key's
# value (mechanics.model = "ideal" is a carriage model). grbl is a firmware before it is an architecture.
WORD_NAMES = {"ideal": {os.path.join("sim", "scenario", "mechanics_settings.cpp")}, "grbl": set()}


def resolve(source, path, including_dir):
    for base in (including_dir,) + tuple(os.path.join(source, r) for r in ROOTS):
        candidate = os.path.normpath(os.path.join(base, path))
        if os.path.isfile(candidate):
            return candidate
    return None


def systemc_chain(source, start):
    """The include chain from `start` to a SystemC header, or None."""
    seen = set()
    stack = [(start, [start])]
    while stack:
        path, chain = stack.pop()
        if path in seen:
            continue
        seen.add(path)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for kind, name in INCLUDE.findall(text):
            if kind == "<" and name in SYSTEMC:
                return chain + ["<%s>" % name]
            if kind == '"':
                target = resolve(source, name, os.path.dirname(path))
                if target is not None:
                    stack.append((target, chain + [target]))
    return None


def architecture_names(cncsim):
    keys = subprocess.run([cncsim, "keys"], capture_output=True, text=True, check=True).stdout
    for line in keys.splitlines():
        if line.startswith("| `scenario.architecture` |"):
            allowed = line.split(" | ")[3]
            return [n.strip() for n in allowed.replace("\\|", "|").split("|")]
    raise SystemExit("cncsim keys lists no scenario.architecture")


def spellings(name):
    """The ways code spells an architecture: its name, and as an identifier or a folder."""
    if name in WORD_NAMES:
        return [re.compile(r'"%s"' % re.escape(name))]
    ident = name.replace("-", "_")
    return [re.compile(r"\b%s\b" % re.escape(n)) for n in sorted({name, ident})]


def main():
    cncsim, source, closure_file = sys.argv[1:4]
    failures = []

    scenario_dir = os.path.join(source, "sim", "scenario")
    for name in sorted(os.listdir(scenario_dir)):
        chain = systemc_chain(source, os.path.join(scenario_dir, name))
        if chain:
            failures.append("rule 1: %s includes SystemC: %s" % (
                name, " -> ".join(os.path.relpath(c, source) if os.sep in c else c for c in chain)))

    with open(closure_file, encoding="utf-8") as f:
        closure = [l.strip() for l in f if l.strip()]
    for lib in closure:
        if "systemc" in lib.lower() or lib == "cnc_sim":
            failures.append("rule 2: cnc_scenario links %s (its links: %s)" % (lib, ", ".join(closure)))

    names = architecture_names(cncsim)
    own = {os.path.join(source, "sim", "architectures", n.replace("-", "_")) for n in names}
    registry = os.path.join(source, "sim", "architectures", "registry.hpp")
    for root, dirs, files in os.walk(os.path.join(source, "sim")):
        if any(root == d or root.startswith(d + os.sep) for d in own):
            continue
        for f in files:
            path = os.path.join(root, f)
            if path == registry or not f.endswith((".cpp", ".hpp")):
                continue
            rel = os.path.relpath(path, source)
            with open(path, encoding="utf-8") as fh:
                lines = fh.read().splitlines()
            for name in names:
                if rel in WORD_NAMES.get(name, set()):
                    continue
                for pattern in spellings(name):
                    for i, line in enumerate(lines, 1):
                        if pattern.search(line):
                            failures.append("rule 3: %s:%d spells the architecture %s: %s" % (rel, i, name,
                                                                                             line.strip()))
    print("architectures: %s; %d libraries in cnc_scenario's link closure" % (", ".join(names), len(closure)))
    print("\n".join(failures) if failures else "every rule holds")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
