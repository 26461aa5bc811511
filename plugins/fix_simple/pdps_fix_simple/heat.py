r"""Fix ``heat``: every N steps, add (or remove, for a negative flux) the energy EFLUX N dt to the group's
particles (those inside a region, with ``region``) by scaling their velocities relative to their
centre of mass, so that their momentum is unchanged: the heat exchange (HEX) of Ikeshoji & Hafskjold,
Mol. Phys. 81, 251 (1994), as LAMMPS's fix heat does it (a source and a sink of heat for the thermal
conductivity by non-equilibrium MD, LAMMPS's KAPPA/in.heat).

.. math::

    \mathbf{v}_i \leftarrow s\,\mathbf{v}_i - (s - 1)\,\mathbf{v}_\mathrm{cm}, \qquad
    s = \sqrt{\frac{K + Q - \tfrac12 M v_\mathrm{cm}^2}{K - \tfrac12 M v_\mathrm{cm}^2}},
    \qquad Q = \mathrm{EFLUX}\; N\, \Delta t

with K the particles' kinetic energy, M their mass and :math:`\mathbf{v}_\mathrm{cm}` their
centre-of-mass velocity at the end of the step: the kinetic energy changes by exactly Q, the momentum
not at all. EFLUX is in energy/time units; ``v_NAME`` (an equal-style variable) is evaluated at each
application (an atom-style one: below). The particles scaled are those of the group inside the region at
that step (the region is read as it is then, moving or not). The fix's scalar ``f_ID`` is the last
factor s (1 before the first application; intensive). A sink that would take more than the particles'
thermal kinetic energy (s^2 < 0) stops the run, as LAMMPS's ("kinetic energy went negative"). Applied in
``end_of_step`` on steps that are multiples of N.

Compared with LAMMPS 22 Jul 2025 (plugins/fix_simple/tests/test_heat.py): a source and a sink of
our own, one given by a variable, every 1 and every 2 steps, to 10 digits over 200 steps, on 1 and 2 ranks;
atom-style fluxes in a region and in the whole box, alike.

EFLUX as an atom-style variable ``v_NAME`` gives each particle i its own flux :math:`q_i`, as
LAMMPS's: :math:`s_i^2 = (K + q_i N \Delta t - \tfrac12 M v_\mathrm{cm}^2)/(K - \tfrac12 M
v_\mathrm{cm}^2)` with the reservoir's K, M and :math:`v_\mathrm{cm}`, and
:math:`\mathbf{v}_i \leftarrow s_i \mathbf{v}_i - \sum_j (s_j - 1) m_j \mathbf{v}_j / M`: the momentum is
kept, and the energy added is, to first order in dt, the mean of the :math:`q_i N \Delta t` weighted by
each particle's share of the thermal kinetic energy (a uniform :math:`q_i = q` adds exactly what
EFLUX q does). ``f_ID`` is then the mean of the :math:`s_i` of the last application.

Syntax::

    fix ID GROUP heat N EFLUX [region RID]

Example::

    region hot block INF INF INF INF 0 1
    fix hot all heat 1 100.0 region hot
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import (FloatOrVariable, Fix, ScriptError, SimulationError, StyleArgs, VariableRef, keyword,
                           observables, param)


@njit(cache=True)
def reservoir_sums(v, mass, inside, nlocal, sums):
    """sums <- (sum m, sum m v (3), sum m v^2) over the owned particles ``inside``, in row order."""
    sums[:] = 0.0
    for i in range(nlocal):
        if inside[i]:
            m = mass[i]
            sums[0] += m
            sums[1] += v[i, 0] * m
            sums[2] += v[i, 1] * m
            sums[3] += v[i, 2] * m
            sums[4] += (v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2]) * m


@njit(cache=True)
def scale_about(v, inside, nlocal, scale, vcm):
    """v <- s v - (s - 1) v_cm on the owned particles ``inside``."""
    for i in range(nlocal):
        if inside[i]:
            for d in range(3):
                v[i, d] = scale * v[i, d] - (scale - 1.0) * vcm[d]


@njit(cache=True)
def scale_each(v, mass, inside, nlocal, scales, vsub):
    """vsub <- sum (s_i - 1) v_i m_i over the owned particles ``inside`` (row order); the caller
    divides it by M over all ranks and ``shift_each`` applies v <- s_i v - vsub."""
    vsub[:] = 0.0
    for i in range(nlocal):
        if inside[i]:
            for d in range(3):
                vsub[d] += (scales[i] - 1.0) * v[i, d] * mass[i]


@njit(cache=True)
def shift_each(v, inside, nlocal, scales, vsub):
    """v <- s_i v - vsub on the owned particles ``inside``."""
    for i in range(nlocal):
        if inside[i]:
            for d in range(3):
                v[i, d] = scales[i] * v[i, d] - vsub[d]


def region_of(sim, fix_id, style, region):
    """The region a heat exchanger names, or the one-line error that it is not defined."""
    try:
        return sim.region(region)
    except ScriptError:
        raise ScriptError(f"fix {fix_id} {style}: region {region} is not defined") from None


class FixHeat(Fix):
    name = "heat"
    usage = "fix ID GROUP heat N EFLUX [region RID]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        eflux: FloatOrVariable = param(unit="energy/time")
        region: str | None = keyword(None, names="region ID")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.region is not None:
            region_of(sim, id, self.name, args.region)
        self.scale = 1.0
        self.sums = np.zeros(5)
        self.vcm = np.zeros(3)
        self.vsub = np.zeros(3)

    def init_run(self, sim):
        flux = self.args.eflux
        if isinstance(flux, VariableRef):
            if flux.name not in sim.variables:
                raise ScriptError(f"fix {self.id} heat: variable {flux.name} is not defined")
            if sim.variables.style(flux.name) not in ("equal", "internal", "atom"):
                raise ScriptError(f"fix {self.id} heat: EFLUX v_{flux.name} is a {sim.variables.style(flux.name)}-"
                                  "style variable; give an equal-style or atom-style one (LAMMPS's 'Variable for "
                                  "fix heat is invalid style')")
        if observables.count(sim, self.group) == 0:
            raise ScriptError(f"fix {self.id} heat: group {self.group} has no particles")

    def inside(self, sim):
        """The owned particles the exchange acts on now: the group's, inside the region if one is named."""
        p = sim.particles
        chosen = sim.groups.select(sim, self.group)
        if self.args.region is not None:
            chosen &= np.asarray(region_of(sim, self.id, self.name, self.args.region).match(p.x[:p.nlocal]), dtype=bool)
        return chosen

    def reservoir(self, sim, inside):
        """(M, v_cm, sum m v^2) of the particles ``inside``, over all ranks."""
        p = sim.particles
        reservoir_sums(p.v, observables.masses(sim), inside, p.nlocal, self.sums)
        total = np.asarray(sim.comm.sum(self.sums), dtype=np.float64)
        mass = float(total[0])
        if not mass > 0.0:
            where = f" inside region {self.args.region}" if self.args.region is not None else ""
            raise SimulationError(f"fix {self.id} {self.name} at step {sim.step}: no particles of group "
                                  f"{self.group}{where} to exchange heat with")
        return mass, total[1:4] / mass, float(total[4])

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        inside = self.inside(sim)
        mass, vcm, twice_ke = self.reservoir(sim, inside)
        ftm2v = sim.units.ftm2v
        # in mass * velocity^2, as LAMMPS: ke and heat times ftm2v (mvv2e ftm2v = 1)
        ke = twice_ke * (0.5 * sim.units.mvv2e) * ftm2v
        flux = self.args.eflux
        if isinstance(flux, VariableRef) and sim.variables.style(flux.name) == "atom":
            self.per_particle(sim, inside, mass, vcm, ke)
            return
        heat = float(sim.evaluate(flux)) * self.args.every * sim.dt * ftm2v
        drift = 0.5 * (vcm[0] * vcm[0] + vcm[1] * vcm[1] + vcm[2] * vcm[2]) * mass
        thermal = ke - drift
        if not thermal > 0.0:
            raise SimulationError(f"fix {self.id} heat at step {sim.step}: the particles have no kinetic energy "
                                  "about their centre of mass, which velocity scaling could change")
        escale = (ke + heat - drift) / thermal
        if not (escale >= 0.0 and math.isfinite(escale)):
            raise SimulationError(f"fix {self.id} heat at step {sim.step}: the kinetic energy went negative "
                                  f"(removing {-heat / ftm2v:g} from a thermal kinetic energy of "
                                  f"{thermal / ftm2v:g}; LAMMPS's 'Fix heat kinetic energy went negative')")
        self.scale = math.sqrt(escale)
        self.vcm[:] = vcm
        scale_about(sim.particles.v, inside, sim.particles.nlocal, self.scale, self.vcm)

    def per_particle(self, sim, inside, mass, vcm, ke):
        """An atom-style EFLUX: each particle's own factor s_i, the momentum kept by one shift."""
        p = sim.particles
        ftm2v = sim.units.ftm2v
        heat = np.asarray(sim.variables.atom_values(self.args.eflux.name), dtype=np.float64)
        heat = heat * self.args.every * sim.dt * ftm2v
        drift = 0.5 * (vcm[0] * vcm[0] + vcm[1] * vcm[1] + vcm[2] * vcm[2]) * mass
        thermal = ke - drift
        if not thermal > 0.0:
            raise SimulationError(f"fix {self.id} heat at step {sim.step}: the particles have no kinetic energy "
                                  "about their centre of mass, which velocity scaling could change")
        squares = (ke + heat - drift) / thermal
        negative = inside & ~(squares >= 0.0)
        if sim.comm.sum(int(negative.sum())):
            raise SimulationError(f"fix {self.id} heat at step {sim.step}: the kinetic energy of a particle went "
                                  "negative (its EFLUX takes more than the thermal kinetic energy; LAMMPS's 'Fix heat "
                                  "kinetic energy of an atom went negative')")
        scales = np.sqrt(np.where(inside, squares, 1.0))
        scale_each(p.v, observables.masses(sim), inside, p.nlocal, scales, self.vsub)
        self.vsub[:] = np.asarray(sim.comm.sum(self.vsub), dtype=np.float64) / mass
        shift_each(p.v, inside, p.nlocal, scales, self.vsub)
        count = sim.comm.sum(int(inside.sum()))
        self.scale = float(sim.comm.sum(float(np.sum(scales[inside])))) / count if count else 0.0

    def scalar(self, sim):
        """f_ID: the velocity scale factor of the last application (an atom-style EFLUX: their mean)."""
        return self.scale
