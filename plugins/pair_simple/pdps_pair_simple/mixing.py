"""LAMMPS's mixing of a distance (a cutoff) between types: geometric sqrt(a b), arithmetic (a + b) / 2,
sixthpower ((a^6 + b^6) / 2)^(1/6) (its Pair::mix_distance)."""

import math


def mix_distance(a, b, rule):
    if rule == "geometric":
        return math.sqrt(a * b)
    if rule == "arithmetic":
        return 0.5 * (a + b)
    return (0.5 * (a ** 6 + b ** 6)) ** (1.0 / 6.0)
