r"""Fix ``store/state``: per-particle values kept as they were at one time, or refreshed every N steps
(LAMMPS's and LIGGGHTS's fix store/state): a particle's start position for a displacement, its
energy at the last output.

Each input is an attribute (``x y z xu yu zu vx vy vz fx fy fz ix iy iz id type mass radius
omegax omegay omegaz tqx tqy tqz``, as compute property/atom names them), ``c_ID``/``c_ID[k]``,
``f_ID``/``f_ID[k]`` (per-atom values) or ``v_NAME`` (an atom-style variable). Attributes are
stored when the fix is defined; the compute, fix and variable values at the first run's start
(when they can first be evaluated), as LAMMPS stores them. With N > 0 all are stored again at the
end of every step that is a multiple of N; with N = 0 never again. ``com yes`` stores ``xu yu zu``
relative to the centre of mass of the fix's group. Particles outside the group, and those created
later, hold 0.

Output: per-atom values, ``f_ID`` for one input, ``f_ID[k]`` (from the dialect's first index) for
several, read by compute reduce and dump custom; they move with their particles and are written
to restart files.

Syntax::

    fix ID GROUP store/state N input... [com yes|no]

Example::

    fix start all store/state 0 xu yu zu
    compute dx all reduce ave v_dx
"""

from typing import Literal

import numpy as np

from pdps_core.api import Fix, PeratomReference, ScriptError, StyleArgs, keyword, param

from .com import centre_of_mass
from .peratom import ATTRIBUTES, REFERENCE, attribute, check_attribute

VARIABLE_PREFIX = "v_"
RELATIVE = {"xu": 0, "yu": 1, "zu": 2}


class FixStoreState(Fix):
    name = "store/state"
    usage = "fix ID GROUP store/state N input... [com yes|no]"

    class Args(StyleArgs):
        nevery: int = param(ge=0, unit="timesteps")
        inputs: list[str] = param(min_length=1, names="input (x, xu, vx, c_ID, f_ID[k], v_NAME, ...)")
        com: Literal["yes", "no"] = keyword("no")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        what = f"fix {id} store/state"
        self.references = {}
        for word in args.inputs:
            if word in ATTRIBUTES:
                check_attribute(sim, word, what)
            elif REFERENCE.match(word) or word.startswith(VARIABLE_PREFIX):
                self.references[word] = None        # read at the first setup, when it can be evaluated
            else:
                raise ScriptError(f"{what}: unknown input {word} (an attribute, c_ID, c_ID[k], f_ID, f_ID[k] "
                                  "or v_NAME)")
        self.values_name = f"store_state_{id}"
        self.stored = sim.particles.request(self.values_name, width=len(args.inputs), ghost=False)
        self.first = True
        self._store(sim, attributes=True, others=False)

    def _store(self, sim, attributes, others):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        stored = p.arrays[self.values_name][:n]
        centre = centre_of_mass(sim, self.group) if self.args.com == "yes" and attributes else None
        for k, word in enumerate(self.args.inputs):
            if word in ATTRIBUTES:
                if not attributes:
                    continue
                values = attribute(sim, word)
                if centre is not None and word in RELATIVE:
                    values = values - centre[RELATIVE[word]]
            else:
                if not others:
                    continue
                if self.references[word] is None:
                    self.references[word] = PeratomReference(sim, word, f"fix {self.id} store/state: {word}")
                values = self.references[word].values(sim)
            stored[:, k] = np.where(chosen, values, 0.0)

    def needs(self, step):
        # the computes and variables stored may read energies, as a thermo step's would
        due = self.args.nevery and step % self.args.nevery == 0
        return {"energy", "virial"} if due and self.references else set()

    def setup(self, sim):
        if self.first:
            self.first = False
            self._store(sim, attributes=False, others=True)

    def end_of_step(self, sim):
        if self.args.nevery and sim.step % self.args.nevery == 0:
            self._store(sim, attributes=True, others=True)

    def peratom(self, sim):
        values = sim.particles.arrays[self.values_name][: sim.particles.nlocal]
        return values[:, 0] if values.shape[1] == 1 else values
