r"""Compute ``pressure``: the pressure of the whole system from the virial theorem, a scalar ``c_ID``.

.. math::

    P = \frac{N_\mathrm{dof} k_B T + \sum_i \mathbf{r}_i \cdot \mathbf{f}_i}{d\,V}

summed over owned and ghost particles (so periodic images count once), with T the temperature of
group ``all`` or, as in LAMMPS, of the temperature compute named (its T and its group's degrees of
freedom), d the dimension and V the volume (area in 2-d).

Syntax::

    compute ID all pressure [TEMP-ID]

The group must be ``all`` (PDPS manual). ``TEMP-ID`` is LAMMPS's spelling, naming a ``temp`` compute
whose temperature is used for the kinetic part.

Example::

    compute 2 all pressure
"""

from pydantic import Field

from pdps_core.api import Compute, ScriptError, StyleArgs, observables


class ComputePressure(Compute):
    name = "pressure"
    gives_pressure = True
    usage = "compute ID all pressure [TEMP-ID]"
    needs_virial = True

    class Args(StyleArgs):
        temperature: str | None = Field(default=None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if group != "all":
            raise ScriptError(f"compute pressure needs group all (got {group})")
        if args.temperature is not None and args.temperature not in sim.computes:
            raise ScriptError(f"compute {args.temperature} is not defined (temperature for pressure)")

    def scalar(self, sim):
        if self.args.temperature is None:
            return observables.pressure(sim)
        compute = sim.computes[self.args.temperature]
        return observables.pressure(sim, sim.compute_value(self.args.temperature), compute.group)
