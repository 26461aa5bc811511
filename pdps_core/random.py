"""Counter-based random numbers: Philox4x32-10 (Salmon et al., SC'11, "Parallel random numbers: as
easy as 1, 2, 3"; the generator of Random123, HOOMD-blue and numpy's Philox family).

A random number is a pure function of its key, so a particle or a pair gets the same noise whatever
the particle order or the number of ranks. Call from numba code:

    xi = pair_gaussian(seed, step, tag_i, tag_j)                    # N(0, 1), symmetric in i and j
    u0, u1, u2, u3 = particle_uniforms(seed, step, tag, stream)     # four U(0, 1), open interval
    g0, g1, g2, g3 = particle_gaussians(seed, step, tag, stream)    # four N(0, 1)

Argument roles: ``seed`` the style's seed from the script passed through ``sim.random_key(seed)``
(up to 2^63, both key words of Philox; the key changes when reset_timestep goes back, so a run
after it does not replay earlier noise); ``step`` the timestep (both counter words of the upper
half); ``tag_i``, ``tag_j``, ``tag`` global particle ids, all 64 bits of them (ids of 2^32 and more
hash their upper halves into the key); ``stream`` a small number a style chooses so that two of its uses of the same particle
and step (or two styles given the same seed) draw independent numbers. Counters of particles
(tag, 0) and of pairs (min, max) never coincide, as ids start at 1.
"""

import math

import numpy as np
from numba import njit

MASK32 = np.uint64(0xFFFFFFFF)
M0 = np.uint64(0xD2511F53)
M1 = np.uint64(0xCD9E8D57)
W0 = np.uint64(0x9E3779B9)
W1 = np.uint64(0xBB67AE85)
SHIFT32 = np.uint64(32)
TWO_PI = 2.0 * math.pi
INV_2_32 = 1.0 / 4294967296.0


@njit(cache=True)
def philox4x32(c0, c1, c2, c3, k0, k1):
    """Philox4x32 with 10 rounds; all arguments and results are uint64 holding 32-bit values."""
    for r in range(10):
        if r > 0:
            k0 = (k0 + W0) & MASK32
            k1 = (k1 + W1) & MASK32
        p0 = M0 * c0
        p1 = M1 * c2
        hi0, lo0 = p0 >> SHIFT32, p0 & MASK32
        hi1, lo1 = p1 >> SHIFT32, p1 & MASK32
        c0, c1, c2, c3 = hi1 ^ c1 ^ k0, lo1, hi0 ^ c3 ^ k1, lo0
    return c0, c1, c2, c3


@njit(cache=True)
def _wide_key(k, a, b):
    """The key for ids of 32 bits or more: their upper halves hashed into the seed by one more
    Philox block, so every bit of both ids counts (ids below 2^32 keep the plain seed)."""
    high_a = np.uint64(a) >> SHIFT32
    high_b = np.uint64(b) >> SHIFT32
    if high_a == 0 and high_b == 0:
        return k & MASK32, k >> SHIFT32
    h0, h1, _, _ = philox4x32(high_a, high_b, np.uint64(0x5EED), np.uint64(0x1D5),
                              k & MASK32, k >> SHIFT32)
    return h0, h1


@njit(cache=True)
def pair_gaussian(seed, step, tag_i, tag_j):
    """One N(0,1) number for the unordered pair (tag_i, tag_j) at this step (Box-Muller)."""
    a = min(tag_i, tag_j)
    b = max(tag_i, tag_j)
    s = np.uint64(step)
    k0, k1 = _wide_key(np.uint64(seed), a, b)
    r0, r1, r2, r3 = philox4x32(np.uint64(a) & MASK32, np.uint64(b) & MASK32, s & MASK32,
                                s >> SHIFT32, k0, k1)
    u1 = (float(r0) + 0.5) * INV_2_32
    u2 = (float(r1) + 0.5) * INV_2_32
    return math.sqrt(-2.0 * math.log(u1)) * math.cos(TWO_PI * u2)


@njit(cache=True)
def _particle_block(seed, step, tag, stream):
    s = np.uint64(step)
    t = np.uint64(tag)
    k = np.uint64(seed)
    mix = (np.uint64(stream) * W0) & MASK32
    return philox4x32(t & MASK32, t >> SHIFT32, s & MASK32, s >> SHIFT32, k & MASK32,
                      (k >> SHIFT32) ^ mix)


@njit(cache=True)
def particle_uniforms(seed, step, tag, stream):
    """Four U(0, 1) numbers (never 0 or 1) for particle ``tag`` at ``step`` in ``stream``."""
    r0, r1, r2, r3 = _particle_block(seed, step, tag, stream)
    return ((float(r0) + 0.5) * INV_2_32, (float(r1) + 0.5) * INV_2_32,
            (float(r2) + 0.5) * INV_2_32, (float(r3) + 0.5) * INV_2_32)


@njit(cache=True)
def particle_gaussians(seed, step, tag, stream):
    """Four N(0, 1) numbers for particle ``tag`` at ``step`` in ``stream`` (Box-Muller)."""
    u0, u1, u2, u3 = particle_uniforms(seed, step, tag, stream)
    a = math.sqrt(-2.0 * math.log(u0))
    b = math.sqrt(-2.0 * math.log(u2))
    return (a * math.cos(TWO_PI * u1), a * math.sin(TWO_PI * u1),
            b * math.cos(TWO_PI * u3), b * math.sin(TWO_PI * u3))

