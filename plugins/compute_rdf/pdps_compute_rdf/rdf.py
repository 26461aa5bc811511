r"""Compute ``rdf``: the radial distribution function g(r) and the coordination number of type pairs.

Distances from 0 to the cutoff :math:`r_c` are cut into ``NBIN`` bins of width
:math:`\Delta r = r_c/\mathrm{NBIN}`; bin k spans :math:`[r_k, r_{k+1})` with :math:`r_k = k\Delta r` and
is reported at its centre :math:`(k + \tfrac12)\Delta r`. For each pair of type sets (I, J):

.. math::

    g_{IJ}(r_k) = \frac{H_k}{\left(N_I N_J - D\right)\, \Delta V_k / V}, \qquad
    n_{IJ}(r_{k+1}) = \frac{1}{N_I}\sum_{l \le k} H_l

- :math:`H_k`: ordered pairs (i, j) at a distance in bin k, i of a type in I, j of a type in J, both in
  the group, j != i. j runs over every periodic image within the cutoff, so a cutoff longer than half
  the box (even longer than the box) is fine: each image is a neighbor, a particle's own images
  included, exactly as LAMMPS counts its ghost particles.
- :math:`N_I`, :math:`N_J`: particles of the group with a type in I, in J; :math:`D`: those in both
  (:math:`D = N` when I = J), so :math:`N_I N_J - D` is the number of ordered pairs of distinct
  particles and g tends to 1 in an ideal gas at any N.
- :math:`\Delta V_k = \tfrac43\pi(r_{k+1}^3 - r_k^3)` and V the box volume; in 2-d
  :math:`\Delta V_k = \pi(r_{k+1}^2 - r_k^2)` and V the box area.
- :math:`n_{IJ}` (coordination number): the mean number of J particles within :math:`r_{k+1}` of an I
  particle.

This is LAMMPS's compute rdf normalisation. freud (``freud.density.RDF``) divides by
:math:`N_I N_J` instead (its ``normalization_mode='exact'``): :math:`g_\mathrm{LAMMPS} =
g_\mathrm{freud}\, N_I N_J / (N_I N_J - D)`, which for I = J is freud's ``'finite_size'`` mode; freud's
``n_r`` is :math:`n_{IJ}` as defined here. The PDPS source divides by :math:`N_I N_J` as freud does,
and so does LIGGGHTS 3.8.0 (the LAMMPS it was forked from; its source, and its numbers recorded in
plugins/compute_rdf/tests/data/liggghts.cases.json): in the LIGGGHTS dialect g is divided by
:math:`N_I N_J` (``Dialect.rdf_distinct_pairs``).

Parameters:

- ``NBIN``: number of bins (integer > 0).
- ``I J`` (any number of pairs): centre and neighbor types, each a type or a LAMMPS range (``*``,
  ``2*``, ``*3``, ``1*2``); none given: all types with all types.
- ``cutoff R`` (distance, > 0): the largest distance. Default: the largest pair cutoff of the pair
  style (without the skin), known once a run (``run 0`` is enough) has set the pair style up, as in
  LAMMPS. With the keyword no pair style is needed, and R may exceed the pair cutoff: particles are
  binned by this compute itself, independent of the neighbor list.

Output: an array read as ``c_ID[k][c]`` (0-based): NBIN rows; column 0 is r (the bin centre), then
for each pair m, column 1 + 2m is g and column 2 + 2m the coordination number. Averaged over time
with ``analyze ave/time`` (``c_ID`` names the whole array). The compute is evaluated when read, on
the current configuration.

PDPS form. The PDPS manual writes ``compute ID GROUP rdf NEVERY ITYPE JTYPE``, but the PDPS source
reads that first number as the number of bins: ``compute 1 all rdf 100 1 1`` is 100 bins of type 1
around type 1 in PDPS and in LAMMPS alike, and so in pdps. PDPS takes the largest pair cutoff of the
named type pairs; pdps takes LAMMPS's (the pair style's largest).

Syntax::

    compute ID GROUP rdf NBIN [I J]... [cutoff R]

Examples::

    compute 1 all rdf 100 1 1
    compute 2 all rdf 50 1 1 1 2 2 2 cutoff 3.0
    analyze 3 all ave/time 1 100 100 c_1 file Al-Al.rdf

In a parallel run every rank gathers all particles and computes the whole histogram (correct,
not faster: the neighbors of a rank's particles may be owned by others).
"""

import math

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Compute, ScriptError, StyleArgs, check_bins, check_images, keyword, param


