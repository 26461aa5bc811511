"""Commands of bonds: bond_style, bond_coeff, special_bonds, delete_bonds (LAMMPS's).

    bond_style NAME | none | hybrid NAME1 NAME2 ...
    bond_coeff N coeffs...               (N: a bond type or a range *, 2*, *3, 1*4)
    bond_coeff N NAME coeffs... | none   (under hybrid: the sub-style computing type N)
    special_bonds [lj/coul W12 W13 W14] [lj W12 W13 W14] [coul W12 W13 W14]
                  [lj/coul/fene | fene | charmm | amber] [angle no] [dihedral no]
    delete_bonds GROUP multi|atom T|bond T|stats [any] [undo] [remove] [special]

bond_style none computes no bond forces, and where bonds exist and no bond style is set, the run
warns, as LAMMPS 22 Jul 2025 does ("Bonds are defined but no bond style is set"). special_bonds
takes weights 0.0 and 1.0 only (pdps_core/state/topology.py): 0 leaves a special pair out of every
neighbor list, as LAMMPS does for a zero weight; a weight in between would scale the pair's force,
which pdps's pair styles do not do, and is refused at the line. Giving special_bonds rebuilds the
special lists, as in LAMMPS.

delete_bonds, as LAMMPS's: a bond is a candidate when both its particles are in the group (either,
with ``any``); ``multi`` takes every candidate, ``atom T`` those with a particle of type T, ``bond
T`` those of bond type T; each is turned off (its type made negative) or, with ``undo``, on again;
``remove`` then deletes the bonds turned off or broken (type <= 0) of the group for good, and
``special`` rebuilds the special lists (otherwise a bond turned off or removed still leaves its pair
out of the neighbor lists); ``stats`` changes nothing. Each prints LAMMPS's count line.
"""

import numpy as np

from ..errors import ScriptError
from ..styles import registry
from . import command
from .styles import spelled
from .words import integer, number, type_range

# LAMMPS's named sets of weights (lj, coul) for 1-2, 1-3, 1-4
SPECIAL_SETS = {"lj/coul/fene": ((0.0, 1.0, 1.0), (0.0, 1.0, 1.0)), "fene": ((0.0, 1.0, 1.0), (0.0, 1.0, 1.0)),
                "charmm": ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)), "amber": ((0.0, 0.0, 0.5), (0.0, 0.0, 5.0 / 6.0))}


class BondStyles:
    """The bond style of a simulation: one style for every bond type, or hybrid's sub-styles, each
    computing the types its bond_coeff lines gave it (None: bond_coeff N none)."""

    def __init__(self, styles, hybrid):
        self.styles = styles        # {name: Bond}
        self.hybrid = hybrid
        self.owner = {}             # bond type -> name (hybrid) or None

    @property
    def name(self):
        return "hybrid" if self.hybrid else next(iter(self.styles))

    def parts(self):
        """(style, [its bond types]) for each style computing some."""
        if not self.hybrid:
            style = next(iter(self.styles.values()))
            return [(style, sorted(style.coeffs) or [])] if style is not None else []
        found = []
        for name, style in self.styles.items():
            types = sorted(t for t, owner in self.owner.items() if owner == name)
            if types:
                found.append((style, types))
        return found

    def check_set(self, ntypes):
        """Every bond type has coefficients (LAMMPS: "All bond coeffs are not set")."""
        for t in range(1, ntypes + 1):
            if self.hybrid and t in self.owner:
                continue
            if not self.hybrid and t in next(iter(self.styles.values())).coeffs:
                continue
            raise ScriptError(f"bond coefficients are not set for bond type {t} (bond_coeff {t} ...)")


def _require_bond_types(sim, what):
    if sim.particles.has("num_bond") and sim.system.topology.nbondtypes > 0:
        return
    if sim.box is None:
        raise ScriptError(f"{what} before the simulation box exists (read_data or create_box first)")
    raise ScriptError(f"{what}: the box has no bond types (a particle_style with bonds and bond types in the "
                      "data file, or create_box's bond/types)")


