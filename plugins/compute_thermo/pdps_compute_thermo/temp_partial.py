r"""Compute ``temp/partial``: the temperature of a group from the velocity components chosen, a
scalar read as ``c_ID`` (LAMMPS's compute temp/partial).

.. math::

    T = \frac{\sum_i m_i \sum_{a \in F} v_{i,a}^2}{N_\mathrm{dof}\, k_B}, \qquad
    N_\mathrm{dof} = n_F N - \frac{n_F}{d}\,(d + N_\mathrm{fix})

with F the components whose flag is 1 (n_F of them), N the particles in the group, d the dimension
and N_fix the degrees of freedom fixes remove (rigid bodies, constraints); ``compute_modify extra/dof``
replaces the d inside the bracket. The components left out are the group's bias: a thermostat given
this compute (``fix_modify ID temp CID``) scales only the chosen components, as LAMMPS's do.

Syntax::

    compute ID GROUP temp/partial XFLAG YFLAG ZFLAG        # each 0 or 1

Example::

    compute new mobile temp/partial 0 1 0
    fix 3 mobile temp/rescale 200 0.1 0.1 0.02 1.0
    fix_modify 3 temp new
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, observables, param


class ComputeTempPartial(Compute):
    name = "temp/partial"
    gives_temperature = True
    usage = "compute ID GROUP temp/partial XFLAG YFLAG ZFLAG"
    extra_dof = None        # compute_modify extra/dof (None: the dimension)

    class Args(StyleArgs):
        xflag: int = param(ge=0, le=1, unit="dimensionless")
        yflag: int = param(ge=0, le=1, unit="dimensionless")
        zflag: int = param(ge=0, le=1, unit="dimensionless")

    def __init__(self, sim, ident, group, args):
        super().__init__(sim, ident, group, args)
        self.flags = np.array([self.args.xflag, self.args.yflag, self.args.zflag], dtype=np.float64)
        if sim.dimension == 2 and self.args.zflag:
            raise ScriptError("zflag 1 in a 2d simulation, which has no z velocity")

    def dof(self, sim):
        chosen = float(self.flags.sum())
        d = sim.dimension
        full = observables.degrees_of_freedom(sim, self.group, self.extra_dof)
        # LAMMPS's: n_F N - n_F/d (extra + fix), the group's d N - extra - fix scaled by n_F / d
        return chosen / d * full

    def scalar(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        v = p.v[:n][chosen]
        twice_ke = float(np.sum(observables.masses(sim, chosen) * ((v * v) @ self.flags)))
        dof = self.dof(sim)
        total = sim.comm.sum(twice_ke)
        return total * sim.units.mvv2e / (dof * sim.units.boltz) if dof > 0 else 0.0

    def velocity_bias(self, sim):
        """The velocity components this temperature leaves out, per owned particle."""
        p = sim.particles
        return p.v[:p.nlocal] * (1.0 - self.flags)
