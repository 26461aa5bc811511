"""The counter-based random numbers every stochastic style draws (pdps_core.random): their
distributions over a million draws, against the exact normal and uniform laws with sampling error
bars (5 standard errors), including the ziggurat's rare paths (wedges and the tail beyond 3.44)."""

import math

import numpy as np
import pytest
from numba import njit

from pdps_core.api import pair_gaussian, pair_uniform

DRAWS = 1_000_000


@njit(cache=True)
def _draw(n, seed, gaussian):
    out = np.empty(n)
    for k in range(n):
        step, i, j = 1 + k // 4096, 1 + k % 4096, 5000 + (k * 7919) % 65521
        out[k] = pair_gaussian(seed, step, i, j) if gaussian else pair_uniform(seed, step, i, j)
    return out


def _normal_tail(x):
    """P(|X| > x) for a standard normal X."""
    return math.erfc(x / math.sqrt(2.0))


def _within(observed, probability, n):
    return abs(observed - probability) < 5.0 * math.sqrt(probability * (1.0 - probability) / n)


@pytest.fixture(scope="module")
def normals():
    return _draw(DRAWS, 20261123, True)


def test_pair_gaussian_moments(normals):
    n = len(normals)
    assert abs(normals.mean()) < 5 / math.sqrt(n)
    assert abs(normals.var() - 1.0) < 5 * math.sqrt(2.0 / n)
    assert abs(np.mean(normals ** 3)) < 5 * math.sqrt(15.0 / n)
    assert abs(np.mean(normals ** 4) - 3.0) < 5 * math.sqrt(96.0 / n)


@pytest.mark.parametrize("x", [0.5, 1.0, 2.0, 3.0, 3.442619855899, 4.0, 4.5])
def test_pair_gaussian_tails(normals, x):
    """Both sides, and the tail beyond the ziggurat's edge (3.4426), drawn by its slow path."""
    assert _within(np.mean(np.abs(normals) > x), _normal_tail(x), len(normals))
    assert _within(np.mean(normals > x), 0.5 * _normal_tail(x), len(normals))


def test_pair_gaussian_histogram_against_the_normal_law(normals):
    """Chi-square over 60 bins of width 0.1 between -3 and 3 (the ziggurat's 128 layers and their
    wedges): within the 1e-6 quantile of chi-square with 60 degrees of freedom (about 125)."""
    edges = np.linspace(-3.0, 3.0, 61)
    counts, _ = np.histogram(normals, edges)
    cdf = np.array([0.5 * math.erfc(-e / math.sqrt(2.0)) for e in edges])
    expected = len(normals) * np.diff(cdf)
    chi2 = float(((counts - expected) ** 2 / expected).sum())
    assert chi2 < 125.0


def test_pair_uniform_is_uniform_and_symmetric():
    u = _draw(DRAWS, 777, False)
    assert 0.0 < u.min() and u.max() < 1.0
    assert abs(u.mean() - 0.5) < 5 * math.sqrt(1.0 / 12.0 / len(u))
    assert abs(u.var() - 1.0 / 12.0) < 5 * math.sqrt(1.0 / 180.0 / len(u))
    counts, _ = np.histogram(u, np.linspace(0.0, 1.0, 51))
    expected = len(u) / 50
    assert float(((counts - expected) ** 2 / expected).sum()) < 110.0      # 1e-6 quantile, 49 dof
    assert pair_uniform(3, 9, 4, 11) == pair_uniform(3, 9, 11, 4)
    assert len({pair_uniform(3, 9, 4, 11), pair_uniform(3, 10, 4, 11), pair_uniform(4, 9, 4, 11),
                pair_uniform(3, 9, 5, 11)}) == 4


def test_pair_uniform_and_pair_gaussian_are_independent():
    """The two draws of one pair and step come from different Philox blocks: no correlation."""
    g = _draw(200_000, 99, True)
    u = _draw(200_000, 99, False)
    assert abs(np.corrcoef(g, u)[0, 1]) < 5 / math.sqrt(len(g))
