r"""Compute ``cna/atom``: common neighbor analysis, the local crystal structure of each particle
(LAMMPS's and LIGGGHTS's compute cna/atom; Honeycutt and Andersen, J. Phys. Chem. 91, 4950 (1987);
Faken and Jonsson, Comput. Mater. Sci. 2, 279 (1994)).

The near neighbors of a particle i are the particles within the cutoff :math:`r_c` (every periodic
image counts), at most 16 of them (LAMMPS's MAXNEAR). Only a particle with 12 (fcc, hcp,
icosahedral) or 14 (bcc: 8 first and 6 second neighbors) near neighbors is analysed: for each near
neighbor j, the signature

- :math:`n_{cn}`: the common neighbors, near neighbors of both i and j (at most 8, MAXCOMMON),
- :math:`n_b`: the bonds among them (pairs of common neighbors closer than :math:`r_c`),
- the largest and the smallest number of bonds any one common neighbor has (the longest chain of
  bonds, as LAMMPS reads it: (4,2,1,1) is two separate bonds, (4,2,2,0) a chain of two),

and the particle is, by its signatures:

==========  =====  ===============================================================
FCC         1      12 neighbors, all (4,2,1,1)
HCP         2      12 neighbors, 6 (4,2,1,1) and 6 (4,2,2,0)
BCC         3      14 neighbors, 6 (4,4,2,2) and 8 (6,6,2,2)
ICOS        4      12 neighbors, all (5,5,2,2)
OTHER       5      any other, and every particle with a near-neighbor count other than 12 or 14
UNKNOWN     0      particles outside the compute's group
==========  =====  ===============================================================

As in LIGGGHTS 3.8.0 (its compute_cna_atom.cpp, from LAMMPS): neighbors of neighbors are needed, so
the near neighbors of every owned particle are found, in the group or not. For an owned j they are
j's own near neighbors (its first 16); for a ghost j, those of i's neighbors (j itself left out)
within :math:`r_c` of j, the first 16 found; common neighbors are taken in the order of i's near
neighbors. A particle with more than 16 near neighbors gets OTHER and is counted in the warning "Too
many neighbors in CNA for N atoms"; more than 8 common neighbors of a pair keeps the first 8 and
gives "Too many common neighbors in CNA N times". Which 16 (or 8) are kept follows the neighbor
list's order, which is pdps's own: only such crowded particles can differ from LIGGGHTS's.

The neighbors come from an occasional full list the core builds when the compute is read, with
ghosts out to :math:`r_c`, so the values are exact on any number of ranks. LIGGGHTS refuses a
script without a pair style or with :math:`r_c` beyond the pair cutoff; pdps runs both (as its
coord/atom and cluster/atom do) and, with a pair style, warns as LIGGGHTS does where
:math:`2 r_c` exceeds the pair cutoff plus the skin ("Compute cna/atom cutoff may be too large to
find ghost atom neighbors": LIGGGHTS's test; pdps's values do not suffer). A cutoff of 0 is taken
as LIGGGHTS takes it: no near neighbors, every particle of the group OTHER. Read several times on
one step (by several variables, say), the values are computed, and the warnings given, once, as
LIGGGHTS invokes a compute once a step (it prints "Too many neighbors" on the screen only; pdps also
logs it). LIGGGHTS's manual calls 5 "unknown"; its source, and this docstring, OTHER. LIGGGHTS
3.8.0's numbers are recorded in plugins/compute_coord/tests/data/liggghts.cases.json (cases cna_fcc,
cna_bcc, cna_hcp: crystals melting under pair soft, on 1 and 2 ranks).

The cutoff goes between the first and second shells: LAMMPS's manual gives
:math:`r_c = \frac{1}{2}(\frac{1}{\sqrt 2} + 1)\, a \approx 0.854\, a` for fcc (and hcp),
:math:`r_c = \frac{1}{2}(1 + \sqrt 2)\, a \approx 1.207\, a` for bcc, a the lattice constant.

Output: one value per particle, ``c_ID``, read by dumps, atom-style variables and compute reduce.

Syntax::

    compute ID GROUP cna/atom RC

Example::

    compute cna all cna/atom 1.434
    variable fcc atom c_cna==1
    compute nfcc all reduce sum v_fcc
"""

