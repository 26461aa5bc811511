"""LAMMPS's RanPark: the Park-Miller "minimal standard" generator, bit for bit, in numba.

Park & Miller, Comm. ACM 31, 1192 (1988); Schrage's factorisation keeps the product in 32 bits:

    seed <- 16807 seed mod (2^31 - 1)          (IA = 16807, IM = 2^31 - 1, IQ = 127773, IR = 2836)
    uniform = seed / IM                        (in (0, 1); AM = 1/IM as one double)

``gaussian`` is the Marsaglia polar method as LAMMPS writes it: two uniforms v1, v2 in (-1, 1) until
0 < r^2 = v1^2 + v2^2 < 1, then v2 f is returned and v1 f saved for the next call, with
f = sqrt(-2 ln(r^2) / r^2). ``reset(state, seed)`` restarts the stream; ``reset_coord(state, ibase,
coord)`` seeds it from a seed and a position (LAMMPS's ``velocity ... loop geom``): Jenkins's
one-at-a-time hash of the 4 bytes of the int ``ibase`` and the 24 bytes of the three doubles, each
byte added as a signed char, the low 27 bits kept (0 becomes 1), then five uniforms discarded.

The state is a float64 array of 3 (``park_state(seed)``): the seed, whether a second gaussian is
saved, and that value; every function takes it first, so numba loops can carry a generator:

    state = park_state(87287)
    u = park_uniform(state)
    g = park_gaussian(state)
"""

import math

import numpy as np
from numba import njit

from .errors import ScriptError

IA = 16807
IM = 2147483647
AM = 1.0 / IM
IQ = 127773
IR = 2836
MAX_SEED = IM - 1          # IM itself is a fixed point at 0 (every uniform 0, gaussian never ends)
SEED, SAVED, SECOND = 0, 1, 2
HASH_MASK = 0xFFFFFFFF
SEED_BITS = 0x7FFFFFF      # LAMMPS keeps these 27 bits of the hash (its comment says 31)
WARMUP_GEOM = 5


def park_state(seed):
    """A generator state seeded as LAMMPS's ``RanPark(lmp, seed)``: 1 <= seed <= 2^31 - 2."""
    if not 1 <= seed <= MAX_SEED:
        raise ScriptError(f"seed must be from 1 to {MAX_SEED} for LAMMPS's Park-Miller generator (got {seed})")
    return np.array([float(seed), 0.0, 0.0])


@njit(cache=True)
def park_uniform(state):
    seed = np.int64(state[SEED])
    k = seed // IQ
    seed = IA * (seed - k * IQ) - IR * k
    if seed < 0:
        seed += IM
    state[SEED] = seed
    return AM * seed


@njit(cache=True)
def park_gaussian(state):
    if state[SAVED] != 0.0:
        state[SAVED] = 0.0
        return state[SECOND]
    while True:
        v1 = 2.0 * park_uniform(state) - 1.0
        v2 = 2.0 * park_uniform(state) - 1.0
        rsq = v1 * v1 + v2 * v2
        if rsq < 1.0 and rsq != 0.0:
            break
    fac = math.sqrt(-2.0 * math.log(rsq) / rsq)
    state[SECOND] = v1 * fac
    state[SAVED] = 1.0
    return v2 * fac


@njit(cache=True)
def park_reset(state, seed):
    state[SEED] = seed
    state[SAVED] = 0.0


@njit(cache=True)
def _hash_byte(h, byte):
    # a char is signed on the machines LAMMPS is built for: bytes of 128 and up add as negatives
    signed = np.int64(byte) - 256 if byte >= 128 else np.int64(byte)
    h = (h + signed) & HASH_MASK
    h = (h + (h << 10)) & HASH_MASK
    return h ^ (h >> 6)


@njit(cache=True)
def park_reset_coord(state, ibase, coord):
    """Seed from ``ibase`` (a positive int) and ``coord`` (3 float64, contiguous), as LAMMPS's
    ``RanPark::reset(int, double *)``."""
    h = np.int64(0)
    for i in range(4):
        h = _hash_byte(h, (np.int64(ibase) >> (8 * i)) & 0xFF)
    data = coord.view(np.uint8)
    for i in range(24):
        h = _hash_byte(h, np.int64(data[i]))
    h = (h + (h << 3)) & HASH_MASK
    h = h ^ (h >> 11)
    h = (h + (h << 15)) & HASH_MASK
    seed = h & SEED_BITS
    if seed == 0:
        seed = 1
    state[SEED] = seed
    for _ in range(WARMUP_GEOM):
        park_uniform(state)
    state[SAVED] = 0.0


@njit(cache=True)
def park_triple(state, gaussian):
    """Three numbers as LAMMPS's velocity create draws them: U(-1/2, 1/2) each, or N(0, 1) each."""
    if gaussian:
        a = park_gaussian(state)
        b = park_gaussian(state)
        return a, b, park_gaussian(state)
    a = park_uniform(state) - 0.5
    b = park_uniform(state) - 0.5
    return a, b, park_uniform(state) - 0.5
