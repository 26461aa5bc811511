"""``create_atoms``, LAMMPS's command (PDPS's is create_particle, commands/particles.py).

    create_atoms TYPE box|region REGION-ID|single X Y Z|random N SEED REGION-ID|NULL [keyword value]...

keywords: ``units box|lattice`` (of ``single``'s X Y Z; default lattice, as LAMMPS), ``remap yes|no``
(``single`` outside a periodic box is wrapped in), ``overlap D`` and ``maxtry N`` (``random``),
``basis M ITYPE`` (the type of basis atom M). Sphere styles get diameter 1 and density 1 (LAMMPS's
defaults for created spheres).

Lattice sites are those of the lattice command: integer cells from the origin (not from the box or
region corner), each with the lattice's basis, kept when inside the box as LAMMPS keeps them (a site
on a periodic box's upper face is the image of the one on its lower face, and is not created twice;
LAMMPS shifts both faces down by 1e-6 of the box length) and, for ``region``, inside the region (its
``side`` counted).

``random`` draws uniform positions in the box (inside the region when one is given) from pdps's own
generator: not LAMMPS's numbers (docs/lammps.md).
"""

import numpy as np

from ..errors import ScriptError
from ..state import limits
from . import command
from .particles import _random_no_overlap, _sphere_values
from .words import choice, integer, number, yes_no

EPSILON = 1e-6      # LAMMPS's create_atoms: faces shifted by this fraction of the box length


@command("create_atoms")
def create_atoms(sim, args):
    usage = ("create_atoms TYPE box|region REGION-ID|single X Y Z|random N SEED REGION-ID|NULL "
             "[units box|lattice] [remap yes|no] [overlap D] [maxtry N] [basis M ITYPE]")
    sim.require_box("create_atoms")
    if len(args) < 2:
        raise ScriptError(f"expected a type and a style; usage: {usage}")
    ptype = integer(args[0], "type", low=1, high=sim.ntypes)
    style = choice(args[1], "create_atoms style", ("box", "region", "single", "random"))
    positional = {"box": 0, "region": 1, "single": 3, "random": 3}[style]
    rest = args[2:2 + positional]
    if len(rest) < positional:
        raise ScriptError(f"create_atoms {style} needs {positional} argument(s); usage: {usage}")
    options = _options(args[2 + positional:], usage, sim.ntypes)
    if style in ("box", "region"):
        region = sim.region(rest[0]) if style == "region" else None
        x, basis_index = lattice_sites(sim, region)
        types = np.full(len(x), ptype, dtype=np.int64)
        for m, btype in options["basis"].items():
            if m > int(basis_index.max(initial=0)) + 1:
                raise ScriptError(f"basis {m}: the lattice has {int(basis_index.max(initial=0)) + 1} basis atoms")
            types[basis_index == m - 1] = btype
    elif style == "single":
        scale = _lattice_scale(sim) if options["units"] == "lattice" else np.ones(3)
        x = np.array([[number(w, a) for a, w in zip("xyz", rest)]]) * scale
        if sim.dimension == 2:
            x[:, 2] = 0.0
        if options["remap"]:
            box = sim.box
            for d in range(3):
                if box.periodic[d]:
                    x[:, d] = box.lo[d] + np.mod(x[:, d] - box.lo[d], box.length[d])
        if not sim.box.inside(x).all():
            raise ScriptError(f"position {' '.join(rest)} is outside the box (remap yes wraps it in "
                              "across periodic faces)")
        types = np.full(1, ptype, dtype=np.int64)
    else:
        n = integer(rest[0], "N", low=0, high=limits.MAX_CREATE)
        seed = integer(rest[1], "seed", low=1)
        region = None if rest[2] == "NULL" else sim.region(rest[2])
        x = _random_no_overlap(sim, n, region if region is not None else _WholeBox(sim), options["overlap"], seed,
                               max_misses=options["maxtry"] * max(n, 1))
        types = np.full(len(x), ptype, dtype=np.int64)
    _add(sim, x, types)


class _WholeBox:
    """The box as a region, for create_atoms random ... NULL."""

    def __init__(self, sim):
        self.sim, self.id = sim, "NULL"

    def bounds(self):
        return self.sim.box.lo, self.sim.box.hi

    def match(self, x):
        return np.ones(len(x), dtype=bool)


