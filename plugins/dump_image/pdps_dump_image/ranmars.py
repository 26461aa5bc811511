"""RanMars: Marsaglia, Zaman and Tsang's universal generator (RANMAR, F. James, Comp. Phys. Comm. 60,
329 (1990)), the generator LIGGGHTS 3.8.0 and LAMMPS jitter SSAO with.

The state is 97 lagged-Fibonacci numbers u[1..97] and an arithmetic sequence c, set from one seed
in 1..900000000 through two 3-lag and 1-lag generators; each number is (u[i] - u[j]) mod 1 minus c
mod 1. LIGGGHTS's generator draws one number when it is made (its RanMars constructor does), so its
first SSAO number is RANMAR's second: ``RanMars(seed)`` does the same.

The state lives in two arrays the renderer's kernel advances (render._uniform): ``state`` (101
floats: u[1..97] at 1..97, then c, cd, cm) and ``indices`` (i97, j97).
"""

import numpy as np

from .render import _uniform


class RanMars:
    def __init__(self, seed):
        if not 0 < seed <= 900000000:
            raise ValueError(f"the seed must be from 1 to 900000000 (got {seed})")
        state = np.zeros(101)
        ij = (seed - 1) // 30082
        kl = (seed - 1) - 30082 * ij
        i = (ij // 177) % 177 + 2
        j = ij % 177 + 2
        k = (kl // 169) % 178 + 1
        m_l = kl % 169
        for ii in range(1, 98):
            s, t = 0.0, 0.5
            for _ in range(24):
                m = ((i * j) % 179) * k % 179
                i, j, k = j, k, m
                m_l = (53 * m_l + 1) % 169
                if (m_l * m) % 64 >= 32:
                    s = s + t
                t = 0.5 * t
            state[ii] = s
        state[98] = 362436.0 / 16777216.0
        state[99] = 7654321.0 / 16777216.0
        state[100] = 16777213.0 / 16777216.0
        self.state = state
        self.indices = np.array([97, 33], dtype=np.int64)
        self.uniform()

    def uniform(self):
        return _uniform(self.state, self.indices)
