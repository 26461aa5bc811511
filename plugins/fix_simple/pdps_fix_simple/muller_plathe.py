"""What fix thermal/conductivity and fix viscosity share (Muller-Plathe's reverse non-equilibrium
swaps, J. Chem. Phys. 106, 6082 (1997) and Phys. Rev. E 59, 4894 (1999)): the two slabs of the box
along an axis (the lowest of NBIN, and the one just above half height), and the NSWAP best particles of
each over all ranks. No style of its own."""

import numpy as np

from pdps_core.api import ScriptError

AXES = ("x", "y", "z")


def check_slabs(style, nbin):
    """NBIN must be even and above 2 (LAMMPS 22 Jul 2025 refuses others: "Illegal fix ... command")."""
    if nbin % 2 or nbin <= 2:
        raise ScriptError(f"{style}: nbin must be even and > 2 (got {nbin})")


def slab_members(sim, group, dim, nbin):
    """(rows in the lowest slab, rows in the slab at half height) of the group's owned particles, a
    coordinate outside a periodic box taken back by one period, as LAMMPS's."""
    box = sim.box
    p = sim.particles
    lo, hi, length = float(box.lo[dim]), float(box.hi[dim]), float(box.length[dim])
    width = (hi - lo) / nbin
    coord = p.x[:p.nlocal, dim].copy()
    if box.periodic[dim]:
        coord[coord < lo] += length
        coord[coord >= hi] -= length
    chosen = sim.groups.select(sim, group)
    low = chosen & (coord >= lo) & (coord < lo + width)
    middle = chosen & (coord >= lo + (nbin // 2) * width) & (coord < lo + (nbin // 2 + 1) * width)
    return np.flatnonzero(low), np.flatnonzero(middle)


def best(sim, rows, key, nswap):
    """The NSWAP rows of this slab over all ranks with the smallest key, in order: (tag, key, rank,
    row) records; a tie goes to the smaller id (LAMMPS's goes to the particle it met first, an order
    that depends on how it stores them)."""
    p = sim.particles
    tags = p.tag[rows]
    order = np.lexsort((tags, key))[:nswap]
    local = np.column_stack([tags[order].astype(np.float64), key[order],
                             np.full(len(order), float(sim.comm.rank)), rows[order].astype(np.float64)])
    every = np.asarray(sim.comm.allgather_rows(local), dtype=np.float64).reshape(-1, 4)
    return every[np.lexsort((every[:, 0], every[:, 1]))][:nswap]


def owned_values(sim, records, values):
    """Per record, the particle's ``values`` (rows of an (nlocal, k) array) from the rank owning it,
    known on every rank."""
    mine = records[:, 2] == sim.comm.rank
    found = np.zeros((len(records), values.shape[1]))
    found[mine] = values[records[mine, 3].astype(np.int64)]
    return np.asarray(sim.comm.sum(found), dtype=np.float64)
