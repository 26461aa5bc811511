"""LAMMPS's mixing of a distance (a cutoff) between types: geometric sqrt(a b), arithmetic (a + b) / 2,
sixthpower ((a^6 + b^6) / 2)^(1/6) (its Pair::mix_distance), and the cutoffs it mixes: a type pair's
own, else the pair style's global one."""

import math


def mix_distance(a, b, rule):
    if rule == "geometric":
        return math.sqrt(a * b)
    if rule == "arithmetic":
        return 0.5 * (a + b)
    return (0.5 * (a ** 6 + b ** 6)) ** (1.0 / 6.0)


def cutoff_of(style, coeff):
    """A type pair's cutoff: its coefficients' own, else the pair style's global one."""
    return coeff.cutoff if coeff.cutoff is not None else style.args.cutoff


def mixed_cutoff(style, ci, cj, rule):
    """The i-j cutoff mixed from the i-i and j-j ones (LAMMPS's init_one for unset pairs)."""
    return mix_distance(cutoff_of(style, ci), cutoff_of(style, cj), rule)