@command("bond_style")
def bond_style(sim, args):
    if not args:
        raise ScriptError(f"expected a style; installed: {', '.join(['none', 'hybrid', *registry.names('bond')])}")
    if args[0] == "none":
        if len(args) > 1:
            raise ScriptError(f"bond_style none takes no arguments (got {' '.join(args[1:])})")
        sim.styles.bond = None
        return
    if args[0] == "hybrid":
        names = args[1:]
        if not names:
            raise ScriptError("bond_style hybrid needs one or more bond styles, e.g. bond_style hybrid harmonic fene")
        styles = {}
        for name in names:
            if name in ("none", "hybrid"):
                raise ScriptError(f"bond_style hybrid cannot have {name} as a sub-style")
            if name in styles:
                raise ScriptError(f"bond_style hybrid names {name} twice")
            cls, words = spelled(sim, "bond", name, [])
            styles[name] = cls(sim, cls.parse(words))
        sim.styles.bond = BondStyles(styles, hybrid=True)
        return
    cls, words = spelled(sim, "bond", args[0], args[1:])
    style = cls(sim, cls.parse(words))
    previous = sim.styles.bond
    if previous is not None and not previous.hybrid and previous.name == style.name:
        style.coeffs = next(iter(previous.styles.values())).coeffs     # LAMMPS keeps them for the same style
    sim.styles.bond = BondStyles({style.name: style}, hybrid=False)


@command("bond_coeff")
def bond_coeff(sim, args):
    styles = sim.styles.bond
    if styles is None:
        raise ScriptError("bond_coeff before bond_style")
    _require_bond_types(sim, "bond_coeff")
    if not args:
        raise ScriptError("expected a bond type and coefficients: bond_coeff N coeffs...")
    lo, hi = type_range(args[0], sim.system.topology.nbondtypes, "bond type")
    words = args[1:]
    if styles.hybrid:
        if not words:
            raise ScriptError(f"bond_coeff {args[0]}: under bond_style hybrid give the sub-style first "
                              f"({', '.join(styles.styles)} or none)")
        name, words = words[0], words[1:]
        if name == "none":
            if words:
                raise ScriptError(f"bond_coeff {args[0]} none takes no coefficients (got {' '.join(words)})")
            for t in range(lo, hi + 1):
                styles.owner[t] = None
            return
        if name not in styles.styles:
            raise ScriptError(f"bond_coeff {args[0]}: {name} is not a sub-style of bond_style hybrid "
                              f"({', '.join(styles.styles)} or none)")
        style = styles.styles[name]
        coeff = style.parse_coeff(words)
        for t in range(lo, hi + 1):
            style.coeffs[t] = coeff
            styles.owner[t] = name
        return
    style = next(iter(styles.styles.values()))
    coeff = style.parse_coeff(words)
    for t in range(lo, hi + 1):
        style.coeffs[t] = coeff


def _weights(words, at, what):
    if len(words) < at + 4:
        raise ScriptError(f"special_bonds {words[at]} needs three weights (1-2, 1-3, 1-4)")
    values = [number(w, f"{what} weight", 0.0, 1.0) for w in words[at + 1:at + 4]]
    for value in values:
        if value not in (0.0, 1.0):
            raise ScriptError(f"special_bonds {words[at]}: weight {value:g} between 0 and 1 is not supported: pdps's "
                              "pair styles do not scale the forces of special pairs (give 0.0, left out, or 1.0)")
    return values


@command("special_bonds")
def special_bonds(sim, args):
    topology = sim.system.topology
    lj, coul = list(topology.special_lj), list(topology.special_coul)
    i = 0
    while i < len(args):
        word = args[i]
        if word in ("lj/coul", "lj", "coul"):
            values = _weights(args, i, word)
            if word in ("lj/coul", "lj"):
                lj = values
            if word in ("lj/coul", "coul"):
                coul = values
            i += 4
        elif word in SPECIAL_SETS:
            set_lj, set_coul = SPECIAL_SETS[word]
            for values in (set_lj, set_coul):
                if any(v not in (0.0, 1.0) for v in values):
                    raise ScriptError(f"special_bonds {word}: its weights {' '.join(f'{v:g}' for v in values)} "
                                      "are not all 0 or 1, and pdps's pair styles do not scale special pairs")
            lj, coul = list(set_lj), list(set_coul)
            i += 1
        elif word in ("angle", "dihedral"):
            if i + 1 >= len(args) or args[i + 1] not in ("yes", "no"):
                raise ScriptError(f"special_bonds {word} takes yes or no")
            if args[i + 1] == "yes":
                raise ScriptError(f"special_bonds {word} yes counts 1-{'3' if word == 'angle' else '4'} neighbors "
                                  f"by {word}s, and pdps has no {word} styles")
            i += 2
        elif word in ("extra", "one/five"):
            raise ScriptError(f"special_bonds {word} is not supported (pdps keeps 1-2, 1-3 and 1-4 neighbors)")
        else:
            raise ScriptError(f"unknown special_bonds keyword {word} (lj/coul, lj, coul, fene, lj/coul/fene, "
                              "charmm, amber, angle, dihedral)")
    topology.special_lj, topology.special_coul = lj, coul
    if sim.box is not None and topology.has_bonds(sim.particles):
        topology.build_special(sim)


