r"""Fix ``balance``: LAMMPS's periodic load balancing, read and kept to its word: pdps's ranks hold a
regular grid of equal bricks that stays as the run starts (``processors``), so balancing would
change which rank computes a particle, never a number a run prints. On one rank there is nothing to
balance, as in LAMMPS; on more, pdps says once that it keeps its grid.

Syntax (LAMMPS's)::

    fix ID GROUP balance NFREQ THRESH shift DIMSTR NITER STOPTHRESH [keyword value ...]
    fix ID GROUP balance NFREQ THRESH rcb [keyword value ...]

NFREQ the steps between balancings (0: only at the start of a run), THRESH the imbalance factor
(>= 1) beyond which LAMMPS balances; the keywords (``weight``, ``out``) are LAMMPS's. ``out FILE``,
which writes LAMMPS's sub-domain boxes, is refused: pdps has none to write.

Outputs, LAMMPS's: ``f_ID`` the imbalance factor (the most particles a rank holds over the mean per
rank), ``f_ID[1]`` the most particles a rank holds, ``f_ID[2]`` the iterations of the last
balancing (0: pdps never moves its bricks), ``f_ID[3]`` the imbalance factor before it. pdps reports
its own grid's numbers, so before and after are equal. On one rank they are LAMMPS's: N, 0, 1 and 1.

Example::

    comm_style tiled
    fix 10 all balance 50 0.9 rcb
"""

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, param


class FixBalance(Fix):
    name = "balance"
    usage = "fix ID GROUP balance NFREQ THRESH shift DIMSTR NITER STOPTHRESH | rcb [weight ...]"
    # LAMMPS's fix balance flags a changing box (its sub-domains'), which gives thermo one its Volume
    changes_box = True

    class Args(StyleArgs):
        every: int = param(ge=0, unit="timesteps")
        threshold: float = param(unit="dimensionless")
        style: list[str] = param(min_length=1, names="shift DIMSTR NITER STOPTHRESH | rcb [keyword value ...]")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        words = self.args.style
        if words[0] not in ("shift", "rcb"):
            raise ScriptError(f"balance style must be shift or rcb (got {words[0]})")
        if words[0] == "shift" and len(words) < 4:
            raise ScriptError("balance shift needs DIMSTR NITER STOPTHRESH")
        if "out" in words:
            raise ScriptError("out: pdps keeps a regular processor grid, so it has no balanced sub-domains to write")
        if sim.comm.nprocs > 1:
            sim.warn(f"fix {id} balance: pdps keeps its regular processor grid; balancing would move work "
                     "between ranks, not change a number")

    def _imbalance(self, sim):
        most = sim.comm.max(sim.nlocal)
        total = sim.comm.sum(sim.nlocal)
        return most * sim.comm.nprocs / total if total else 1.0

    def scalar(self, sim):
        """The imbalance factor: the most particles on a rank over the mean per rank."""
        return float(self._imbalance(sim))

    def vector(self, sim):
        """The most particles on a rank, the last balancing's iterations (0), the imbalance before it."""
        return np.array([float(sim.comm.max(sim.nlocal)), 0.0, self._imbalance(sim)])
