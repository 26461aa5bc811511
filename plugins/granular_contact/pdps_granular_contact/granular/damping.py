r"""What LAMMPS's damping models of pair granular share: each gives a prefactor :math:`\eta_n` (this
overlap's damping, ``GAMMA_N``, which the tangential models scale by their :math:`x_{\gamma,t}`) and
adds :math:`-\eta_n v_n` to the normal model's force,

.. math::

    F_n = F_{ne} - \eta_n v_n, \qquad F_n \leftarrow \max(F_n, 0) \text{ with limit\_damping}

and, for a normal model without adhesion, the Coulomb limit's :math:`F_{n,crit} = |F_n|`
(the adhesive ones set their own). Their compute functions get ``k`` = (their coefficient,
limit_damping 1/0, cohesive normal model 1/0, ...)."""

from numba import njit

from pdps_granular_contact.contact_state import FN, FN_LIMIT, GAMMA_N, VN

from .base import GranularSubModel


@njit(cache=True)
def add_damping(c, k, prefactor):
    c[GAMMA_N] = prefactor
    fn = c[FN] - prefactor * c[VN]
    if k[1] != 0.0 and fn < 0.0:
        fn = 0.0
    c[FN] = fn
    if k[2] == 0.0:
        c[FN_LIMIT] = abs(fn)


class DampingModel(GranularSubModel):
    """A damping model: no coefficients of its own; its compute function's k starts with
    ``coefficient(law)`` (from the normal model's eta_n0), then limit_damping and cohesive."""

    def coefficient(self, law):
        return law.args("normal").eta_n0

    def values(self, law, contact):
        return (self.coefficient(law), 1.0 if law.limit_damping else 0.0,
                1.0 if law.parts["normal"][0].cohesive else 0.0)
