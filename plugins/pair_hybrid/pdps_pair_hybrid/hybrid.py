r"""Pair styles ``hybrid`` and ``hybrid/overlay``: several pair styles in one run, each acting on the
type pairs assigned to it (LAMMPS's pair_style hybrid and hybrid/overlay).

.. math::

    E = \sum_{i<j} \sum_{s \in S(t_i, t_j)} E_s(r_{ij})

where S(t_i, t_j) is the set of sub-styles assigned to the pair of types: one (``hybrid``) or any
number (``hybrid/overlay``, whose energies and forces add), or none. Units are the sub-styles'.

Syntax::

    pair_style hybrid STYLE1 ARGS1 STYLE2 ARGS2 ...
    pair_style hybrid/overlay STYLE1 ARGS1 STYLE2 ARGS2 ...
    pair_coeff I J STYLE COEFFS...        (COEFFS as the sub-style's own pair_coeff)
    pair_coeff I J none                   (no interaction between types I and J)

A word of the pair_style line that names an installed pair style starts the next sub-style. With
``hybrid`` a later pair_coeff moves the type pair to its style; with ``hybrid/overlay`` it adds the
style to the pair's (``none`` clears them). An i != j pair given no pair_coeff is mixed by the
sub-style of its i i and j j pairs when each has just that one (with the sub-style's mixing rule or
``pair_modify mix``), as LAMMPS; otherwise it must be given. A sub-style no pair uses is refused. ``pair_modify`` applies to every
sub-style; the tail correction of a pair sums those of its sub-styles that have one.

The core builds one half neighbor list with, for each type pair, the largest cutoff among its
sub-styles; each sub-style's loop sees only its own pairs (the others' cutoffs are 0). Sub-styles are
force laws over half lists (``PairLaw``: lj/cut, soft, morse, yukawa, zero, table, dpd, dpd/fdt, ...)
and the styles with a loop of their own that skips the type pairs left to others (``Pair.hybrid_sub_style``:
dpd/ext, dpd/ext/tstat). A granular style (one with its own loop over a list of its own) may be the
only sub-style of ``hybrid``: then the line is that style, each pair_coeff naming it first (LAMMPS's
granregion example: ``pair_style hybrid gran/hooke ...`` with ``pair_coeff * * gran/hooke``; a
restart brings it back as that style itself, whose pair_coeff lines then name no style); beside
other sub-styles, or with ``hybrid/overlay``, it is refused by name. A style may appear more than once,
each with its own settings (LAMMPS's); then pair_coeff names which, counted from 1:
``pair_coeff I J soft 2 COEFFS`` (``soft:2`` in what pdps prints). Example::

    pair_style hybrid lj/cut 2.5 soft 1.12
    pair_coeff 1 1 lj/cut 1.0 1.0
    pair_coeff 2 2 soft 10.0
    pair_coeff 1 2 none
"""

import inspect
from typing import Annotated, NamedTuple

import numpy as np

from pdps_core.api import Pair, ScriptError, StyleArgs, StyleName, param, registry


class SubStyle(NamedTuple):
    """One sub-style of the pair_style line: its name and the words its own ``parse`` reads."""
    style: Annotated[str, StyleName("pair")]
    args: tuple[str, ...]


class SubStyles(StyleArgs):
    substyles: list[SubStyle] = param(min_length=1, names="pair style, then its own arguments")


def sole_sub_style(cls):
    """``cls`` as the one sub-style of pair_style hybrid: the style itself, its pair_coeff lines
    naming it before its own coefficients."""

    class Sole(cls):
        def parse_coeff(self, words):
            if not words or words[0] != cls.name:
                got = " ".join(words) or "nothing"
                raise ScriptError(f"pair_coeff I J {cls.name} COEFFS: the only sub-style of this pair_style hybrid "
                                  f"is {cls.name} (got {got})")
            return super().parse_coeff(words[1:])

    Sole.__name__ = Sole.__qualname__ = f"Hybrid{cls.__name__}"
    return Sole


