r"""Compute ``pressure``: the pressure of the whole system from the virial theorem, a scalar ``c_ID``
and the tensor ``c_ID[1-6]`` (xx yy zz xy xz yz), as LAMMPS's compute pressure.

.. math::

    P = \frac{N_\mathrm{dof} k_B T + \sum_i \mathbf{r}_i \cdot \mathbf{f}_i}{d\,V}, \qquad
    P_{ab} = \frac{\sum_i m_i v_{i,a} v_{i,b} + \sum_i r_{i,a} f_{i,b}}{V}

summed over owned and ghost particles (so periodic images count once), with T the temperature of
group ``all`` or, as in LAMMPS, of the temperature compute named (its T and its group's degrees of
freedom; the tensor's kinetic part is its group's), d the dimension and V the volume (area in
2-d), in pressure units.

Keywords choose the terms, as LAMMPS's (none: all of them): ``ke`` the kinetic part, ``pair`` the
pair style's virial, ``fix`` the virial of the fixes that add one (``fix_modify virial yes``),
``virial`` every virial term; LAMMPS's ``bond angle dihedral improper kspace`` are 0 in pdps.
Without ``ke`` the temperature may be ``NULL``.

Syntax::

    compute ID all pressure [TEMP-ID|NULL] [ke] [pair] [bond] [angle] [dihedral] [improper] [kspace] [fix] [virial]

The group must be ``all`` (PDPS manual). ``TEMP-ID`` is LAMMPS's spelling, naming a ``temp`` compute
whose temperature is used for the kinetic part.

Example::

    compute 2 all pressure
    compute pvirial all pressure NULL virial
"""

from typing import Literal

import numpy as np
from pydantic import Field

from pdps_core.api import Compute, ScriptError, StyleArgs, observables, param

TERMS = ("ke", "pair", "bond", "angle", "dihedral", "improper", "kspace", "fix", "virial")


class ComputePressure(Compute):
    name = "pressure"
    gives_pressure = True
    usage = ("compute ID all pressure [TEMP-ID|NULL] [ke] [pair] [bond] [angle] [dihedral] [improper] [kspace] "
             "[fix] [virial]")
    needs_virial = True

    class Args(StyleArgs):
        temperature: str | None = Field(default=None)
        terms: list[Literal[TERMS]] = param(default_factory=list)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if group != "all":
            raise ScriptError(f"compute pressure needs group all (got {group})")
        temperature = args.temperature
        if temperature in TERMS:
            raise ScriptError(f"compute pressure: {temperature} where the temperature compute's ID (or NULL) "
                              "goes; the keywords follow it")
        terms = set(args.terms or TERMS)
        self.ke = "ke" in terms
        self.pair = bool(terms & {"pair", "virial"})
        self.fix = bool(terms & {"fix", "virial"})
        if temperature == "NULL" and self.ke:
            raise ScriptError("compute pressure: the kinetic part (ke) needs a temperature compute, not NULL")
        if temperature not in (None, "NULL") and temperature not in sim.computes:
            raise ScriptError(f"compute {temperature} is not defined (temperature for pressure)")
        self.every_term = self.ke and self.pair and self.fix

    @property
    def temperature(self):
        """The temperature compute's ID, or None (fix_modify temp may change it after the compute)."""
        return None if self.args.temperature in (None, "NULL") else self.args.temperature

    def _temperature_group(self):
        return "all" if self.temperature is None else self.sim.computes[self.temperature].group

    def _virial(self, sim):
        pair, fixes = observables.virial_parts(sim)
        return pair * self.pair + fixes * self.fix

    def scalar(self, sim):
        if self.every_term and self.temperature is None:
            return observables.pressure(sim)
        if self.every_term:
            return observables.pressure(sim, sim.compute_value(self.temperature),
                                        dof=observables.compute_dof(sim, sim.computes[self.temperature]))
        kinetic = 0.0
        if self.ke:
            temp = sim.compute_value(self.temperature) if self.temperature else None
            group = self._temperature_group()
            if temp is None:
                temp = observables.temperature(sim, group)
            dof = observables.compute_dof(sim, sim.computes[self.temperature]) if self.temperature else \
                observables.degrees_of_freedom(sim, group)
            kinetic = dof * sim.units.boltz * temp
        virial = float(self._virial(sim)[: sim.dimension].sum())
        return (kinetic + virial) / (sim.dimension * sim.box.volume) * sim.units.nktv2p

    def vector(self, sim):
        if self.every_term:
            return observables.pressure_tensor(sim, self._temperature_group())
        tensor = self._virial(sim)
        if self.ke:
            tensor = tensor + observables.kinetic_tensor(sim, self._temperature_group())
        return np.asarray(tensor) / sim.box.volume * sim.units.nktv2p
