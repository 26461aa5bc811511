r"""Compute ``temp/sphere``: the temperature of a group of spheres from their translational and
rotational kinetic energy, a scalar read as ``c_ID`` (LAMMPS's compute temp/sphere).

.. math::

    T = \frac{\sum_i \left(m_i v_i^2 + I_i \omega_i^2\right)}{N_\mathrm{dof}\, k_B}, \qquad
    I_i = \tfrac25 m_i r_i^2, \qquad
    N_\mathrm{dof} = \sum_i n_i - d - N_\mathrm{fix}

with :math:`n_i` 6 for a sphere in 3-d (3 translations, 3 rotations) and 3 for a point particle
(radius 0), 3 and 2 in 2-d; d the dimension (``compute_modify extra/dof`` replaces it) and
N_fix what fixes remove (rigid bodies, constraints). ``dof rotate`` counts the rotations alone:
:math:`m_i v_i^2` leaves the sum, :math:`n_i` is 3 (1 in 2-d) for a sphere and 0 for a point, and no
d is taken off. The vector ``c_ID[1..6]`` is the kinetic energy tensor
:math:`\sum m_i v_a v_b + I_i \omega_a \omega_b` (xx, yy, zz, xy, xz, yz; energy units), rotations
only with ``dof rotate``. The degrees of freedom are counted at each call, so particles inserted or
lost count at once (LAMMPS's ``compute_modify dynamic/dof yes``).

Syntax::

    compute ID GROUP temp/sphere [dof all|rotate]

``bias CID`` (a bias compute's velocity removed first) is refused at the line.

Example::

    compute 2 all temp/sphere
    thermo_style custom step atoms temp c_2
"""

from typing import Literal

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, keyword, observables

INERTIA = 0.4   # solid sphere


class ComputeTempSphere(Compute):
    name = "temp/sphere"
    gives_temperature = True
    extensive_vector = True     # the kinetic energy tensor, a total (LAMMPS's extvector)
    usage = "compute ID GROUP temp/sphere [dof all|rotate]"
    extra_dof = None        # compute_modify extra/dof (None: the dimension; 0 with dof rotate)

    class Args(StyleArgs):
        dof: Literal["all", "rotate"] = keyword("all")
        bias: str | None = keyword(None)

    def __init__(self, sim, ident, group, args):
        if "sphere" not in sim.particle_styles:
            raise ScriptError("compute temp/sphere needs particle_style sphere (radius, rmass, omega)")
        super().__init__(sim, ident, group, args)
        if self.args.bias is not None:
            raise ScriptError(f"bias {self.args.bias}: compute temp/sphere with a velocity bias is not in pdps")
        self.rotate_only = self.args.dof == "rotate"
        if self.rotate_only:
            self.extra_dof = 0

    def dof(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        spheres = int(np.count_nonzero(p.radius[:n][chosen] > 0.0))
        points = int(np.count_nonzero(chosen)) - spheres
        per_sphere, per_point = (3, 2) if sim.dimension == 2 else (6, 3)
        if self.rotate_only:
            per_sphere, per_point = per_sphere - sim.dimension, 0
        counted = sim.comm.sum(per_sphere * spheres + per_point * points)
        removed = observables.dof_removed(sim, self.group)
        extra = sim.dimension if self.extra_dof is None else self.extra_dof
        return counted - extra - removed

    def _tensor(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        m = p.rmass[:n][chosen]
        w = p.omega[:n][chosen]
        inertia = INERTIA * m * p.radius[:n][chosen] ** 2
        pairs = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))
        t = np.array([np.sum(inertia * w[:, a] * w[:, b]) for a, b in pairs])
        if not self.rotate_only:
            v = p.v[:n][chosen]
            t += np.array([np.sum(m * v[:, a] * v[:, b]) for a, b in pairs])
        return np.array([sim.comm.sum(float(value)) for value in t])

    def scalar(self, sim):
        twice_ke = float(np.sum(self._tensor(sim)[:3]))
        dof = self.dof(sim)
        if dof < 0 and observables.count(sim, self.group) > 0:
            raise ScriptError(f"compute {self.id} temp/sphere: degrees of freedom < 0 ({dof})")
        return twice_ke * sim.units.mvv2e / (dof * sim.units.boltz) if dof > 0 else 0.0

    def vector(self, sim):
        return self._tensor(sim) * sim.units.mvv2e