@njit(cache=True)
def pair_histogram(x, type_, chosen, member, lo, length, periodic, dimension, cutoff, nbin, cell_size):
    """hist[m, k]: ordered pairs (i, j or a periodic image of j) of histogram m at a distance in
    bin k. Cells are at least ``cell_size`` wide (one cell spanning the box when that exceeds it);
    each cell offset within reach is one (cell, image) combination, so every image is seen once.
    Particles are visited in cell order, and a pair of distinct particles from its lower index
    only, counted in both orientations."""
    n = x.shape[0]
    nhisto = member.shape[0]
    hist = np.zeros((nhisto, nbin), dtype=np.int64)
    ncell = np.ones(3, dtype=np.int64)
    reach = np.zeros(3, dtype=np.int64)
    width = length.copy()
    for d in range(dimension):
        ncell[d] = max(1, int(length[d] / cell_size))
        width[d] = length[d] / ncell[d]
        reach[d] = int(math.ceil(cutoff / width[d]))
    # owned particles may have drifted out of the box since the last re-wrap
    xw = x.copy()
    for i in range(n):
        for d in range(dimension):
            if periodic[d]:
                xw[i, d] = lo[d] + (xw[i, d] - lo[d]) % length[d]
    ncells = ncell[0] * ncell[1] * ncell[2]
    home = np.empty((n, 3), dtype=np.int64)
    cell = np.empty(n, dtype=np.int64)
    start = np.zeros(ncells + 1, dtype=np.int64)
    for i in range(n):
        for d in range(3):
            home[i, d] = min(max(int((xw[i, d] - lo[d]) / width[d]), 0), ncell[d] - 1)
        cell[i] = (home[i, 0] * ncell[1] + home[i, 1]) * ncell[2] + home[i, 2]
        start[cell[i] + 1] += 1
    for c in range(ncells):
        start[c + 1] += start[c]
    fill = start[:-1].copy()
    order = np.empty(n, dtype=np.int64)
    for i in range(n):
        order[fill[cell[i]]] = i
        fill[cell[i]] += 1
    # cell-ordered copies: neighbors sit next to each other in memory
    xs = xw[order]
    ts = type_[order]
    cs = chosen[order]
    hs = home[order]

    cutsq = cutoff * cutoff
    bins_per_length = nbin / cutoff
    for a in range(n):
        ti = ts[a]
        if not cs[a]:
            continue
        for kx in range(-reach[0], reach[0] + 1):
            cx = hs[a, 0] + kx
            if not periodic[0] and (cx < 0 or cx >= ncell[0]):
                continue
            wrap_x = cx // ncell[0]
            for ky in range(-reach[1], reach[1] + 1):
                cy = hs[a, 1] + ky
                if not periodic[1] and (cy < 0 or cy >= ncell[1]):
                    continue
                wrap_y = cy // ncell[1]
                for kz in range(-reach[2], reach[2] + 1):
                    cz = hs[a, 2] + kz
                    if not periodic[2] and (cz < 0 or cz >= ncell[2]):
                        continue
                    wrap_z = cz // ncell[2]
                    same_image = wrap_x == 0 and wrap_y == 0 and wrap_z == 0
                    c = (((cx - wrap_x * ncell[0]) * ncell[1] + cy - wrap_y * ncell[1]) * ncell[2]
                         + cz - wrap_z * ncell[2])
                    sx = wrap_x * length[0]
                    sy = wrap_y * length[1]
                    sz = wrap_z * length[2]
                    for b in range(max(start[c], a), start[c + 1]):
                        if not cs[b] or (b == a and same_image):
                            continue
                        dx = xs[a, 0] - xs[b, 0] - sx
                        dy = xs[a, 1] - xs[b, 1] - sy
                        dz = xs[a, 2] - xs[b, 2] - sz
                        rsq = dx * dx + dy * dy + dz * dz
                        if rsq >= cutsq:
                            continue
                        k = int(math.sqrt(rsq) * bins_per_length)
                        if k >= nbin:
                            continue
                        tj = ts[b]
                        for m in range(nhisto):
                            if member[m, ti, tj]:
                                hist[m, k] += 1
                            # a particle's own image once per shift: the shift -s comes round too
                            if b != a and member[m, tj, ti]:
                                hist[m, k] += 1
    return hist


def type_bounds(word, ntypes):
    """LAMMPS's type ranges: ``N``, ``*``, ``N*``, ``*M``, ``N*M`` -> (lo, hi)."""
    try:
        if "*" in word:
            left, right = word.split("*", 1)
            lo = int(left) if left else 1
            hi = int(right) if right else ntypes
        else:
            lo = hi = int(word)
    except ValueError:
        raise ScriptError(f"type must be an integer or a range like 1*2 (got {word})") from None
    if lo < 1 or hi > ntypes or lo > hi:
        raise ScriptError(f"type {word} is out of range: the box has types 1 to {ntypes}")
    return lo, hi


