"""Wall-clock accounting for a run: where the time went, by stage and by style (LAMMPS's table)."""

import time
from collections import defaultdict

STAGES = ("Pair", "Bond", "Neigh", "Comm", "Modify", "Output", "Other")


class Timers:
    def __init__(self):
        self.stage = defaultdict(float)
        self.style = defaultdict(float)     # "fix 1 (nve)" -> seconds
        self.start = time.perf_counter()

    def reset(self):
        self.stage.clear()
        self.style.clear()
        self.start = time.perf_counter()

    def report(self, total):
        """Lines of the breakdown table: stage (and each style under Modify), seconds, percent."""
        accounted = sum(self.stage[s] for s in STAGES if s != "Other")
        rows = []
        for name in STAGES:
            rows.append((name, max(total - accounted, 0.0) if name == "Other" else self.stage[name]))
            if name == "Modify":
                rows += [(f"  {style}", t) for style, t in sorted(self.style.items(), key=lambda kv: -kv[1])]
        width = max(len("Section"), *(len(label) for label, _ in rows))
        lines = [f"{'Section':<{width}} |  time (s)  | %total", f"{'-' * width}-+------------+-------"]
        for label, seconds in rows:
            share = 100.0 * seconds / total if total > 0 else 0.0
            lines.append(f"{label:<{width}} | {seconds:10.4g} | {share:6.2f}")
        return lines


def timed_hooks(style, timers, hooks):
    """A stand-in for ``style`` whose hook methods time themselves into ``timers.style``.

    pluggy's wrappers see a hook call as a whole; the per-style line of the table needs each style's
    own share, so each implementation is wrapped once when a run is set up.
    """
    label = f"{style.kind} {style.id} ({style.name})"
    proxy = type(f"Timed_{type(style).__name__}", (), {})()
    clock = time.perf_counter
    for hook in hooks:
        method = getattr(style, hook, None)
        if method is None:
            continue

        def timed(sim, _method=method):
            t0 = clock()
            _method(sim)
            timers.style[label] += clock() - t0

        setattr(proxy, hook, timed)
    proxy.style = style
    return proxy
