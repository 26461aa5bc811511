"""The turning of a contact's history with its normal, as LAMMPS's granular models do it
(GranSubMod::rotate_rescale_vec): the stored vector is projected onto the current tangent plane and
scaled back to its length before, so a spring keeps its stretch while the contact rolls."""

import math

from numba import njit

from pdps_granular_contact.contact_state import NX, NY, NZ

# LAMMPS's EPSILON of the tangential and rolling models: the history is turned only when its normal
# part matters against the Coulomb limit
EPSILON = 1e-10


@njit(cache=True)
def along_normal(c, hist, h):
    """hist[h:h+3] . n."""
    return hist[h] * c[NX] + hist[h + 1] * c[NY] + hist[h + 2] * c[NZ]


@njit(cache=True)
def rotate_rescale(c, hist, h):
    """hist[h:h+3] onto the plane normal to n, its length kept (0 if it lay along n)."""
    before = math.sqrt(hist[h] * hist[h] + hist[h + 1] * hist[h + 1] + hist[h + 2] * hist[h + 2])
    along = along_normal(c, hist, h)
    hist[h] -= along * c[NX]
    hist[h + 1] -= along * c[NY]
    hist[h + 2] -= along * c[NZ]
    after = math.sqrt(hist[h] * hist[h] + hist[h + 1] * hist[h + 1] + hist[h + 2] * hist[h + 2])
    scale = before / after if after > 0.0 else 0.0
    hist[h] *= scale
    hist[h + 1] *= scale
    hist[h + 2] *= scale


@njit(cache=True)
def coulomb_cut(hist, h, fx, fy, fz, dx, dy, dz, limit, per_history, store):
    """A force (fx, fy, fz) = per_history * hist[h:h+3] + (dx, dy, dz) (its damping part) cut back to
    ``limit``: returned scaled onto the limit, the history set (when ``store``) to the elastic part of
    the cut force; a history of zero length over the limit gives no force (LAMMPS's)."""
    size = math.sqrt(fx * fx + fy * fy + fz * fz)
    if size <= limit:
        return fx, fy, fz
    if hist[h] == 0.0 and hist[h + 1] == 0.0 and hist[h + 2] == 0.0:
        return 0.0, 0.0, 0.0
    ratio = limit / size
    fx *= ratio
    fy *= ratio
    fz *= ratio
    if store:
        back = 1.0 / per_history if per_history != 0.0 else 0.0
        hist[h] = (fx - dx) * back
        hist[h + 1] = (fy - dy) * back
        hist[h + 2] = (fz - dz) * back
    return fx, fy, fz
