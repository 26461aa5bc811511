"""Counter-based random numbers: Philox4x32-10 (Salmon et al., SC'11, "Parallel random numbers: as
easy as 1, 2, 3"; the generator of Random123, HOOMD-blue and numpy's Philox family).

A random number is a pure function of its key, so a particle or a pair gets the same noise whatever
the particle order or the number of ranks. Call from numba code:

    xi = pair_gaussian(seed, step, tag_i, tag_j)                    # N(0, 1), symmetric in i and j
    u = pair_uniform(seed, step, tag_i, tag_j)                      # U(0, 1), symmetric in i and j
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


def _ziggurat_tables(layers=128, edge=3.442619855899, area=9.91256303526217e-3):
    """Marsaglia and Tsang's ziggurat for the normal density (J. Stat. Softw. 5 (8), 2000): for
    layer i, ``accept[i]`` bounds |h| (h a signed 32-bit number) of the draws that fall inside the
    layer's rectangle, ``width[i]`` turns h into x, ``height[i]`` is exp(-x_i^2/2) at its edge."""
    accept = np.zeros(layers, dtype=np.int64)
    width = np.zeros(layers)
    height = np.zeros(layers)
    scale = 2.0 ** 31
    x = edge
    q = area / math.exp(-0.5 * x * x)
    accept[0] = int(x / q * scale)
    width[0] = q / scale
    width[layers - 1] = x / scale
    height[0] = 1.0
    height[layers - 1] = math.exp(-0.5 * x * x)
    for i in range(layers - 2, 0, -1):
        inner = math.sqrt(-2.0 * math.log(area / x + math.exp(-0.5 * x * x)))
        accept[i + 1] = int(inner / x * scale)
        x = inner
        height[i] = math.exp(-0.5 * x * x)
        width[i] = x / scale
    return accept, width, height


ZIGGURAT_ACCEPT, ZIGGURAT_WIDTH, ZIGGURAT_HEIGHT = _ziggurat_tables()
ZIGGURAT_EDGE = 3.442619855899
INT32_OFFSET = np.int64(2 ** 31)


@njit(cache=True)
def _signed(word):
    return np.int64(word) - INT32_OFFSET


@njit(cache=True)
def _unit(word):
    return (float(word) + 0.5) * INV_2_32


@njit(cache=True)
def pair_gaussian(seed, step, tag_i, tag_j):
    """One N(0,1) number for the unordered pair (tag_i, tag_j) at this step, by the ziggurat: one
    Philox block gives the layer and the value, and 99 % of draws end there (two further words and,
    rarely, further blocks of the same key serve the wedges and the tail)."""
    a = min(tag_i, tag_j)
    b = max(tag_i, tag_j)
    s = np.uint64(step)
    k0, k1 = _wide_key(np.uint64(seed), a, b)
    c0, c1 = np.uint64(a) & MASK32, np.uint64(b) & MASK32
    c2, c3 = s & MASK32, s >> SHIFT32
    r0, r1, r2, r3 = philox4x32(c0, c1, c2, c3, k0, k1)
    h = _signed(r0)
    layer = np.int64(r1) & 127
    if abs(h) < ZIGGURAT_ACCEPT[layer]:
        return h * ZIGGURAT_WIDTH[layer]
    block = 0
    while True:
        x = h * ZIGGURAT_WIDTH[layer]
        if layer == 0:
            # the tail beyond the edge (Marsaglia's method): two uniforms per try
            while True:
                block += 1
                t0, t1, _, _ = philox4x32(c0, c1, c2, c3, k0, (k1 + np.uint64(block) * W0) & MASK32)
                tail = -math.log(_unit(t0)) / ZIGGURAT_EDGE
                if -2.0 * math.log(_unit(t1)) > tail * tail:
                    return ZIGGURAT_EDGE + tail if h > 0 else -ZIGGURAT_EDGE - tail
        if ZIGGURAT_HEIGHT[layer] + _unit(r2) * (ZIGGURAT_HEIGHT[layer - 1] - ZIGGURAT_HEIGHT[layer]) \
                < math.exp(-0.5 * x * x):
            return x
        block += 1
        r0, r1, r2, r3 = philox4x32(c0, c1, c2, c3, k0, (k1 + np.uint64(block) * W0) & MASK32)
        h = _signed(r0)
        layer = np.int64(r1) & 127
        if abs(h) < ZIGGURAT_ACCEPT[layer]:
            return h * ZIGGURAT_WIDTH[layer]


@njit(cache=True)
def pair_uniform(seed, step, tag_i, tag_j):
    """One U(0, 1) number (never 0 or 1) for the unordered pair (tag_i, tag_j) at this step, from
    the Philox block pair_gaussian's would start with, through another key word."""
    a = min(tag_i, tag_j)
    b = max(tag_i, tag_j)
    s = np.uint64(step)
    k0, k1 = _wide_key(np.uint64(seed), a, b)
    r0, _, _, _ = philox4x32(np.uint64(a) & MASK32, np.uint64(b) & MASK32, s & MASK32, s >> SHIFT32,
                             k0 ^ np.uint64(0x55555555), k1)
    return _unit(r0)


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