class PairHybrid(Pair):
    name = "hybrid"
    usage = "pair_style hybrid STYLE1 ARGS1 [STYLE2 ARGS2 ...]"
    coeff_usage = "STYLE COEFFS... | none"
    overlay = False
    peratom_tally = True        # every sub-style is a force law, which tallies
    Args = SubStyles

    @classmethod
    def respell(cls, dialect, words):
        # hybrid with one sub-style that has its own loop (a granular one) is that style
        if cls.overlay or not words or words[0] not in registry.names("pair"):
            return None
        names = registry.names("pair")
        if any(word in names for word in words[1:]):
            return None
        sub = registry.lookup("pair", words[0])
        if cls.force_law(sub) or words[0] in ("hybrid", "hybrid/overlay"):
            return None
        return sole_sub_style(sub), list(words[1:])

    @staticmethod
    def force_law(sub):
        """Whether the pair style class ``sub`` can share a run with others as a sub-style."""
        return (sub.hybrid_sub_style and sub.neighbor_list == "half"
                and "pairs" in inspect.signature(sub.init).parameters)

    @classmethod
    def check_args(cls, args):
        names = [name for name, _ in args.substyles]
        for k, name in enumerate(names):
            if name in ("hybrid", "hybrid/overlay"):
                raise ScriptError(f"pair style {name} cannot be a sub-style of {cls.name}")

    def __init__(self, sim, args):
        super().__init__(sim, args)
        self.styles = {}
        names = [name for name, _ in args.substyles]
        self.repeated = {name for name in names if names.count(name) > 1}
        seen = {}
        for name, words in args.substyles:
            cls = registry.lookup("pair", name)
            if not self.force_law(cls):
                raise ScriptError(f"pair style {name} cannot be a sub-style of {self.name}: it is not a force law "
                                  "over a half list")
            seen[name] = seen.get(name, 0) + 1
            label = f"{name}:{seen[name]}" if name in self.repeated else name
            self.styles[label] = cls(sim, cls.parse(list(words)))
        subs = list(self.styles.values())
        self.per_atom = tuple(dict.fromkeys(entry for s in subs for entry in s.per_atom))
        self.ghost_velocity = any(s.ghost_velocity for s in subs)
        self.ghost_fields = tuple(dict.fromkeys(f for s in subs for f in s.ghost_fields))
        self.assigned = {}      # (i, j), i <= j -> [style names]

    def parse_coeff(self, words):
        if not words:
            raise ScriptError(f"expected a sub-style or none; usage: pair_coeff I J {self.coeff_usage}")
        name = words[0]
        if name == "none":
            if len(words) > 1:
                raise ScriptError(f"pair_coeff I J none takes nothing more (got {' '.join(words[1:])})")
            return (name, None)
        rest = words[1:]
        if name in self.repeated:
            count = sum(label.startswith(f"{name}:") for label in self.styles)
            if not rest or not rest[0].isdigit() or not 1 <= int(rest[0]) <= count:
                raise ScriptError(f"pair style {name} appears {count} times in pair_style {self.name}: name which "
                                  f"with a number from 1 to {count} after it (got {' '.join(rest) or 'nothing'})")
            name, rest = f"{name}:{int(rest[0])}", rest[1:]
        if name not in self.styles:
            raise ScriptError(f"{name} is not a sub-style of this pair_style {self.name} "
                              f"(it has: {', '.join(self.styles)})")
        return (name, self.styles[name].parse_coeff(rest))

    @property
    def substyles(self):
        """name -> sub-style, each holding its own coefficients (a restart writes them so)."""
        return self.styles

    def state(self):
        return {"assigned": [[i, j, names] for (i, j), names in sorted(self.assigned.items())]}

    def restore(self, state):
        for i, j, names in state["assigned"]:
            unknown = [name for name in names if name not in self.styles]
            if unknown:
                raise ScriptError(f"pair {self.name}: the restart file assigns types {i} {j} to {unknown[0]}, "
                                  "which is not one of its sub-styles")
            self.assigned[(int(i), int(j))] = list(names)

    def coeff(self, i, j, coeff):
        key = (min(i, j), max(i, j))
        name, values = coeff
        if name == "none":
            self.assigned[key] = []
            return
        self.styles[name].coeff(i, j, values)
        if self.overlay:
            self.assigned[key] = [*(s for s in self.assigned.get(key, []) if s != name), name]
        else:
            self.assigned[key] = [name]

    def _assignment(self, ntypes):
        """Type pair -> sub-styles, the unset i != j pairs taking their i i and j j pairs' common ones."""
        assigned = {}
        for i in range(1, ntypes + 1):
            for j in range(i, ntypes + 1):
                if (i, j) in self.assigned:
                    assigned[(i, j)] = self.assigned[(i, j)]
                elif i == j:
                    raise ScriptError(f"pair coefficients are not set for types {i} {j} (give pair_coeff {i} {j} "
                                      "STYLE ... or none)")
                elif len(self.assigned[(i, i)]) == 1 and self.assigned[(i, i)] == self.assigned.get((j, j)):
                    assigned[(i, j)] = list(self.assigned[(i, i)])
                else:
                    raise ScriptError(f"pair coefficients are not set for types {i} {j}: only a pair whose types "
                                      "each have the same one sub-style is mixed (give pair_coeff "
                                      f"{i} {j} STYLE ... or none)")
        return assigned

    def init(self, ntypes):
        assigned = self._assignment(ntypes)
        self.resolved = assigned
        cut = np.zeros((ntypes + 1, ntypes + 1))
        self.active = []
        for name, style in self.styles.items():
            pairs = {key for key, names in assigned.items() if name in names}
            style.mix_rule, style.shift = self.mix_rule, self.shift
            style.tail = False
            if not pairs:
                raise ScriptError(f"pair {self.name} sub-style {name} is not used (no pair_coeff assigns a type "
                                  "pair to it)")
            cut = np.maximum(cut, style.init(ntypes, pairs))
            self.active.append(style)
        self.sum_tails(ntypes, lambda i, j, count_i, count_j: [
            self.styles[name].tail_ij(i, j, count_i, count_j) for name in assigned[(i, j)]])
        return cut

    def single(self, sim, i, j, delta):
        """The sum over the sub-styles in use: each is 0 on the type pairs it is not assigned."""
        fpair, energy = np.zeros(len(delta)), np.zeros(len(delta))
        for style in self.active:
            f, e = style.single(sim, i, j, delta)
            fpair += f
            energy += e
        return fpair, energy

    def tail_ij(self, i, j, count_i, count_j):
        """Summed over the pair's sub-styles in ``init`` (those without a tail correction add 0)."""
        raise NotImplementedError

    def compute(self, sim, nlist, eflag, vflag):
        energy = 0.0
        for style in self.active:
            style.compute(sim, nlist, eflag, vflag)
            energy += style.energy
        self.energy = energy


class PairHybridOverlay(PairHybrid):
    name = "hybrid/overlay"
    usage = "pair_style hybrid/overlay STYLE1 ARGS1 [STYLE2 ARGS2 ...]"
    overlay = True
