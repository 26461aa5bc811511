r"""Fix ``langevin``: a Langevin thermostat (Schneider & Stoll, Phys. Rev. B 17, 1302 (1978); LAMMPS's
fix langevin), with the target temperature ramped linearly over a run.

Each particle of the group feels, besides its other forces, a friction and a random force:

.. math::

    \mathbf{F}_i \mathrel{+}= -\frac{m_i}{\tau}\mathbf{v}_i
        + \sqrt{\frac{24\, k_B T(t)\, m_i}{\Delta t\,\tau}}\;(\mathbf{u}_i - \tfrac12),
    \qquad T(t) = T_\mathrm{start} + (T_\mathrm{stop} - T_\mathrm{start})\,
                  \frac{t - t_\mathrm{first}}{t_\mathrm{last} - t_\mathrm{first}}

with :math:`\mathbf{u}_i` three uniform numbers in (0, 1) (variance 1/12, so the random force has
variance :math:`2 k_B T m_i / (\Delta t\,\tau)`, as LAMMPS's), drawn from the counter-based
generator keyed by (seed, step, particle id): the noise does not depend on particle order or on
the number of ranks. LAMMPS draws from a per-rank Marsaglia generator, so trajectories differ from
LAMMPS's while the statistics agree. The ramp runs over the run in which the fix is active (LAMMPS's
``ramp``): first step of the run at T_START, last at T_STOP. Applied in ``post_force`` and at setup.
The fix only adds forces: an integrator (fix nve) moves the particles.

Parameters:

- ``T_START``, ``T_STOP``: target temperature at the first and last step of a run (>= 0,
  temperature units).
- ``DAMP``: the damping time :math:`\tau` (> 0, time units): the friction relaxes velocities over
  :math:`\tau`, kinetic energy over :math:`\tau/2`.
- ``SEED``: integer >= 1.

Syntax::

    fix ID GROUP langevin T_START T_STOP DAMP SEED

Example::

    fix heat all langevin 1.0 1.5 0.1 48279
    fix 2 all nve
"""

import math

from numba import njit

from pdps_core.api import Fix, StyleArgs, observables, param, particle_uniforms

STREAM = 1      # the generator stream of this fix's draws


@njit(cache=True)
def langevin_forces(v, f, tag, mass, mask, groupbit, nlocal, damp, noise_scale, seed, step):
    """Friction -m v/damp and noise sqrt(24 kT m/(dt damp)) (u - 1/2); ``noise_scale`` is
    sqrt(24 kT / (dt damp)) in the run's units."""
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        m = mass[i]
        u0, u1, u2, _ = particle_uniforms(seed, step, tag[i], STREAM)
        amplitude = noise_scale * math.sqrt(m)
        friction = m / damp
        f[i, 0] += -friction * v[i, 0] + amplitude * (u0 - 0.5)
        f[i, 1] += -friction * v[i, 1] + amplitude * (u1 - 0.5)
        f[i, 2] += -friction * v[i, 2] + amplitude * (u2 - 0.5)


class FixLangevin(Fix):
    name = "langevin"
    usage = "fix ID GROUP langevin T_START T_STOP DAMP SEED"

    class Args(StyleArgs):
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        damp: float = param(gt=0, unit="time")
        seed: int = param(ge=1, lt=2 ** 63, unit="dimensionless")

    def target(self, sim):
        """The temperature the thermostat holds at this step (the ramp)."""
        return sim.ramp(self.args.t_start, self.args.t_stop)

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        kt = sim.units.boltz * self.target(sim) / sim.units.mvv2e
        # forces in force units: m v / damp and the noise are divided by ftm2v (1 in lj and si), as LAMMPS
        ftm2v = sim.units.ftm2v
        noise_scale = math.sqrt(24.0 * kt / (sim.dt * self.args.damp)) / ftm2v
        langevin_forces(p.v, p.f, p.tag, observables.masses(sim), p.mask, sim.groups.bit(self.group),
                        p.nlocal, self.args.damp * ftm2v, noise_scale, sim.random_key(self.args.seed), sim.step)

    def scalar(self, sim):
        """f_ID: the target temperature now."""
        return self.target(sim)
