r"""Fix ``buoyancy``: the buoyancy of spheres in a fluid at rest that fills space below a level
(LIGGGHTS's fix buoyancy).

With the script's one fix gravity of acceleration :math:`\mathbf{g}` along axis ``dim`` (its sign
:math:`s = \pm 1` along the axis), a fluid of density :math:`\rho_f` fills the side of the plane
:math:`x_{dim} = L` that gravity points to. Each sphere of radius R, its centre a distance
:math:`h = s\,(x_{dim} - L)` into the fluid, feels

.. math::

    F_{dim} = -s\,|\mathbf{g}|\,\rho_f\,V_\mathrm{im}, \qquad
    V_\mathrm{im} = \begin{cases} 0 & h < -R \\
    V_\mathrm{cap}(R + h) & -R \le h \le 0 \\
    \tfrac43\pi R^3 - V_\mathrm{cap}(R - h) & 0 < h \le R \\
    \tfrac43\pi R^3 & h > R \end{cases}

with :math:`V_\mathrm{cap}(c) = \tfrac{\pi}{6} c\,(3a^2 + c^2)`, :math:`a^2 = 2Rc - c^2`, the volume of a
spherical cap of height c: the weight of the fluid the immersed part displaces, against gravity.
The total buoyancy force on the group at the last step is ``f_ID[1-3]`` (force units). Applied in
``post_force`` and at setup, as LIGGGHTS's; the direction of gravity is read every step.

Parameters:

- ``density RHO``: the fluid's density (mass/volume, > 0).
- ``dim x|y|z``: the axis gravity acts along (fix gravity must point along it).
- ``level L`` (optional): where the fluid's surface is on that axis (distance; LIGGGHTS requires
  L > 0 when it is given, and takes 0 without it).
- ``region RID`` (optional): act only on particles inside region RID.

Syntax::

    fix ID GROUP buoyancy density RHO dim x|y|z [level L] [region RID]

Example::

    fix grav all gravity 9.81 vector 0 0 -1
    fix float all buoyancy density 1000 level 0.05 dim z
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, StyleArgs, keyword

from ._common import AXES, ForceFix, chosen, require_spheres
from .gravity import FixGravity

NO_SELECTION = np.zeros(0, dtype=np.bool_)


@njit(cache=True)
def add_buoyancy(x, f, radius, mask, groupbit, selected, nlocal, axis, level, sign, weight_density, total):
    """f[:, axis] += the buoyancy of each sphere of the group (of ``selected`` when not empty);
    the forces' sum into total[axis]."""
    pi6 = math.pi / 6.0
    ball = 4.0 * math.pi / 3.0
    use_selected = len(selected) > 0
    total[:] = 0.0
    for i in range(nlocal):
        if not mask[i] & groupbit or (use_selected and not selected[i]):
            continue
        r = radius[i]
        h = (x[i, axis] - level) * sign
        if abs(h) > r and h < 0.0:
            continue
        if abs(h) > r:
            immersed = ball * r * r * r
        elif h > 0.0:
            c = r - h
            immersed = ball * r * r * r - c * pi6 * (3.0 * (2.0 * r * c - c * c) + c * c)
        else:
            c = r + h
            immersed = c * pi6 * (3.0 * (2.0 * r * c - c * c) + c * c)
        force = -sign * weight_density * immersed
        f[i, axis] += force
        total[axis] += force


class FixBuoyancy(ForceFix):
    name = "buoyancy"
    usage = "fix ID GROUP buoyancy density RHO dim x|y|z [level L] [region RID]"

    class Args(StyleArgs):
        density: float | None = keyword(None, gt=0, unit="density")
        dim: Literal["x", "y", "z"] | None = keyword(None)
        level: float | None = keyword(None, gt=0, unit="distance")
        region: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.dim is None:
            raise ScriptError("fix buoyancy needs dim x|y|z, the axis gravity acts along")
        if args.density is None:
            raise ScriptError("fix buoyancy needs density RHO, the fluid's density")
        require_spheres(sim, "fix buoyancy")
        if args.region is not None:
            sim.region(args.region)
        self.axis = AXES[args.dim]
        self.level = 0.0 if args.level is None else args.level
        self.total = np.zeros(3)

    def _find_gravity(self, sim):
        fixes = [fix for fix in sim.fixes.values() if isinstance(fix, FixGravity)]
        if len(fixes) != 1:
            raise ScriptError(f"fix {self.id} (buoyancy) needs exactly one fix gravity (found {len(fixes)})")
        return fixes[0]

    def _gravity(self, sim):
        """(the sign of gravity along dim, |g|), read every step as LIGGGHTS reads it."""
        g = np.asarray(self.gravity.acceleration)
        across = np.delete(g, self.axis)
        if np.any(across != 0.0) or g[self.axis] == 0.0:
            raise ScriptError(f"fix {self.id} (buoyancy): fix {self.gravity.id} (gravity) does not point along "
                              f"dim {self.args.dim} (its acceleration {g.tolist()})")
        return math.copysign(1.0, g[self.axis]), float(np.linalg.norm(g))

    def setup(self, sim):
        self.gravity = self._find_gravity(sim)
        self._gravity(sim)
        super().setup(sim)

    def post_force(self, sim):
        sign, g = self._gravity(sim)
        p = sim.particles
        selected = NO_SELECTION if self.args.region is None else chosen(sim, self.group, self.args.region)
        add_buoyancy(p.x, p.f, p.radius, p.mask, sim.groups.bit(self.group), selected, p.nlocal, self.axis,
                     self.level, sign, g * self.args.density, self.total)

    def vector(self, sim):
        return sim.comm.sum(self.total)
