r"""Compute ``heat/flux``: the heat flux vector of a group, times the volume (LAMMPS's compute
heat/flux), for Green-Kubo thermal conductivity:

.. math::

    \mathbf{J} V = \sum_i e_i \mathbf{v}_i - \sum_i \mathbf{S}_i \mathbf{v}_i

with :math:`e_i` the particle's kinetic plus potential energy (from a ``ke/atom`` and a
``pe/atom`` compute) and :math:`\mathbf{S}_i` its stress times volume (a ``stress/atom`` compute,
divided by ``nktv2p`` to energy units), in energy*velocity units. Six values:
``c_ID[1..3]`` the flux, ``c_ID[4..6]`` its convective part :math:`\sum_i e_i \mathbf{v}_i`
(LAMMPS's order). Extensive: thermo divides them by the particle count in lj units, as LAMMPS;
a variable reads them as they are (the example divides by ``vol``). Only particles in this
compute's group count; the three computes' own groups give their values (0 outside). The pair
style's per-particle energies and virials are tallied on the steps this compute is read.

Syntax::

    compute ID GROUP heat/flux KE_ID PE_ID STRESS_ID

Example (LAMMPS's examples/KAPPA/in.heatflux)::

    compute myKE all ke/atom
    compute myPE all pe/atom
    compute myStress all stress/atom NULL virial
    compute flux all heat/flux myKE myPE myStress
    variable Jx equal c_flux[1]/vol
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, param

# the compute each argument must name: LAMMPS's checks of style (ke/atom) and flags (pe, stress)
INPUTS = (("ke", "ke/atom"), ("pe", "pe/atom"), ("stress", "stress/atom"))


class ComputeHeatFlux(Compute):
    name = "heat/flux"
    usage = "compute ID GROUP heat/flux KE_ID PE_ID STRESS_ID"
    needs_energy = True
    needs_virial = True
    extensive = True

    class Args(StyleArgs):
        ke: str = param(names="KE_ID (a ke/atom compute)")
        pe: str = param(names="PE_ID (a pe/atom compute)")
        stress: str = param(names="STRESS_ID (a stress/atom compute)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        for field, style in INPUTS:
            ident = getattr(args, field)
            compute = sim.computes.get(ident)
            if compute is None:
                raise ScriptError(f"compute {id} heat/flux: compute {ident} is not defined")
            if compute.name != style:
                raise ScriptError(f"compute {id} heat/flux: compute {ident} is {compute.name}, not {style}")

    def _input(self, sim, field):
        # looked up at each call: the ID may have been redefined since this compute was made
        ident = getattr(self.args, field)
        compute = sim.computes.get(ident)
        if compute is None:
            raise ScriptError(f"compute {self.id} heat/flux: compute {ident} is not defined")
        return np.asarray(compute.peratom(sim), dtype=np.float64)

    def vector(self, sim):
        n = sim.particles.nlocal
        chosen = sim.groups.select(sim, self.group)
        v = sim.particles.v[:n][chosen]
        energy = (self._input(sim, "ke") + self._input(sim, "pe"))[chosen]
        s = self._input(sim, "stress")[chosen]
        convective = (energy[:, None] * v).sum(axis=0)
        virial = -np.array([
            (s[:, 0] * v[:, 0] + s[:, 3] * v[:, 1] + s[:, 4] * v[:, 2]).sum(),
            (s[:, 3] * v[:, 0] + s[:, 1] * v[:, 1] + s[:, 5] * v[:, 2]).sum(),
            (s[:, 4] * v[:, 0] + s[:, 5] * v[:, 1] + s[:, 2] * v[:, 2]).sum()]) / sim.units.nktv2p
        local = np.concatenate([convective + virial, convective])
        return np.asarray(sim.comm.sum(local), dtype=np.float64)
