r"""Fix ``ave/atom``: per-particle values averaged over time (LAMMPS's and LIGGGHTS's fix ave/atom).

Syntax::

    fix ID GROUP ave/atom NEVERY NREPEAT NFREQ value1 value2 ...

Each value, for each particle of the group, is averaged over NREPEAT samples taken NEVERY steps
apart, the last on a multiple of NFREQ (schedule.py: LAMMPS's rule, as fix ave/time):

.. math::  \bar a_i = \frac{1}{N_\mathrm{repeat}}\sum_{k=1}^{N_\mathrm{repeat}} a_i(t_k)

Values (LAMMPS's list): ``x y z vx vy vz fx fy fz`` (positions as stored, wrapped into the box),
``c_ID``, ``c_ID[k]``, ``f_ID``, ``f_ID[k]`` (per-atom values of a compute or fix) and ``v_NAME`` (an
atom-style variable); unwrapped positions through ``compute property/atom xu``. ``f_ID`` is the average of one value per particle, ``f_ID[k]``
of value k (counted from the dialect's first index) for several; between two averages it holds the
last one, before the first 0, and 0 for particles outside the group. The sums and the averages are
kept with the particles (they move with them between ranks and through re-sorting).

Example::

    fix 1 all ave/atom 1 100 100 vx vy vz
    dump 1 all custom 100 v.dump id f_1[1] f_1[2] f_1[3]
"""

import numpy as np

from pdps_core.api import Fix, PeratomReference, ScriptError, param

from .schedule import Schedule, ScheduleArgs

COMPONENTS = {"x": ("x", 0), "y": ("x", 1), "z": ("x", 2), "vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2),
              "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2)}


class FixAveAtom(Fix):
    name = "ave/atom"
    usage = "fix ID GROUP ave/atom NEVERY NREPEAT NFREQ value1 value2 ..."

    class Args(ScheduleArgs):
        values: list[str] = param(min_length=1, names="value (x, vx, fx, xu, c_ID, f_ID[k], v_NAME, ...)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.readers = []
        for word in args.values:
            if word in COMPONENTS:
                self.readers.append(word)
            elif word[:2] in ("c_", "f_", "v_"):
                self.readers.append(PeratomReference(sim, word, f"fix {id} ave/atom value {word}"))
            else:
                raise ScriptError(f"fix {id} ave/atom: unknown value {word} (x y z vx vy vz fx fy fz, c_ID, "
                                  "c_ID[k], f_ID, f_ID[k] or v_NAME)")
        width = len(self.readers)
        p = sim.particles
        self.sum_name, self.mean_name = f"ave_atom_sum_{id}", f"ave_atom_mean_{id}"
        p.request(self.sum_name, width=width, default=0.0, ghost=False)
        p.request(self.mean_name, width=width, default=0.0, ghost=False)
        self.schedule = Schedule(args.nevery, args.nrepeat, args.nfreq, sim.step)

    def _sample(self, sim):
        p = sim.particles
        n = p.nlocal
        columns = []
        for reader in self.readers:
            if isinstance(reader, PeratomReference):
                columns.append(np.asarray(reader.values(sim), dtype=np.float64))
            else:
                array, d = COMPONENTS[reader]
                columns.append(p.arrays[array][:n, d])
        return np.column_stack(columns) if columns else np.zeros((n, 0))

    def needs(self, step):
        if step != self.schedule.due:
            return set()
        wanted = set()
        for reader in self.readers:
            if isinstance(reader, PeratomReference):
                wanted |= reader.needs(self.sim)
        return wanted

    def setup(self, sim):
        self.schedule.run_setup(sim.step)
        self.end_of_step(sim)

    def end_of_step(self, sim):
        if sim.step != self.schedule.due:
            return
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        total = p.arrays[self.sum_name][:n].reshape(n, -1)
        total[chosen] += self._sample(sim)[chosen]
        if self.schedule.advance(sim.step):
            mean = p.arrays[self.mean_name][:n].reshape(n, -1)
            mean[:] = 0.0
            mean[chosen] = total[chosen] / self.args.nrepeat
            total[:] = 0.0

    def peratom(self, sim):
        return sim.particles.arrays[self.mean_name][:sim.particles.nlocal]