import numpy as np
from numba import njit

from pdps_core.api import Compute, ScriptError, StyleArgs, param

MAXNEAR = 16
MAXCOMMON = 8
UNKNOWN, FCC, HCP, BCC, ICOS, OTHER = range(6)


@njit(cache=True)
def near_neighbors(x, offsets, neighbors, nlocal, cutsq, nearest, nnearest):
    """The first MAXNEAR neighbors within the cutoff of each owned particle; returns how many
    particles had more."""
    nerror = 0
    for i in range(nlocal):
        n = 0
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            if dx * dx + dy * dy + dz * dz < cutsq:
                if n < MAXNEAR:
                    nearest[i, n] = j
                    n += 1
                else:
                    nerror += 1
                    break
        nnearest[i] = n
    return nerror


@njit(cache=True)
def cna_patterns(x, mask, groupbit, offsets, neighbors, nlocal, cutsq, nearest, nnearest, pattern):
    """The CNA class of each owned particle into ``pattern``; returns how many times a pair had more
    than MAXCOMMON common neighbors."""
    nerror = 0
    cna = np.zeros((MAXNEAR, 4), dtype=np.int64)
    onenearest = np.empty(MAXNEAR, dtype=np.int64)
    common = np.empty(MAXCOMMON, dtype=np.int64)
    bonds = np.empty(MAXCOMMON, dtype=np.int64)
    for i in range(nlocal):
        if not mask[i] & groupbit:
            pattern[i] = UNKNOWN
            continue
        nn = nnearest[i]
        if nn != 12 and nn != 14:
            pattern[i] = OTHER
            continue
        for m in range(nn):
            j = nearest[i, m]
            ncommon = 0
            first = True
            if j < nlocal:
                for a in range(nn):
                    for b in range(nnearest[j]):
                        if nearest[i, a] == nearest[j, b]:
                            if ncommon < MAXCOMMON:
                                common[ncommon] = nearest[i, a]
                                ncommon += 1
                            elif first:
                                nerror += 1
                                first = False
            else:
                n = 0
                for kk in range(offsets[i], offsets[i + 1]):
                    k = neighbors[kk]
                    if k == j:
                        continue
                    dx = x[j, 0] - x[k, 0]
                    dy = x[j, 1] - x[k, 1]
                    dz = x[j, 2] - x[k, 2]
                    if dx * dx + dy * dy + dz * dz < cutsq:
                        if n < MAXNEAR:
                            onenearest[n] = k
                            n += 1
                        else:
                            break
                for a in range(nn):
                    for b in range(n):
                        if nearest[i, a] == onenearest[b]:
                            if ncommon < MAXCOMMON:
                                common[ncommon] = nearest[i, a]
                                ncommon += 1
                            elif first:
                                nerror += 1
                                first = False
            for a in range(ncommon):
                bonds[a] = 0
            nbonds = 0
            for a in range(ncommon):
                ja = common[a]
                for b in range(a + 1, ncommon):
                    kb = common[b]
                    dx = x[ja, 0] - x[kb, 0]
                    dy = x[ja, 1] - x[kb, 1]
                    dz = x[ja, 2] - x[kb, 2]
                    if dx * dx + dy * dy + dz * dz < cutsq:
                        nbonds += 1
                        bonds[a] += 1
                        bonds[b] += 1
            maxbonds = 0
            minbonds = MAXCOMMON
            for a in range(ncommon):
                maxbonds = max(maxbonds, bonds[a])
                minbonds = min(minbonds, bonds[a])
            cna[m, 0] = ncommon
            cna[m, 1] = nbonds
            cna[m, 2] = maxbonds
            cna[m, 3] = minbonds
        pattern[i] = OTHER
        if nn == 12:
            nfcc = nhcp = nico = 0
            for m in range(12):
                cj, ck, cl, cm = cna[m, 0], cna[m, 1], cna[m, 2], cna[m, 3]
                if cj == 4 and ck == 2 and cl == 1 and cm == 1:
                    nfcc += 1
                elif cj == 4 and ck == 2 and cl == 2 and cm == 0:
                    nhcp += 1
                elif cj == 5 and ck == 5 and cl == 2 and cm == 2:
                    nico += 1
            if nfcc == 12:
                pattern[i] = FCC
            elif nfcc == 6 and nhcp == 6:
                pattern[i] = HCP
            elif nico == 12:
                pattern[i] = ICOS
        else:
            nbcc4 = nbcc6 = 0
            for m in range(14):
                cj, ck, cl, cm = cna[m, 0], cna[m, 1], cna[m, 2], cna[m, 3]
                if cj == 4 and ck == 4 and cl == 2 and cm == 2:
                    nbcc4 += 1
                elif cj == 6 and ck == 6 and cl == 2 and cm == 2:
                    nbcc6 += 1
            if nbcc4 == 6 and nbcc6 == 8:
                pattern[i] = BCC
    return nerror


