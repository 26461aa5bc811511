r"""Fix ``spring/self``: each particle of the group tethered by a spring to where it was when the fix
was defined (LAMMPS's and LIGGGHTS's fix spring/self).

.. math::

    \mathbf{F}_i = -K\,(\mathbf{x}^u_i - \mathbf{x}^0_i), \qquad
    E = \tfrac12 K \sum_i |\mathbf{x}^u_i - \mathbf{x}^0_i|^2

over the components the direction word keeps (``xyz``, the default; ``xy``, ``xz``, ``yz``, ``x``,
``y``, ``z``), K the spring constant (force/distance), :math:`\mathbf{x}^u` the position unwrapped
through periodic images and :math:`\mathbf{x}^0` its unwrapped position at the definition, kept with
each particle (and in restart files: the fix given again after read_restart takes up its origins, as
LAMMPS's does). ``f_ID`` is the energy E (extensive); ``fix_modify ID energy yes`` adds it to thermo
pe. Applied in ``post_force``, at setup and in each minimization step.

Syntax::

    fix ID GROUP spring/self K [xyz|xy|xz|yz|x|y|z]

Example::

    fix tether solid spring/self 10.0 xy
"""

from typing import Literal

import numpy as np

from pdps_core.api import StyleArgs, param

from ._common import ForceFix


class FixSpringSelf(ForceFix):
    name = "spring/self"
    usage = "fix ID GROUP spring/self K [xyz|xy|xz|yz|x|y|z]"
    can_energy = True
    extensive = True

    class Args(StyleArgs):
        k: float = param(ge=0, unit="force/distance")
        direction: Literal["xyz", "xy", "xz", "yz", "x", "y", "z"] = param("xyz")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.kept = np.array([axis in args.direction for axis in "xyz"], dtype=np.float64)
        p = sim.particles
        self.origin_name = f"spring_self_origin_{id}"
        existed = p.has(self.origin_name)
        origin = p.request(self.origin_name, width=3, default=np.nan)
        n = p.nlocal
        # read_restart brings the particles, their origins among their values, before the script
        # gives the fix again: restore() puts back what this replaces
        self.replaced = (p.tag[:n].copy(), origin[:n].copy()) if existed else None
        chosen = sim.groups.select(sim, group)
        origin[:n][chosen] = self.unwrapped(sim)[chosen]
        self.energy = 0.0

    @staticmethod
    def unwrapped(sim):
        p = sim.particles
        n = p.nlocal
        return p.x[:n] + p.image[:n] * sim.box.length

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        origin = p.arrays[self.origin_name][:n]
        here = self.unwrapped(sim)
        # a particle that joined later is tethered where it is first seen
        late = chosen & np.isnan(origin).any(axis=1)
        origin[late] = here[late]
        delta = (here[chosen] - origin[chosen]) * self.kept
        p.f[:n][chosen] -= self.args.k * delta
        self.energy = 0.5 * self.args.k * float((delta * delta).sum())

    def compute_energy(self, sim):
        return self.energy

    def scalar(self, sim):
        return float(sim.comm.sum(self.energy))

    def state(self):
        return {"origin": self.origin_name}

    def restore(self, state):
        """The origins saved with the particles, which __init__ replaced (read_restart)."""
        if self.replaced is None:
            return
        p = self.sim.particles
        tags, saved = self.replaced
        n = p.nlocal
        if len(tags) and n:
            order = np.argsort(tags)
            where = np.minimum(np.searchsorted(tags[order], p.tag[:n]), len(tags) - 1)
            found = tags[order[where]] == p.tag[:n]
            p.arrays[self.origin_name][:n][found] = saved[order[where[found]]]
        self.replaced = None
