r"""Fix ``ehex``: the enhanced heat exchange algorithm (eHEX) of Wirnsberger, Frenkel & Dellago,
J. Chem. Phys. 143, 124104 (2015), as LAMMPS's fix ehex: every N steps the velocities of the group's
particles inside a region are scaled about their centre of mass to add the energy F N dt (fix heat's
HEX), and their positions are corrected at third order in dt, which removes the drift of the total
energy that HEX's scaling causes with velocity Verlet.

.. math::

    \mathbf{v}_i \leftarrow s\,\mathbf{v}_i - (s - 1)\,\mathbf{v}_R, \qquad
    s = \sqrt{1 + \frac{F N \Delta t}{K_R}}, \qquad
    K_R = \sum_{i\in R} \tfrac12 m_i v_i^2 - \tfrac12 M_R v_R^2

    \mathbf{x}_i \leftarrow \mathbf{x}_i - \Delta t^3\,\boldsymbol{\epsilon}_i, \qquad
    \boldsymbol{\epsilon}_i = \frac{\boldsymbol{\eta}_i}{m_i K_R}
        \left(\frac{F'}{48} + \frac{1}{6}\sum_{j\in R}\mathbf{f}_j\cdot(\mathbf{v}_j - \mathbf{v}_R)\right)
        - \frac{F'}{12 K_R}\left(\frac{\mathbf{f}_i}{m_i} - \frac{\mathbf{F}_R}{M_R}\right),
    \qquad \boldsymbol{\eta}_i = \frac{m_i F'}{2 K_R}(\mathbf{v}_i - \mathbf{v}_R)

with :math:`F' = F N`, :math:`\mathbf{v}_R` the reservoir's centre-of-mass velocity, :math:`M_R` its
mass and :math:`\mathbf{F}_R` the sum of its forces (Eq. 20 of the paper), all from the velocities and
forces at the end of the step; kinetic energies in mass*velocity^2 (energy times ftm2v, LAMMPS's).
The reservoir is the group's particles whose position, wrapped into the periodic box, lies in the
region at that step (all the group's without ``region``). ``hex`` leaves the positions alone: plain
HEX (fix heat's scaling, its factor from :math:`K_R`). The fix's scalar ``f_ID`` is the last factor
s (1 before the first application; intensive). A sink that would take more than the reservoir's
thermal kinetic energy stops the run, as LAMMPS's. Applied in ``end_of_step`` on steps that are
multiples of N.

Compared with LAMMPS 22 Jul 2025 (plugins/fix_simple/tests/test_ehex.py): an eHEX source and a HEX
sink of our own, every 1 and every 2 steps, to 10 digits over 200 steps, on 1 and 2 ranks.

Not supported: ``constrain`` and ``com`` (SHAKE/RATTLE's corrections after the scaling; pdps has no
fix shake or rattle, and LAMMPS refuses both without one), refused at the fix's line.

Syntax::

    fix ID GROUP ehex N F [region RID] [hex]

Example::

    region hot block INF INF INF INF 0 1
    fix hot all ehex 1 100.0 region hot
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, SimulationError, StyleArgs, keyword, observables, param

from .heat import region_of

NO_SHAKE = ("it applies fix shake's or rattle's constraints after the scaling, and pdps has neither "
            "(LAMMPS refuses it without one)")


@njit(cache=True)
def reservoir_properties(v, f, mass, inside, nlocal, sums):
    """sums <- (sum m v (3), sum m/2 v^2, sum m, sum f (3), sum f.v) over the owned particles
    ``inside``, in row order (LAMMPS's com_properties)."""
    sums[:] = 0.0
    for i in range(nlocal):
        if inside[i]:
            m = mass[i]
            sums[4] += m
            sums[3] += m / 2.0 * (v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2])
            sums[8] += f[i, 0] * v[i, 0] + f[i, 1] * v[i, 1] + f[i, 2] * v[i, 2]
            for d in range(3):
                sums[d] += m * v[i, d]
                sums[5 + d] += f[i, d]