class ComputeCNAAtom(Compute):
    name = "cna/atom"
    usage = "compute ID GROUP cna/atom RC"
    neighbor_lists_needed = True

    class Args(StyleArgs):
        cutoff: float = param(ge=0, unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.nlist = None
        self.ready = False
        self.cached = (None, None)      # (the list build it was made from, the values)

    def init_run(self, sim):
        rc = self.args.cutoff
        if sim.pair is not None and sim.comm.is_root:
            cutforce = float(np.sqrt(np.max(sim.pair.cutsq)))
            if 2.0 * rc > cutforce + sim.neighbor.skin:
                sim.warn("Compute cna/atom cutoff may be too large to find ghost atom neighbors")
        if sim.comm.is_root and sum(c.name == self.name for c in sim.computes.values()) > 1:
            sim.warn("More than one compute cna/atom defined")
        # every particle's near neighbors (not only the group's): CNA reads neighbors of neighbors
        self.nlist = sim.request_neighbor_list("full", rc, occasional=True) if rc > 0 else None
        self.ready = True

    def peratom(self, sim):
        if not self.ready:
            raise ScriptError(f"compute {self.id} (cna/atom) is read before any run: run 0 first")
        if self.nlist is not None:
            nlist = sim.build_neighbor_list(self.nlist)
            built = (id(nlist), nlist.version)
            if self.cached[0] == built:      # read again on one step: computed (and warned) once, as LIGGGHTS
                return self.cached[1].copy()
        p = sim.particles
        n = p.nlocal
        groupbit = np.uint32(sim.groups.bit(self.group))
        pattern = np.zeros(n, dtype=np.int64)
        nearest = np.zeros((n, MAXNEAR), dtype=np.int64)
        nnearest = np.zeros(n, dtype=np.int64)
        if self.nlist is None:          # cutoff 0: no near neighbors
            offsets, neighbors = np.zeros(n + 1, dtype=np.int64), np.zeros(0, dtype=np.int64)
        else:
            offsets, neighbors = nlist.offsets, nlist.neighbors
        cutsq = self.args.cutoff ** 2
        crowded = sim.comm.sum(near_neighbors(p.x, offsets, neighbors, n, cutsq, nearest, nnearest))
        if crowded and sim.comm.is_root:
            sim.warn(f"Too many neighbors in CNA for {crowded} atoms")
        overfull = sim.comm.sum(cna_patterns(p.x, p.mask, groupbit, offsets, neighbors, n, cutsq, nearest, nnearest,
                                             pattern))
        if overfull and sim.comm.is_root:
            sim.warn(f"Too many common neighbors in CNA {overfull} times")
        values = pattern.astype(np.float64)
        if self.nlist is not None:
            self.cached = (built, values)
        return values.copy()
