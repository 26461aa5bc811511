r"""Pair style ``dpd/fdt``: DPD whose dissipative and random parts are left to ``fix shardlow``
(LAMMPS's pair dpd/fdt; Lisal, Brennan & Bonet Avalos, J. Chem. Phys. 135, 204105 (2011); Larentzos
et al., Comput. Phys. Commun. 185, 1987 (2014)).

With a ``fix shardlow`` defined, this style computes only the conservative DPD force; the
fluctuation-dissipation pair (the "fdt" of the name) is integrated by the Shardlow splitting in the
fix. With :math:`\mathbf{r}_{ij} = \mathbf{r}_i - \mathbf{r}_j`, :math:`\hat{\mathbf{r}}_{ij} =
\mathbf{r}_{ij}/r_{ij}` and :math:`w = 1 - r_{ij}/r_c`, for :math:`r_{ij} < r_c`:

.. math::

    \mathbf{F}_{ij} = a\,w\,\hat{\mathbf{r}}_{ij}, \qquad E = \tfrac12\,a\,r_c\,w^2

Without ``fix shardlow`` it computes the full DPD force of ``pair_style dpd`` (conservative,
dissipative :math:`-\gamma w^2 (\hat{\mathbf{r}}_{ij}\cdot\mathbf{v}_{ij})\hat{\mathbf{r}}_{ij}` and
random :math:`\sigma w \xi_{ij} \Delta t^{-1/2} \hat{\mathbf{r}}_{ij}`, :math:`\sigma^2 = 2 k_B T
\gamma`), as LAMMPS does; then ghosts carry velocities, otherwise they need not.
Pairs closer than 1e-10 are skipped, as in LAMMPS.

Parameters (units of the run), the same words as ``pair_style dpd``:

- ``pair_style dpd/fdt T rc seed``: ``T`` temperature of the fluctuation-dissipation theorem
  (>= 0, temperature units), ``rc`` global cutoff (> 0, distance), ``seed`` integer >= 1 (fix
  shardlow derives its noise key from it).
- ``pair_coeff I J a gamma [rc]`` (PDPS dialect): ``a`` repulsion (force), ``gamma`` friction
  (>= 0, force/velocity), ``rc`` cutoff of this pair (distance; default the global one), the same
  words as ``pair_style dpd``.
- ``pair_coeff I J A sigma [rc]`` (LAMMPS dialect, as LAMMPS's dpd/fdt): ``sigma`` the noise
  amplitude (>= 0, force time^1/2), from which gamma = sigma^2 / (2 k_B T); ``sigma`` > 0 needs
  ``T`` > 0; such coefficients do not mix (LAMMPS's dpd/fdt has no mixing rule). A LAMMPS script's
  ``pair_coeff * * 25.0 3.0`` (k_B T 1) is the PDPS dialect's ``pair_coeff * * 25.0 4.5``.

Example (the Groot-Warren fluid integrated with the Shardlow splitting)::

    pair_style dpd/fdt 1.0 1.0 3442527
    pair_coeff * * 25.0 4.5
    fix 1 all shardlow
    fix 2 all nve
"""

from pdps_core.api import ScriptError, StyleArgs, param, parse_args

from .dpd import PairDPD


def shardlow_defined(sim):
    """True when a fix shardlow takes over the dissipative and random forces (LAMMPS: a fix whose
    style starts with ``shardlow``)."""
    return any(fix.name.startswith("shardlow") for fix in sim.fixes.values())


class PairDPDfdt(PairDPD):
    name = "dpd/fdt"
    usage = "pair_style dpd/fdt T rc seed"

    @property
    def ghost_velocity(self):
        # read by the core before init(): the conservative force alone needs no ghost velocity
        return not shardlow_defined(self.sim)

    def init(self, ntypes, pairs=None):
        self.split = shardlow_defined(self.sim)
        return super().init(ntypes, pairs)

    class SigmaCoeff(StyleArgs):
        """LAMMPS's pair_coeff of dpd/fdt (LAMMPS's PairDPDfdt keeps sigma; its fix shardlow derives
        gamma from it)."""
        a: float = param(unit="force")
        sigma: float = param(ge=0, unit="force*time/distance")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def parse_coeff(self, words):
        if self.sim.dialect.name != "pdps":     # LAMMPS's meaning (LIGGGHTS keeps LAMMPS's styles)
            return parse_args(self.SigmaCoeff, words, "A sigma [cutoff]")
        return super().parse_coeff(words)

    def mix_coeff(self, ci, cj, rule):
        if isinstance(ci, self.SigmaCoeff) or isinstance(cj, self.SigmaCoeff):
            raise ScriptError("pair dpd/fdt with LAMMPS's sigma coefficients does not mix (LAMMPS's does not "
                              "either): give pair_coeff for every type pair")
        return super().mix_coeff(ci, cj, rule)

    def friction(self, i, j, coeff, kT):
        """gamma: pair_coeff's second coefficient (PDPS dialect), or sigma^2 / (2 k_B T) from LAMMPS's
        sigma."""
        if not isinstance(coeff, self.SigmaCoeff):
            return coeff.gamma
        if coeff.sigma == 0.0:
            return 0.0
        if kT <= 0.0:
            raise ScriptError(f"pair_coeff {i} {j}: sigma {coeff.sigma:g} needs pair_style dpd/fdt's temperature "
                              "> 0 (LAMMPS's dpd/fdt takes sigma, and gamma = sigma^2 / (2 k_B T))")
        return coeff.sigma * coeff.sigma / (2.0 * kT)