class ComputeRDF(Compute):
    name = "rdf"
    usage = "compute ID GROUP rdf NBIN [I J]... [cutoff R]"

    class Args(StyleArgs):
        nbin: int = param(gt=0, unit="dimensionless")
        pairs: list[str] = param(default_factory=list, names="type range (I J pairs)")
        cutoff: float | None = keyword(None, gt=0, unit="distance")

        @model_validator(mode="before")
        @classmethod
        def _cutoff_after_pairs(cls, data):
            # a positional list takes every word left, the keyword included: split it off
            words = list(data.get("pairs", []))
            if "cutoff" not in words:
                return data
            k = words.index("cutoff")
            if len(words) != k + 2:
                raise ValueError("keyword cutoff takes one value and comes last"
                                 f" (got {' '.join(words[k:])})")
            return {**data, "pairs": words[:k], "cutoff": words[k + 1]}

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        words = args.pairs or ["*", "*"]
        if len(words) % 2:
            raise ScriptError(f"type pairs come as I J (got {len(words)} words: {' '.join(words)})")
        check_bins(args.nbin, f"compute {id} (rdf): NBIN")
        ntypes = sim.ntypes
        self.bounds = [(type_bounds(words[k], ntypes), type_bounds(words[k + 1], ntypes))
                       for k in range(0, len(words), 2)]
        self.member = np.zeros((len(self.bounds), ntypes + 1, ntypes + 1), dtype=np.bool_)
        for m, ((ilo, ihi), (jlo, jhi)) in enumerate(self.bounds):
            self.member[m, ilo:ihi + 1, jlo:jhi + 1] = True
        self._key = None
        self._array = None

    def cutoff(self, sim):
        if self.args.cutoff is not None:
            return self.args.cutoff
        if sim.pair is None:
            raise ScriptError(f"compute {self.id} (rdf) needs a pair style for its default cutoff, "
                              "or the keyword cutoff R")
        if sim.pair_list is None:
            raise ScriptError(f"compute {self.id} (rdf): the pair cutoff is known once a run has set "
                              "the pair style up (run 0), or give the keyword cutoff R")
        return float(sim.pair_list.cutoff.max())

    def array(self, sim):
        p, box = sim.particles, sim.box
        x, types = np.ascontiguousarray(p.x[:p.nlocal]), p.type[:p.nlocal]
        chosen = sim.groups.select(sim, self.group)
        if sim.comm.nprocs > 1:
            # every rank bins every particle: the neighbors of its own may be owned elsewhere
            x, types, chosen = (sim.comm.allgather_rows(a) for a in (x, types, chosen))
        n = len(x)
        cutoff = self.cutoff(sim)
        check_images(box, cutoff, f"compute {self.id} (rdf): cutoff", every_axis=True)
        # thermo may read several elements in one step: recompute only when something changed
        key = (sim.step, cutoff, x.tobytes(), types.tobytes(), chosen.tobytes(),
               box.lo.tobytes(), box.hi.tobytes())
        if key == self._key:
            return self._array
        nbin = self.args.nbin
        # cells of half the cutoff, or of ~4 particles when that is wider: fewer cells to visit
        d = sim.dimension
        cell_size = max(0.5 * cutoff, (4.0 * box.volume / max(n, 1)) ** (1.0 / d))
        hist = pair_histogram(x, types, chosen, self.member, box.lo, box.length,
                              np.array(box.periodic), d, cutoff, nbin, cell_size)
        self._array = self.normalise(sim, hist, types[chosen], cutoff)
        self._key = key
        return self._array

    def normalise(self, sim, hist, chosen_types, cutoff):
        """g(r) and the coordination number from pair counts (LAMMPS's normalisation, docstring)."""
        typecount = np.bincount(chosen_types, minlength=sim.ntypes + 1)
        nbin = self.args.nbin
        width = cutoff / nbin
        edges = width * np.arange(nbin + 1)
        if sim.dimension == 3:
            shell = 4.0 * math.pi / 3.0 * (edges[1:] ** 3 - edges[:-1] ** 3)
        else:
            shell = math.pi * (edges[1:] ** 2 - edges[:-1] ** 2)
        fraction = shell / sim.box.volume
        out = np.zeros((nbin, 1 + 2 * len(self.bounds)))
        out[:, 0] = (np.arange(nbin) + 0.5) * width
        for m, ((ilo, ihi), (jlo, jhi)) in enumerate(self.bounds):
            icount = int(typecount[ilo:ihi + 1].sum())
            jcount = int(typecount[jlo:jhi + 1].sum())
            duplicates = int(typecount[max(ilo, jlo):min(ihi, jhi) + 1].sum())
            pairs = icount * jcount - (duplicates if sim.dialect.rdf_distinct_pairs else 0)
            if pairs > 0:
                out[:, 1 + 2 * m] = hist[m] / (fraction * pairs)
            if icount > 0:
                out[:, 2 + 2 * m] = np.cumsum(hist[m]) / icount
        return out
