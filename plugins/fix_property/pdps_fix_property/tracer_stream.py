r"""Fix ``property/atom/tracer/stream``: mark as tracers the first N particles of a ``fix
insert/stream`` to cross its face after a step, once or again every E steps (LIGGGHTS 3.8.0's fix
property/atom/tracer/stream, for residence-time distributions with ``compute
nparticles/tracer/region``).

The marker is a per-atom property named by the fix's ID (``f_ID`` in dumps and compute reduce, as
fix property/atom/tracer's), 0 at first. At each insertion of the stream, the particles it inserts
in the fix's group whose release step (the step they reach the face) is at or after the first open
packet's step are taken in order of release step and marked 1, N to a packet: a packet at
``mark_step``, and with ``every E`` one more at every ``mark_step + k E`` as the insertions reach
it. A packet not filled by one insertion takes the next insertion's particles (``once`` too); with
``every E`` a packet whose step lies more than one insertion interval back is dropped, with a
warning, as LIGGGHTS's are. The scalar ``f_ID`` is the number marked since it was last read.

Particles crossing at the same step are taken in the order they were inserted (LIGGGHTS sorts them
with std::sort, which leaves their order among themselves to its implementation); which of them are
marked is random anyway, as the insertion's positions are, so the counts are what the recorded case
compares.

Syntax::

    fix ID GROUP property/atom/tracer/stream mark_step S n_tracer N insert_stream INS_ID every once|E

- ``mark_step S`` (timesteps), ``n_tracer N`` (>= 0 particles), ``insert_stream INS_ID`` (a fix
  insert/stream), ``every once|E`` (E > 0 timesteps): all four needed, as LIGGGHTS.

Example::

    fix tracer all property/atom/tracer/stream mark_step 10000 n_tracer 20 insert_stream ins every 10000
    compute out all nparticles/tracer/region region_count outlet tracer tracer
"""

from typing import Literal

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword


class FixPropertyAtomTracerStream(Fix):
    name = "property/atom/tracer/stream"
    usage = "fix ID GROUP property/atom/tracer/stream mark_step S n_tracer N insert_stream INS_ID every once|E"

    class Args(StyleArgs):
        mark_step: int = keyword(..., ge=0, unit="timesteps")
        n_tracer: int = keyword(..., ge=0, unit="particles")
        insert_stream: str = keyword(..., names="fix ID")
        every: Literal["once"] | int = keyword(..., unit="timesteps")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.every != "once" and args.every < 1:
            raise ScriptError(f"every must be once or > 0 (got {args.every})")
        stream = sim.fixes.get(args.insert_stream)
        watch = getattr(stream, "watch_releases", None)
        if watch is None:
            raise ScriptError(f"insert_stream {args.insert_stream} is not a fix insert/stream"
                              + ("" if stream is None else f" (it is fix {stream.name})"))
        self.stream = stream
        self.marker = id
        sim.particles.request(self.marker)
        self.marked = self.read = 0
        self.every = 0 if args.every == "once" else args.every
        self.packets = [[args.mark_step, args.n_tracer]]      # [step, still to mark], oldest first
        watch(self.mark)

    def scalar(self, sim):
        newly, self.read = self.marked - self.read, self.marked
        return float(newly)

    def peratom(self, sim):
        return sim.particles.arrays[self.marker][: sim.particles.nlocal]

    def _open_packets(self, sim):
        """LIGGGHTS's add_remove_packets, at an insertion step."""
        step, interval = sim.step, self.stream.every
        if not self.every:
            if self.packets and self.packets[0][1] == 0:
                self.packets.pop(0)
            return
        while self.packets and (self.packets[0][0] < step - interval or self.packets[0][1] == 0):
            if self.packets[0][1] > 0:
                sim.warn(f"fix {self.id} (property/atom/tracer/stream): not all requested tracers could be "
                         f"marked (packet of step {self.packets[0][0]})")
            self.packets.pop(0)
        for start in range(self.args.mark_step + self.every, step + interval, self.every):
            if start > step:
                self.packets.append([start, self.args.n_tracer])

    def mark(self, sim, rows, release_steps):
        """Called by the insert/stream after each insertion on every rank (module docstring)."""
        self._open_packets(sim)
        if not self.packets:
            return
        p = sim.particles
        tags = p.tag[rows]
        chosen = (p.mask[rows] & sim.groups.bit(self.group)) != 0
        chosen &= release_steps >= self.packets[0][0]
        local = np.column_stack([release_steps[chosen], tags[chosen]]).astype(np.int64)
        candidates = np.asarray(sim.comm.allgather_rows(local), dtype=np.int64).reshape(-1, 2)
        candidates = candidates[np.argsort(candidates[:, 0], kind="stable")]
        chosen_tags = []
        packet = 0
        for release, tag in candidates:
            if release >= self.packets[packet][0]:
                chosen_tags.append(tag)
                self.packets[packet][1] -= 1
            if self.packets[packet][1] == 0:
                packet += 1
            if packet == len(self.packets):
                break
        self.marked += len(chosen_tags)
        if chosen_tags:
            marker = p.arrays[self.marker]
            n = p.nlocal
            marker[:n][np.isin(p.tag[:n], chosen_tags)] = 1.0
