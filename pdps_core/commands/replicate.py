"""``replicate``: copies of every particle side by side in a box NX NY NZ times as large, LAMMPS's
way or, with ``offset``, LIGGGHTS's.

    replicate NX NY NZ [bbox]                               (LAMMPS's)
    replicate NX NY NZ offset OX OY OZ [shift SX SY SZ]     (LIGGGHTS's)

LAMMPS's (its Replicate, 22 Jul 2025): the box keeps its lower corner and its lengths become
NX Lx, NY Ly, NZ Lz. Each particle is unwrapped by its image flags (u = x + i L), and copy
(ix, iy, iz), 0 <= ix < NX and so on, lies at u + (ix Lx, iy Ly, iz Lz) wrapped into the new box
along its periodic axes, its image flags counting from 0; its id is the particle's plus
(iz NY NX + iy NX + ix) times the largest id, a molecule id above 0 the same multiple of the
largest molecule id. ``bbox`` (a faster search for the copies a processor owns) changes nothing.

LIGGGHTS's (its Replicate, 3.8.0 source; recorded): every particle moves by the shift (0 when not
given) and so does the box's lower corner, the lengths again becoming NX Lx, NY Ly, NZ Lz; copy
(i, j, k) lies at the shifted position plus (i OX, j OY, k OZ), not wrapped (the next run's setup
does that), with the particle's image flags and molecule id; its id is the particle's plus
((i NY + j) NZ + k) times the largest id (LIGGGHTS counts by the number of particles, the same for
ids 1..N). LIGGGHTS 3.8.0 itself refuses the line without shift ("Illegal replicate command",
measured), which its manual allows and pdps reads.

In both, copies take every other per-particle value (velocities, radii, masses, types, groups,
the values a style keeps for its particles and says copies share: temperatures, fix property/atom
values); a style's values a copy must not take (a rigid body's members, the position a particle
started from, a contact partner while a contact is open) are refused at the line: replicate
before defining such styles or running. The copies are listed in LAMMPS's order on one rank
(copy by copy, each in the particles' order), the processor grid is chosen again for the new box,
and a replicated non-periodic axis draws a warning (both programs': copies may overlap there).

Example::

    replicate 2 2 1
    replicate 2 1 1 offset 0.06 0.0 0.0 shift 0.01 0.0 0.0
"""

from typing import Literal

import numpy as np

from ..errors import ScriptError
from ..run.shrink_wrap import set_initial_box
from ..state import limits
from ..state.box import remap
from ..state.particles import CORE, KNOWN
from ..styles import StyleArgs, keyword, param, parse_args
from . import command

USAGE = "replicate NX NY NZ [bbox] | replicate NX NY NZ offset OX OY OZ [shift SX SY SZ]"


class Args(StyleArgs):
    nx: int = param(ge=1, le=limits.MAX_CREATE, unit="1")
    ny: int = param(ge=1, le=limits.MAX_CREATE, unit="1")
    nz: int = param(ge=1, le=limits.MAX_CREATE, unit="1")
    option: Literal["bbox", "bondlist"] | None = param(None)
    offset: tuple[float, float, float] | None = keyword(None, unit="distance")
    shift: tuple[float, float, float] | None = keyword(None, unit="distance")


@command("replicate")
def replicate(sim, args):
    sim.require_box("replicate")
    args = parse_args(Args, args, usage=USAGE)
    counts = np.array([args.nx, args.ny, args.nz])
    if args.option == "bondlist":
        raise ScriptError("replicate bondlist re-links bonds across the copies, and pdps has no bonds: replicate "
                          "NX NY NZ")
    if args.shift is not None and args.offset is None:
        raise ScriptError(f"shift goes with offset (LIGGGHTS's replicate); usage: {USAGE}")
    if args.option is not None and args.offset is not None:
        raise ScriptError(f"{args.option} is LAMMPS's replicate's, offset LIGGGHTS's: give one; usage: {USAGE}")
    if sim.dimension == 2 and args.nz != 1:
        raise ScriptError(f"a 2-d simulation cannot be replicated in z (nz = {args.nz})")
    copies = args.nx * args.ny * args.nz
    p, box, comm = sim.particles, sim.box, sim.comm
    _refuse_what_copies_cannot_take(sim)
    if args.offset is None:
        _refuse_lost(sim)
    n = p.nlocal
    made = int(comm.sum(n)) * (copies - 1)
    if made > limits.MAX_CREATE:
        raise ScriptError(f"replicate {args.nx} {args.ny} {args.nz} would make {made} particles (at most "
                          f"{limits.MAX_CREATE} at once)")
    largest = int(comm.max(int(p.tag[:n].max()) if n else 0))
    largest_molecule = int(comm.max(int(p.molecule[:n].max()) if n else 0)) if p.has("molecule") else 0
    if copies * largest > limits.MAX_TAG or copies * largest_molecule > limits.MAX_TAG:
        raise ScriptError(f"replicate {args.nx} {args.ny} {args.nz} gives ids beyond {limits.MAX_TAG}")
    p.check_room(n * (copies - 1))
    if any(c > 1 and not periodic for c, periodic in zip(counts, box.periodic)):
        sim.warn("Replicating in a non-periodic dimension")
    length = box.length.copy()
    if args.offset is None:
        values, lo = _lammps_copies(sim, counts, largest, largest_molecule), box.lo.copy()
    else:
        shift = np.zeros(3) if args.shift is None else np.array(args.shift)
        values, lo = _liggghts_copies(sim, counts, np.array(args.offset), shift, largest), box.lo + shift
    hi = lo + counts * length
    limits.check_box(lo, hi, "the replicated box's")
    if args.offset is None:
        _wrap_copies(sim, values, lo, hi)
    lo, hi, sim.system.shrink_faces = set_initial_box(sim.system.periodicity, lo, hi)
    box.set_bounds(lo, hi)
    p.load(p.properties, values, n * copies)
    p.next_tag = max(p.next_tag, copies * largest + 1)
    comm.decompose(box)
    comm.migrate(p, box)
    sim.groups.update(sim)
    sim.run_state.box_changed = True
    total = int(comm.sum(p.nlocal))
    sim.output.message(f"Replicating atoms ...\n  {args.nx}x{args.ny}x{args.nz} = {copies} copies, orthogonal box = "
                       f"({' '.join(f'{v:.8g}' for v in lo)}) to ({' '.join(f'{v:.8g}' for v in hi)})\n  {total} atoms")