DELETE_STYLES = ("multi", "atom", "bond", "stats")


@command("delete_bonds")
def delete_bonds(sim, args):
    if len(args) < 2:
        raise ScriptError("expected: delete_bonds GROUP multi|atom T|bond T|stats [any] [undo] [remove] [special]")
    sim.require_box("delete_bonds")
    group, style = sim.require_group(args[0]), args[1]
    if style not in DELETE_STYLES:
        extra = " (pdps has no angles, dihedrals or impropers)" if style in ("angle", "dihedral", "improper") else ""
        raise ScriptError(f"unknown delete_bonds style {style} (multi, atom, bond, stats){extra}")
    i, which = 2, None
    if style in ("atom", "bond"):
        if len(args) < 3:
            raise ScriptError(f"delete_bonds {style} needs a type")
        which = integer(args[2], "atom type" if style == "atom" else "bond type",
                        1 if style == "atom" else 0)
        i = 3
    flags = set()
    for word in args[i:]:
        if word not in ("any", "undo", "remove", "special"):
            raise ScriptError(f"unknown delete_bonds keyword {word} (any, undo, remove, special)")
        flags.add(word)
    p = sim.particles
    if not p.has("num_bond"):
        raise ScriptError("delete_bonds: there are no bonds (a particle_style with bonds and a data file's Bonds)")
    sim.output.message("Deleting bonds ...")
    bit = sim.groups.bit(group)
    partner_mask, partner_type = _partners(sim)
    n = p.nlocal
    width = p.bond_type.shape[1]
    slots = np.arange(width)[None, :] < p.num_bond[:n, None]
    mine = (p.mask[:n] & bit) != 0
    theirs = (partner_mask & bit) != 0
    chosen = (mine[:, None] | theirs) if "any" in flags else (mine[:, None] & theirs)
    chosen &= slots
    kinds = p.bond_type[:n]
    if style == "atom":
        chosen &= (p.type[:n, None] == which) | (partner_type == which)
    elif style == "bond":
        chosen &= np.abs(kinds) == which         # a bond turned off is still of its type (undo)
    if style != "stats":
        if "undo" in flags:
            kinds[chosen & (kinds < 0)] *= -1
        else:
            kinds[chosen & (kinds > 0)] *= -1
    if "remove" in flags:
        gone = slots & (kinds <= 0) & ((mine[:, None] | theirs) if "any" in flags else (mine[:, None] & theirs))
        for row in np.flatnonzero(gone.any(axis=1)):
            keep = np.flatnonzero(slots[row] & ~gone[row])
            p.bond_type[row, :len(keep)] = p.bond_type[row, keep]
            p.bond_atom[row, :len(keep)] = p.bond_atom[row, keep]
            p.num_bond[row] = len(keep)
        slots = np.arange(width)[None, :] < p.num_bond[:n, None]
    on = int(sim.comm.sum(int((slots & (p.bond_type[:n] > 0)).sum())))
    off = int(sim.comm.sum(int((slots & (p.bond_type[:n] <= 0)).sum())))
    sim.output.message(f"  {on + off} total bonds, {on} turned on, {off} turned off")
    if "special" in flags:
        sim.system.topology.build_special(sim)


def _partners(sim):
    """(mask, type) of each bond's partner, (nlocal, width), from every rank's particles (a command:
    no ghosts are needed)."""
    p = sim.particles
    n, width = p.nlocal, p.bond_type.shape[1]
    rows = np.stack([p.tag[:n], p.mask[:n], p.type[:n]], axis=1).astype(np.float64)
    every = sim.comm.allgather_rows(rows).astype(np.int64).reshape(-1, 3)
    index = {int(tag): (mask, kind) for tag, mask, kind in every.tolist()}
    masks = np.zeros((n, width), dtype=np.uint32)
    types = np.zeros((n, width), dtype=np.int32)
    for row in range(n):
        for b in range(int(p.num_bond[row])):
            tag = int(p.bond_atom[row, b])
            found = index.get(tag)
            if found is None:
                raise ScriptError(f"bond atom {tag} missing in delete_bonds (the bond of {int(p.tag[row])})")
            masks[row, b], types[row, b] = found
    return masks, types
