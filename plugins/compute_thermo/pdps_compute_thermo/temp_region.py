r"""Compute ``temp/region``: the temperature of the group's particles inside a region now, a scalar
read as ``c_ID`` (LAMMPS's compute temp/region).

.. math::

    T = \frac{\sum_{i \in R} m_i v_i^2}{N_\mathrm{dof}\, k_B}, \qquad N_\mathrm{dof} = d\,N_R - d

with N_R the group's particles inside the region R at the time it is read and d the dimension;
``compute_modify extra/dof`` replaces the second d. As LAMMPS's, the degrees of freedom fixes remove
(rigid bodies, constraints) are not taken off. The particles outside the region are its bias: a
thermostat given this compute (``fix_modify ID temp CID``) leaves them alone.

Syntax::

    compute ID GROUP temp/region REGION

Example::

    region hot block INF INF INF INF 0 2
    compute Thot all temp/region hot
    fix hot all temp/rescale 10 1.5 1.5 0.0 1.0
    fix_modify hot temp Thot
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, observables, param


class ComputeTempRegion(Compute):
    name = "temp/region"
    gives_temperature = True
    usage = "compute ID GROUP temp/region REGION"
    extra_dof = None        # compute_modify extra/dof (None: the dimension)

    class Args(StyleArgs):
        region: str = param(description="the region whose particles count")

    def __init__(self, sim, ident, group, args):
        super().__init__(sim, ident, group, args)
        self._region(sim)

    def _region(self, sim):
        try:
            return sim.region(self.args.region)
        except ScriptError:
            raise ScriptError(f"compute temp/region: region {self.args.region} is not defined") from None

    def _inside(self, sim):
        p = sim.particles
        return sim.groups.select(sim, self.group) & self._region(sim).match(p.x[:p.nlocal])

    def dof(self, sim):
        count = sim.comm.sum(int(self._inside(sim).sum()))
        extra = sim.dimension if self.extra_dof is None else self.extra_dof
        return sim.dimension * count - extra

    def scalar(self, sim):
        inside = self._inside(sim)
        p = sim.particles
        v = p.v[:p.nlocal][inside]
        twice_ke = sim.comm.sum(float(np.sum(observables.masses(sim, inside) * np.einsum("ij,ij->i", v, v))))
        dof = self.dof(sim)
        return twice_ke * sim.units.mvv2e / (dof * sim.units.boltz) if dof > 0 else 0.0

    def velocity_bias(self, sim):
        """The velocities this temperature leaves out: those of the particles outside the region."""
        p = sim.particles
        outside = ~self._region(sim).match(p.x[:p.nlocal])
        return p.v[:p.nlocal] * outside[:, None]
