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
- ``scale TYPE RATIO`` (repeatable): particles of TYPE are damped over DAMP / RATIO (LAMMPS's scale).
- ``zero yes``: the random forces of the group are shifted to sum to zero every step, so the
  thermostat adds no net momentum (LAMMPS's zero).
- ``angmom``, ``omega``, ``tally`` and ``gjf`` are LAMMPS keywords pdps refuses in one line.

Syntax::

    fix ID GROUP langevin T_START T_STOP DAMP SEED [scale TYPE RATIO]... [zero yes|no]

Example::

    fix heat all langevin 1.0 1.5 0.1 48279
    fix 2 all nve
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, observables, param, particle_uniforms

STREAM = 1      # the generator stream of this fix's draws


@njit(cache=True)
def langevin_forces(v, f, tag, type_, mass, mask, groupbit, nlocal, damp, noise_scale, ratio, seed, step,
                    noise_sum):
    """Friction -m v/damp and noise sqrt(24 kT m/(dt damp)) (u - 1/2) with damp divided by
    ``ratio[type]``; ``noise_scale`` is sqrt(24 kT / (dt damp)) in the run's units. The noise added
    is summed into ``noise_sum`` (3,), for ``zero yes``."""
    noise_sum[:] = 0.0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        m = mass[i]
        scale = ratio[type_[i]]
        u0, u1, u2, _ = particle_uniforms(seed, step, tag[i], STREAM)
        amplitude = noise_scale * math.sqrt(m * scale)
        friction = m * scale / damp
        n0, n1, n2 = amplitude * (u0 - 0.5), amplitude * (u1 - 0.5), amplitude * (u2 - 0.5)
        f[i, 0] += -friction * v[i, 0] + n0
        f[i, 1] += -friction * v[i, 1] + n1
        f[i, 2] += -friction * v[i, 2] + n2
        noise_sum[0] += n0
        noise_sum[1] += n1
        noise_sum[2] += n2


class FixLangevin(Fix):
    name = "langevin"
    usage = "fix ID GROUP langevin T_START T_STOP DAMP SEED"

    class Args(StyleArgs):
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        damp: float = param(gt=0, unit="time")
        seed: int = param(ge=1, lt=2 ** 63, unit="dimensionless")
        scale: list[tuple[int, float]] = keyword(default_factory=list, unit="dimensionless")
        zero: bool = keyword(False)
        angmom: str | None = keyword(None)
        omega: str | None = keyword(None)
        tally: str | None = keyword(None)
        gjf: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        for name in ("angmom", "omega", "tally", "gjf"):
            if getattr(args, name) is not None:
                raise ScriptError(f"fix langevin keyword {name} is not supported (supported: scale, zero)")
        self.ratio = np.ones(sim.ntypes + 1)
        for ptype, ratio in args.scale:
            if not 1 <= ptype <= sim.ntypes:
                raise ScriptError(f"scale: type {ptype} is out of range 1..{sim.ntypes}")
            if not ratio > 0:
                raise ScriptError(f"scale: ratio must be > 0 (got {ratio:g})")
            self.ratio[ptype] = ratio
        self.noise_sum = np.zeros(3)
        self.last_target = None

    def target(self, sim):
        """The temperature the thermostat holds at this step (the ramp)."""
        return sim.ramp(self.args.t_start, self.args.t_stop)

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        self.last_target = self.target(sim)
        kt = sim.units.boltz * self.last_target / sim.units.mvv2e
        # forces in force units: m v / damp and the noise are divided by ftm2v (1 in lj and si), as LAMMPS
        ftm2v = sim.units.ftm2v
        noise_scale = math.sqrt(24.0 * kt / (sim.dt * self.args.damp)) / ftm2v
        langevin_forces(p.v, p.f, p.tag, p.type, observables.masses(sim), p.mask, sim.groups.bit(self.group),
                        p.nlocal, self.args.damp * ftm2v, noise_scale, self.ratio, sim.random_key(self.args.seed),
                        sim.step, self.noise_sum)
        if self.args.zero:
            # LAMMPS's zero yes: the mean random force of the group taken off each of its particles
            count = observables.count(sim, self.group)
            if count:
                mean = np.asarray(sim.comm.sum(self.noise_sum), dtype=np.float64) / count
                chosen = sim.groups.select(sim, self.group)
                p.f[:p.nlocal][chosen] -= mean

    def scalar(self, sim):
        """f_ID: the target temperature of the last step the thermostat acted on (between runs, the
        one the last run ended at)."""
        return self.last_target if self.last_target is not None else self.target(sim)