def _refuse_what_copies_cannot_take(sim):
    """A style's per-particle values that copies must not take (Property.replicate), on every rank."""
    p = sim.particles
    for name, prop in p.properties.items():
        rule = "copy" if name in CORE or name in KNOWN else prop.replicate
        if rule == "refuse":
            raise ScriptError(f"replicate cannot copy the per-particle values {name} a style keeps (a rigid "
                              "body's members, a particle's earlier position: copies must not share them); "
                              "replicate before defining the styles that keep them, or before the run that "
                              "made them")
        if rule == "contacts":
            open_contacts = int(sim.comm.sum(int((p.arrays[name][:p.nlocal] >= 0).sum())))
            if open_contacts:
                raise ScriptError(f"replicate cannot copy contacts ({name}: {open_contacts} open): a copy's "
                                  "partners are other copies; replicate before the first run")


def _refuse_lost(sim):
    """LAMMPS's replicate gives no processor the copies of a particle outside a non-periodic face
    ("Replicate did not assign all atoms correctly"): refused, naming the first such particle."""
    p, box = sim.particles, sim.box
    x = p.x[:p.nlocal]
    outside = np.zeros(len(x), dtype=bool)
    for d in range(3):
        if not box.periodic[d]:
            outside |= (x[:, d] < box.lo[d]) | (x[:, d] > box.hi[d])
    found = None
    if outside.any():
        i = int(np.flatnonzero(outside)[0])
        d = next(d for d in range(3) if not box.periodic[d] and not box.lo[d] <= x[i, d] <= box.hi[d])
        found = (f"particle {int(p.tag[i])} lies outside the box's non-periodic {'xyz'[d]} faces ({'xyz'[d]} = "
                 f"{x[i, d]:g} outside [{box.lo[d]:g}, {box.hi[d]:g}]): replicate copies particles in the box "
                 "(LAMMPS's refuses so too)")
    sim.comm.agree(found)


def _cells(counts, liggghts):
    """(ix, iy, iz) of each copy in the order they are made, and the multiple of the largest id its
    ids add: LAMMPS's counts x fastest, LIGGGHTS's z fastest."""
    nx, ny, nz = (int(c) for c in counts)
    ix, iy, iz = (a.ravel() for a in np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij"))
    multiple = (ix * ny + iy) * nz + iz if liggghts else (iz * ny + iy) * nx + ix
    return np.column_stack([ix, iy, iz]), multiple.astype(np.int64)


def _copied(p, count):
    """Every owned per-particle array, its rows repeated ``count`` times (copy after copy)."""
    n = p.nlocal
    return {name: np.tile(p.arrays[name][:n], (count,) + (1,) * (p.arrays[name].ndim - 1))
            for name in p.properties}


def _lammps_copies(sim, counts, largest, largest_molecule):
    p, box = sim.particles, sim.box
    n = p.nlocal
    values = _copied(p, int(np.prod(counts)) if n else 0)
    if n == 0:
        return values
    cells, multiple = _cells(counts, liggghts=False)
    unwrapped = p.x[:n] + p.image[:n] * box.length
    values["x"] = np.tile(unwrapped, (len(cells), 1)) + np.repeat(cells * box.length, n, axis=0)
    values["image"][:] = 0
    values["tag"] += np.repeat(multiple * largest, n)
    if "molecule" in values:
        molecule = values["molecule"]
        molecule += np.where(molecule > 0, np.repeat(multiple * largest_molecule, n), 0)
    return values


def _liggghts_copies(sim, counts, offset, shift, largest):
    p = sim.particles
    n = p.nlocal
    values = _copied(p, int(np.prod(counts)) if n else 0)
    if n == 0:
        return values
    cells, multiple = _cells(counts, liggghts=True)
    values["x"] += shift + np.repeat(cells * offset, n, axis=0)
    values["tag"] += np.repeat(multiple * largest, n)
    return values


def _wrap_copies(sim, values, lo, hi):
    """LAMMPS's copies into the new box along its periodic axes, their image flags counting."""
    shifts = np.zeros((len(values["x"]), 3), dtype=np.int64)
    remap(values["x"], shifts, lo, hi, np.asarray(sim.box.periodic, dtype=np.bool_))
    if sim.comm.sum(int(np.abs(shifts).max(initial=0) > limits.MAX_IMAGE)):
        raise ScriptError(f"replicate puts particles more than {limits.MAX_IMAGE} box lengths from the box")
    values["image"][:] = shifts