@njit(cache=True)
def exchange(x, v, f, mass, inside, nlocal, scale, vr, sfr, mr, sfvr, kr, flux, dt, ftm2v, correct):
    """Each reservoir particle's position corrected by -dt^3 eps (``correct``) and its velocity scaled
    about v_R, component by component, as LAMMPS's FixEHEX::rescale."""
    for i in range(nlocal):
        if not inside[i]:
            continue
        mi = mass[i]
        for k in range(3):
            if correct:
                eta = mi * flux / (2.0 * kr) * (v[i, k] - vr[k])
                eps = (eta / (mi * kr) * (flux / 48.0 + sfvr / 6.0 * ftm2v)
                       - flux / (12.0 * kr) * (f[i, k] / mi - sfr[k] / mr) * ftm2v)
                x[i, k] -= dt * dt * dt * eps
            v[i, k] = scale * v[i, k] - (scale - 1.0) * vr[k]


class FixEHEX(Fix):
    name = "ehex"
    usage = "fix ID GROUP ehex N F [region RID] [hex]"
    refused = {"constrain": NO_SHAKE, "com": NO_SHAKE}

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        flux: float = param(unit="energy/time")
        region: str | None = keyword(None, names="region ID")
        hex: tuple[()] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.region is not None:
            region_of(sim, id, self.name, args.region)
        self.correct = args.hex is None
        self.scale = 1.0
        self.sums = np.zeros(9)
        self.vr = np.zeros(3)
        self.sfr = np.zeros(3)

    def init_run(self, sim):
        if observables.count(sim, self.group) == 0:
            raise ScriptError(f"fix {self.id} ehex: group {self.group} has no particles")

    def inside(self, sim):
        """The reservoir: the group's owned particles whose wrapped position is in the region."""
        p = sim.particles
        chosen = sim.groups.select(sim, self.group)
        if self.args.region is None:
            return chosen
        x = np.array(p.x[:p.nlocal])
        box = sim.box
        for d in range(3):
            if box.periodic[d]:
                x[x[:, d] < box.lo[d], d] += box.length[d]
                x[x[:, d] >= box.hi[d], d] -= box.length[d]
        return chosen & np.asarray(region_of(sim, self.id, self.name, self.args.region).match(x), dtype=bool)

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        p = sim.particles
        inside = self.inside(sim)
        mass = observables.masses(sim)
        reservoir_properties(p.v, p.f, mass, inside, p.nlocal, self.sums)
        total = np.asarray(sim.comm.sum(self.sums), dtype=np.float64)
        mr = float(total[4])
        if not mr >= 1e-14:
            where = f" inside region {self.args.region}" if self.args.region is not None else ""
            raise SimulationError(f"fix {self.id} ehex at step {sim.step}: the reservoir (group {self.group}{where}) "
                                  f"has no mass (LAMMPS's 'mass of region is close to zero')")
        self.vr[:] = total[0:3] / mr
        self.sfr[:] = total[5:8]
        vr, sfr = self.vr, self.sfr
        kr = float(total[3]) - 0.5 * mr * (vr[0] * vr[0] + vr[1] * vr[1] + vr[2] * vr[2])
        sfvr = float(total[8]) - (vr[0] * sfr[0] + vr[1] * sfr[1] + vr[2] * sfr[2])
        ftm2v = sim.units.ftm2v
        flux = self.args.flux * ftm2v * self.args.every
        if not kr > 0.0:
            raise SimulationError(f"fix {self.id} ehex at step {sim.step}: the reservoir has no kinetic energy "
                                  "about its centre of mass, which velocity scaling could change")
        escale = 1.0 + flux * sim.dt / kr
        if not escale >= 0.0:
            raise SimulationError(f"fix {self.id} ehex at step {sim.step}: the kinetic energy went negative "
                                  f"(removing {-flux * sim.dt / ftm2v:g} from a thermal kinetic energy of "
                                  f"{kr / ftm2v:g}; LAMMPS's 'Fix ehex kinetic energy went negative')")
        self.scale = math.sqrt(escale)
        exchange(p.x, p.v, p.f, mass, inside, p.nlocal, self.scale, vr, sfr, mr, sfvr, kr, flux, sim.dt, ftm2v,
                 self.correct)

    def scalar(self, sim):
        """f_ID: the velocity scale factor of the last application."""
        return self.scale
