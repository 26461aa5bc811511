r"""What LAMMPS's twisting models of pair granular share (Marshall, J. Comput. Phys. 228, 1541
(2009), eqs. 29, 30, 34, 44): the twist rate :math:`\Omega_t = (\boldsymbol\omega_i -
\boldsymbol\omega_j)\cdot\mathbf{n}`, the twist angle :math:`\phi` (1 value of history) growing by
:math:`\Omega_t\Delta t`, and the torque

.. math::

    M_t = -k_{twist}\phi - \gamma_{twist}\Omega_t, \quad |M_t| \le M_{crit} = \mu_{twist}F_{n,crit}
    \ \Rightarrow\ M_t = -M_{crit}\,\mathrm{sgn}\,\Omega_t,\ \phi = (M_{crit}\,\mathrm{sgn}\,\Omega_t
    - \gamma_{twist}\Omega_t)/k_{twist}

with :math:`\boldsymbol\tau_i = M_t\mathbf{n} = -\boldsymbol\tau_j`. The angle is the same seen from
either sphere, so the other sphere keeps it unchanged (LAMMPS 22 Jul 2025 negates it, as it does the
tangential spring)."""

from numba import njit

from pdps_granular_contact.contact_state import DT, FN_LIMIT, MTX, MTY, MTZ, NX, NY, NZ, UPDATE, WRX, WRY, WRZ


@njit(cache=True)
def twist_torque(c, hist, h, stiffness, damping, friction):
    """The twisting torque of these coefficients into MT (the loop gives i -MT, j +MT)."""
    rate = c[WRX] * c[NX] + c[WRY] * c[NY] + c[WRZ] * c[NZ]
    if c[UPDATE] != 0.0:
        hist[h] += rate * c[DT]
    torque = -stiffness * hist[h] - damping * rate
    sign = (1.0 if rate > 0.0 else 0.0) - (1.0 if rate < 0.0 else 0.0)
    critical = friction * c[FN_LIMIT]
    if abs(torque) > critical:
        hist[h] = (critical * sign - damping * rate) / stiffness if stiffness != 0.0 else 0.0
        torque = -critical * sign
    c[MTX] = -torque * c[NX]
    c[MTY] = -torque * c[NY]
    c[MTZ] = -torque * c[NZ]
