"""Finite-value checks run at every step or rebuild, as numba passes without temporaries."""

import math

from numba import njit


@njit(cache=True, fastmath={"reassoc"})
def _nan_if_not_finite(values, n):
    """NaN when one of the first ``n`` rows holds a NaN or an infinity (v * 0 is NaN for those), else
    0: a sum the compiler may reorder, so it runs in vector registers."""
    flat = values[:n].reshape(-1)
    total = 0.0
    for k in range(flat.shape[0]):
        total += flat[k] * 0.0
    return total


@njit(cache=True)
def first_non_finite(values, n):
    """Index of the first of the first ``n`` rows holding a NaN or an infinity, -1 if none (every
    step checks positions and forces: one vectorised pass, no temporaries)."""
    if _nan_if_not_finite(values, n) == 0.0:
        return -1
    for i in range(n):
        for d in range(values.shape[1]):
            if not math.isfinite(values[i, d]):
                return i
    return -1
