"""``neighbor auto``: the skin that makes a scene's steps fastest, found by trying several.

The skin trades two costs: a larger skin lists more pairs (each step tests more distances; more
ghosts), a smaller one rebuilds more often. Which wins depends on the scene (density, temperature,
time step, how far particles move per step), so ``neighbor auto`` measures it: the first steps of
the next run are cut into segments, each with one candidate skin, and the run goes on with the
skin whose steps took least wall time (the largest over ranks). The forces do not depend on the
skin (a list holds every pair within the cutoff plus the skin), so the trial is part of the run:
no step is repeated or thrown away; only the summation order, and so the last bits, differ.

Candidates are fractions of the largest pair cutoff (``FRACTIONS``), each run for ``STEPS`` steps after
the rebuild that starts its segment. When ``neigh_modify every``, ``delay`` or ``check no`` hold
rebuilds back, a candidate under which a particle had moved more than half the skin by a rebuild is
ruled out: its lists may have missed pairs. (Checked at every step, a list is rebuilt as soon as
anything moved half the skin, and no candidate misses a pair.) The choice and
every candidate's time per step are printed, as ``neighbor auto: ...``.
"""

import time

FRACTIONS = (0.05, 0.1, 0.15, 0.2, 0.3, 0.45)
STEPS = 25


class SkinTrial:
    def __init__(self, fallback):
        self.fallback = fallback        # the skin before ``neighbor auto`` (used if nothing qualifies)
        self.candidates = None          # skins to try, set at the first run (the cutoff is known then)
        self.index = -1
        self.step_start = 0
        self.clock_start = 0.0
        self.seconds = {}               # skin -> seconds per step (None: ruled out)
        self.done = False

    def begin(self, cutoff):
        if self.candidates is None:
            self.candidates = [round(f * cutoff, 12) for f in FRACTIONS]

    def next_skin(self, neighbor, step, comm):
        """Called before every step of a run while the trial lasts: the skin to switch to on this
        step (the caller rebuilds), or None to go on. Closes the finished segment first."""
        if self.index >= 0 and step - self.step_start < STEPS:
            return None
        if self.index >= 0:
            elapsed = comm.max(time.perf_counter() - self.clock_start)
            # a list rebuilt as soon as anything moved half the skin misses nothing; one held back
            # (every, delay, check no) may have, if a particle had moved more than that by its rebuild
            checked_every_step = neighbor.check and neighbor.every == 1 and neighbor.delay <= 1
            unsafe = not checked_every_step and neighbor.moved_at_build > 0.5 * self.candidates[self.index]
            unsafe = comm.max(int(unsafe))
            self.seconds[self.candidates[self.index]] = None if unsafe else elapsed / STEPS
        self.index += 1
        if self.index >= len(self.candidates):
            self.done = True
            timed = {s: t for s, t in self.seconds.items() if t is not None}
            return min(timed, key=timed.get) if timed else self.fallback
        self.step_start = step
        self.clock_start = time.perf_counter()
        neighbor.moved_at_build = 0.0
        return self.candidates[self.index]

    def report(self, chosen):
        shown = ", ".join(f"{s:g}: " + (f"{t * 1e3:.3g} ms" if t is not None else "ruled out (missed pairs possible)")
                          for s, t in self.seconds.items())
        return f"neighbor auto: skin {chosen:g} (time per step by skin: {shown})"
