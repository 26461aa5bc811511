"""The one guard for geometry and counts: what a box, a cutoff, a skin, a bin grid, a run length, a
type count or an id may be, checked where each is set (script, data file, restart file) and where
they meet (a run's start, when the cutoffs are known). Each check raises one line naming the value.

Limits, and why:

- Box bounds finite, lo < hi, and of magnitude at most ``MAX_COORDINATE`` (1e150): squared distances
  of larger coordinates overflow. A box length must be resolvable at its position: at least
  ``MIN_RELATIVE_LENGTH`` (1e-12) of its largest bound, or positions inside it cannot be told apart.
  No absolute size limit: a box of 1e-9 is a nanometre box in SI units.
- A periodic box no shorter than 1/``MAX_IMAGES`` (1/64) of the ghost cutoff (pair cutoff + skin):
  each periodic image within the cutoff becomes ghosts, 2 x 64 images per axis at most.
- Neighbor bins: at most ``MAX_BINS_PER_AXIS`` per axis and ``MAX_CELLS`` in all; a larger box gets
  wider bins (correct, only slower) instead of a grid that does not fit in memory.
- ``run N``: 0 <= N <= 2^31 - 1, as LAMMPS; the step after it must fit in 64 bits.
- Types: 1 <= ntypes <= ``MAX_TYPES`` (200: per-type-pair tables and their set-up grow as ntypes^2).
- Ids: 1 <= id <= 2^62 (room for insertion); image flags fit in 32 bits.
- Particles made by one command: at most ``MAX_CREATE`` (2e7), counted before any array is made.
- Ghosts: a cutoff that would copy the particles more than ``MAX_GHOST_FACTOR`` (1000) times over
  (many periodic images) is refused at the run's start.
- Sphere diameters and densities within [1e-50, 1e50], so masses and moments of inertia
  (r^5) stay normal numbers.
- Bins of an analysis grid (ave/space layers, rdf bins): at most ``MAX_BINS`` (1e6) in all (each
  written as a line of text every average).
- ``neigh_modify one``: at most ``MAX_NEIGHBORS_ONE`` (1e6) neighbors per particle on average.
- ``include`` nested at most ``MAX_INCLUDE_DEPTH`` (32) deep (a script including itself).
"""

import math

import numpy as np

from ..errors import ScriptError

MAX_COORDINATE = 1e150
MIN_RELATIVE_LENGTH = 1e-12
MAX_IMAGES = 64
MAX_BINS_PER_AXIS = 1024
MAX_CELLS = 2 ** 24
MAX_RUN = 2 ** 31 - 1
MAX_STEP = 2 ** 63 - 1
MAX_TYPES = 200
MAX_CREATE = 20_000_000
MAX_GHOST_FACTOR = 1000
MIN_SIZE, MAX_SIZE = 1e-50, 1e50
MAX_INCLUDE_DEPTH = 32
MAX_BINS = 1_000_000
MAX_NEIGHBORS_ONE = 1_000_000
MAX_TAG = 2 ** 62
MAX_IMAGE = 2 ** 31 - 1


def check_box(lo, hi, where="box"):
    """Bounds of a box as given (create_box, read_data, a restart file)."""
    lo, hi = np.asarray(lo, dtype=np.float64), np.asarray(hi, dtype=np.float64)
    for axis, a, b in zip("xyz", lo, hi):
        if not (math.isfinite(a) and math.isfinite(b)):
            raise ScriptError(f"{where} {axis} bounds must be finite numbers (got {a:g} {b:g})")
        if not a < b:
            raise ScriptError(f"{where} {axis} bounds must have lo < hi (got {a:g} {b:g})")
        largest = max(abs(a), abs(b))
        if largest > MAX_COORDINATE:
            raise ScriptError(f"{where} {axis} bounds {a:g} {b:g} are beyond +-{MAX_COORDINATE:g}, "
                              "where squared distances overflow")
        if b - a < MIN_RELATIVE_LENGTH * largest:
            raise ScriptError(f"{where} {axis} length {b - a:g} is too small to resolve at {largest:g} "
                              f"(at least {MIN_RELATIVE_LENGTH:g} of it)")
    return lo, hi


def check_images(box, cutghost, what="the cutoff plus skin", every_axis=False):
    """The ghost cutoff (largest cutoff + skin) at a run's start, or any distance a style reaches
    (``what``), against the box's periodic lengths (every length with ``every_axis``)."""
    if not (math.isfinite(cutghost) and cutghost >= 0):
        raise ScriptError(f"{what} must be a finite number >= 0 (got {cutghost:g})")
    for d, axis in enumerate("xyz"[: box.dimension]):
        length = float(box.hi[d] - box.lo[d])
        if (box.periodic[d] or every_axis) and cutghost > MAX_IMAGES * length:
            raise ScriptError(f"{what} {cutghost:g} spans {cutghost / length:.3g} "
                              f"{'periodic images of ' if box.periodic[d] else 'times '}the box "
                              f"(length {length:g} along {axis}; at most {MAX_IMAGES}): "
                              "make the box larger or the cutoff smaller")


def check_bins(count, what):
    """A grid a style allocates (analysis bins, histograms): a count it can hold."""
    if not (math.isfinite(count) and count <= MAX_BINS):
        raise ScriptError(f"{what} makes {count:.4g} bins, more than {MAX_BINS:g}")
    return int(count)


def check_ghosts(box, cutghost, natoms):
    """At a run's start: how many times over the ghosts would copy the particles."""
    factor = 1.0
    for d in range(box.dimension):
        if box.periodic[d]:
            factor *= 1.0 + 2.0 * cutghost / float(box.hi[d] - box.lo[d])
    if natoms and factor > MAX_GHOST_FACTOR:
        raise ScriptError(f"the cutoff plus skin {cutghost:g} would copy the {natoms} particles about "
                          f"{factor:.3g} times over as periodic ghosts (at most {MAX_GHOST_FACTOR}): "
                          "make the box larger or the cutoff smaller")


def bin_grid(extent, binsize):
    """Bins per axis for cells at least ``binsize`` wide over ``extent`` (3,), within the limits."""
    nbins = np.maximum(1, np.floor(np.minimum(extent / binsize, MAX_BINS_PER_AXIS))).astype(np.int64)
    while int(np.prod(nbins)) > MAX_CELLS:
        nbins = np.maximum(1, nbins // 2)
    return nbins


def check_ntypes(ntypes, where="ntypes"):
    if not 1 <= ntypes <= MAX_TYPES:
        raise ScriptError(f"{where} must be from 1 to {MAX_TYPES} (got {ntypes})")
    return ntypes
