r"""Fix ``mvv/dpd``: Groot & Warren's modified velocity Verlet for DPD (R. D. Groot & P. B. Warren,
J. Chem. Phys. 107, 4423 (1997), eq. 22; LAMMPS's fix mvv/dpd).

DPD forces depend on velocities, so the force at :math:`t+\Delta t` is evaluated with a predicted
velocity :math:`\tilde{\mathbf{v}}`:

.. math::

    \mathbf{x}(t+\Delta t) = \mathbf{x}(t) + \Delta t\,\mathbf{v}(t)
                             + \tfrac12 \Delta t^2\,\mathbf{F}(t)/m,

    \tilde{\mathbf{v}}(t+\Delta t) = \mathbf{v}(t) + \lambda\,\Delta t\,\mathbf{F}(t)/m,

    \mathbf{F}(t+\Delta t) = \mathbf{F}\big(\mathbf{x}(t+\Delta t),
                                             \tilde{\mathbf{v}}(t+\Delta t)\big),

    \mathbf{v}(t+\Delta t) = \mathbf{v}(t) + \tfrac12 \Delta t\,
                             \big(\mathbf{F}(t) + \mathbf{F}(t+\Delta t)\big)/m

As LAMMPS, ``initial_integrate`` saves the half-step velocity
:math:`\mathbf{v}(t) + \tfrac12\Delta t\,\mathbf{F}(t)/m` in the per-atom array ``vest`` (it moves
with its particle when particles are re-sorted), moves the particle with it, and leaves
:math:`\tilde{\mathbf{v}}` in ``v`` for the pair style; ``final_integrate`` sets
:math:`\mathbf{v} = \texttt{vest} + \tfrac12\Delta t\,\mathbf{F}(t+\Delta t)/m`. With
:math:`\lambda = 1/2` the prediction is the half-step velocity and the scheme is exactly velocity
Verlet (fix nve), to the last bit. Groot & Warren recommend :math:`\lambda = 0.65` for their fluid
(rho = 3, a = 25, gamma = 4.5): it keeps the temperature closer to k_B T at large time steps than
lambda = 1/2 (dt = 0.04: <T>/T = 1.00-1.01 against 1.025-1.033); the best value depends on the
system. Masses are ``rmass`` when present, else the per-type mass. Each kick F dt / m is turned into
a velocity by the unit system's ``ftm2v`` (1 in lj; LAMMPS's force->ftm2v in real and metal).

Parameters:

- ``lambda``: the prediction weight (dimensionless, 0 <= lambda <= 1; default 0.5).

Syntax::

    fix ID GROUP mvv/dpd [lambda]

Example::

    pair_style dpd 1.0 1.0 3442527
    pair_coeff * * 25.0 4.5
    fix 1 all mvv/dpd 0.65
"""

from numba import njit

from pdps_core.api import Fix, StyleArgs, observables, param


@njit(cache=True)
def mvv_initial(x, v, f, vest, mass, mask, groupbit, nlocal, dt, lam, ftm2v):
    half = 0.5 * dt * ftm2v
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / mass[i]
            predict = 2.0 * lam * dtfm
            for d in range(3):
                vest[i, d] = v[i, d] + dtfm * f[i, d]
                x[i, d] += dt * vest[i, d]
                v[i, d] += predict * f[i, d]


@njit(cache=True)
def mvv_final(v, f, vest, mass, mask, groupbit, nlocal, dt, ftm2v):
    half = 0.5 * dt * ftm2v
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / mass[i]
            for d in range(3):
                v[i, d] = vest[i, d] + dtfm * f[i, d]


class FixMvvDPD(Fix):
    name = "mvv/dpd"
    time_integrate = True
    usage = "fix ID GROUP mvv/dpd [lambda]"

    per_atom = (("vest", 3),)        # the half-step velocity, kept between the two halves

    class Args(StyleArgs):
        prediction: float = param(0.5, ge=0.0, le=1.0, alias="lambda", unit="dimensionless")

    def initial_integrate(self, sim):
        p = sim.particles
        mvv_initial(p.x, p.v, p.f, p.arrays["vest"], observables.masses(sim), p.mask,
                    sim.groups.bit(self.group), p.nlocal, sim.dt, self.args.prediction, sim.units.ftm2v)

    def final_integrate(self, sim):
        p = sim.particles
        mvv_final(p.v, p.f, p.arrays["vest"], observables.masses(sim), p.mask,
                  sim.groups.bit(self.group), p.nlocal, sim.dt, sim.units.ftm2v)