def _options(words, usage, ntypes):
    options = {"units": "lattice", "remap": False, "overlap": 0.0, "maxtry": 100, "basis": {}}
    k = 0
    while k < len(words):
        key = words[k]
        if key == "basis":
            if k + 2 >= len(words):
                raise ScriptError(f"basis needs M ITYPE; usage: {usage}")
            options["basis"][integer(words[k + 1], "basis M", low=1)] = integer(words[k + 2], "basis type",
                                                                               low=1, high=ntypes)
            k += 3
            continue
        if k + 1 >= len(words):
            raise ScriptError(f"keyword {key} needs a value; usage: {usage}")
        value = words[k + 1]
        if key == "units":
            options["units"] = choice(value, "units", ("box", "lattice"))
        elif key == "remap":
            options["remap"] = yes_no(value, "remap")
        elif key == "overlap":
            options["overlap"] = number(value, "overlap", low=0.0)
        elif key == "maxtry":
            options["maxtry"] = integer(value, "maxtry", low=1, high=10 ** 6)
        elif key in ("mol", "ratio", "subset", "var", "set", "rotate", "mesh", "radscale", "meshmode"):
            raise ScriptError(f"create_atoms keyword {key} is not supported (supported: units, remap, "
                              "overlap, maxtry, basis)")
        else:
            raise ScriptError(f"unknown create_atoms keyword {key}; usage: {usage}")
        k += 2
    return options


def _lattice_scale(sim):
    return np.ones(3) if sim.lattice is None else np.asarray(sim.lattice.spacing, dtype=np.float64)


def lattice_sites(sim, region=None):
    """Sites of the lattice inside the box (and ``region``), as LAMMPS's create_atoms finds them;
    returns (positions, index of each site's basis atom)."""
    lattice = sim.lattice
    if lattice is None or len(lattice.basis) == 0:
        raise ScriptError("create_atoms box|region needs a lattice (lattice sc|bcc|fcc|... first)")
    box = sim.box
    lo, hi = box.lo.copy(), box.hi.copy()
    if region is not None and not region.side_out:
        try:
            rlo, rhi = region.bounds()
            lo, hi = np.maximum(lo, rlo), np.minimum(hi, rhi)
        except ScriptError:
            pass        # a region with no extent: the box's sites, tested one by one
    # the box faces as LAMMPS shifts them (periodic: the lower one down, the upper one down twice)
    eps = EPSILON * box.length
    face_lo = box.lo - np.where(box.periodic, eps, 0.0)
    face_hi = box.hi - np.where(box.periodic, 2.0 * eps, 0.0)
    # the cells whose sites may fall in [lo, hi]: the corners' cell coordinates, widened by one
    corners = np.array([[(lo, hi)[i][0], (lo, hi)[j][1], (lo, hi)[k][2]]
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)])
    fractions = lattice.fractions(corners)
    first = np.floor(fractions.min(axis=0)) - 1
    last = np.ceil(fractions.max(axis=0)) + 1
    if sim.dimension == 2:
        first[2] = last[2] = 0
    sites = float(np.prod(last - first + 1)) * len(lattice.basis)
    if not sites <= 4 * limits.MAX_CREATE:
        raise ScriptError(f"the lattice (spacing {' '.join(f'{a:g}' for a in lattice.spacing)}) has about "
                          f"{sites:.3g} sites in {'the box' if region is None else 'region ' + region.id}, more "
                          f"than {limits.MAX_CREATE} particles at once")
    axes = [np.arange(first[d], last[d] + 1) for d in range(3)]
    # LAMMPS's loop order (z outermost, then y, x, basis innermost), so ids follow LAMMPS's
    k, j, i = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    cells = np.column_stack([i.ravel(), j.ravel(), k.ravel()])
    x = lattice.sites(cells)
    which = np.tile(np.arange(len(lattice.basis)), len(cells))
    dims = sim.dimension
    if dims == 2:
        x[:, 2] = 0.0
    inside = np.all((x[:, :dims] >= face_lo[:dims]) & (x[:, :dims] < face_hi[:dims]), axis=1)
    x, which = x[inside], which[inside]
    if region is not None:
        keep = region.match(x)
        x, which = x[keep], which[keep]
    if len(x) > limits.MAX_CREATE:
        raise ScriptError(f"create_atoms would make {len(x)} particles, more than {limits.MAX_CREATE} at once")
    return x, which


def _add(sim, x, types):
    p = sim.particles
    extra = _sphere_values(sim, {})
    start = p.nlocal
    if len(x):
        p.add(x, int(types[0]), **extra)
        p.type[start:p.nlocal] = types
    sim.comm.distribute(p, sim.box)
    sim.groups.update(sim)
    sim.output.message(f"Created {len(x)} atoms")

