"""The value changes of named one-bit wires in a VCD, for the Python tests that time a run's pins."""


def vcd_edges(path, names):
    """{name: [(time_ps, level)]} of the one-bit wires NAMES (the $dumpvars values at time 0 included)."""
    ids, edges, t = {}, {n: [] for n in names}, 0
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "$var" and words[4] in edges:
                ids[words[3]] = words[4]
            elif words[0].startswith("#"):
                t = int(words[0][1:])
            elif words[0][0] in "01" and len(words) == 1 and words[0][1:] in ids:
                edges[ids[words[0][1:]]].append((t, int(words[0][0])))
    return edges


def high_intervals(changes):
    """[(rise_ps, fall_ps)] of a wire's changes; a level still high at the end is left out."""
    out, rise = [], None
    for t, level in changes:
        if level and rise is None:
            rise = t
        elif not level and rise is not None:
            out.append((rise, t))
            rise = None
    return out
