"""``create_atoms``, LAMMPS's command (PDPS's is create_particle, commands/particles.py).

    create_atoms TYPE box|region REGION-ID|single X Y Z|random N SEED REGION-ID|NULL [keyword value]...

keywords: ``units box|lattice`` (of ``single``'s X Y Z; default lattice, as LAMMPS; box, as LIGGGHTS 3.8.0), ``remap yes|no``
(``single`` outside a periodic box is wrapped in), ``overlap D`` and ``maxtry N`` (``random``),
``basis M ITYPE`` (the type of basis atom M). Sphere styles get diameter 1 and density 1 (LAMMPS's
defaults for created spheres).

Lattice sites are those of the lattice command: integer cells from the origin (not from the box or
region corner), each with the lattice's basis, kept when inside the box as LAMMPS keeps them (a site
on a periodic box's upper face is the image of the one on its lower face, and is not created twice;
LAMMPS shifts both faces down by 1e-6 of the box length; a shrink-wrapped face without minimum, s,
moves out by that much, so that sites on it are made, as LAMMPS 22 Jul 2025 makes them: an fcc block
of 3 cells makes 108 sites with p or f or m along x, 126 with s) and, for ``region``, inside the region
(its ``side`` counted).

``random N SEED REGION`` in the LAMMPS dialect places the particles LAMMPS (22 Jul 2025) places, on
any number of ranks: its Park-Miller generator seeded with SEED and warmed up by 30 uniforms draws
x, y, z (three uniforms per try, z then set to the box's middle in 2-d) in the box, narrowed to the
region's extent when the region is an inside one; a try counts when the region matches it and, with
``overlap D``, no particle (the existing ones, of every rank, and the ones placed so far) is closer
than D (minimum image across periodic faces; D in lattice spacings with ``units lattice``, the
default); each particle gets at most ``maxtry`` tries (default 1000), after which it is skipped and
LAMMPS's ``WARNING: Only inserted M particles out of N`` follows. Every rank draws the same stream
and all keep the same particles, so ids and positions do not depend on the rank count. (No EPSILON
shift of the faces here: LAMMPS applies it to lattice sites only.) The overlap test looks only at
the cells (at least D wide) around a try, which finds every particle LAMMPS's loop over all would.
After ``MAX_DRAWS`` tries in all pdps stops with an error where LAMMPS would run on (a region too
full for N particles and a huge maxtry). In the PDPS dialect ``random``
keeps pdps's own generator (N particles, ``maxtry`` misses in a row per particle before an error).
"""

import math

import numpy as np
from numba import njit

from ..errors import ScriptError
from ..random_park import MAX_SEED, park_state, park_uniform
from ..state import limits
from . import command
from .particles import _random_no_overlap, _sphere_values
from .words import choice, integer, number, yes_no

EPSILON = 1e-6      # LAMMPS's create_atoms: faces shifted by this fraction of the box length
WARMUP_RANDOM = 30  # LAMMPS's create_atoms random: uniforms discarded after seeding
MAXTRY = {"lammps": 1000, "liggghts": 1000, "pdps": 100}
MAX_DRAWS = 20_000_000      # tries in all before create_atoms random stops instead of running on
MAX_GRID_CELLS = 2 ** 21    # overlap test: wider cells beyond this many (still correct, only slower)


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
    options = _options(args[2 + positional:], usage, sim.ntypes, sim.dialect.command_units)
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
        sim.particles.check_room(n)
        region = None if rest[2] == "NULL" else sim.region(rest[2])
        maxtry = options["maxtry"] or MAXTRY[sim.dialect.name]
        if sim.dialect.name in ("lammps", "liggghts"):
            seed = integer(rest[1], "seed", low=1, high=MAX_SEED)
            overlap = options["overlap"] * (_lattice_scale(sim)[0] if options["units"] == "lattice" else 1.0)
            x = lammps_random(sim, n, seed, region, overlap, maxtry)
        else:
            seed = integer(rest[1], "seed", low=1)
            x = _random_no_overlap(sim, n, region if region is not None else _WholeBox(sim), options["overlap"],
                                   seed, max_misses=maxtry * max(n, 1))
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


def _options(words, usage, ntypes, units):
    options = {"units": units, "remap": False, "overlap": 0.0, "maxtry": None, "basis": {}}
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


def lammps_random(sim, n, seed, region, overlap, maxtry):
    """The positions LAMMPS's create_atoms random creates (module docstring), in creation order."""
    box = sim.box
    lo, hi = box.lo.copy(), box.hi.copy()
    zmid = lo[2] + 0.5 * (hi[2] - lo[2])
    if region is not None and not region.side_out:
        try:
            rlo, rhi = region.extent()
            lo, hi = np.maximum(lo, rlo), np.minimum(hi, rhi)
        except ScriptError:
            pass        # a region with no extent (a plane, a union with an outside part): the whole box
    if np.any(lo > hi):
        raise ScriptError(f"region {region.id} does not overlap the box (LAMMPS: no overlap of box and region)")
    state = park_state(seed)
    for _ in range(WARMUP_RANDOM):
        park_uniform(state)
    flat = sim.dimension == 2
    owned = np.ascontiguousarray(sim.particles.x[:sim.particles.nlocal])
    existing = np.ascontiguousarray(sim.comm.allgather_rows(owned), dtype=np.float64).reshape(-1, 3)
    check = overlap > 0.0
    ncell = _grid_shape(box.length, overlap if check else 0.0, flat)
    points = np.empty((len(existing) + n, 3))
    link = np.full(len(existing) + n, -1, dtype=np.int64)
    head = np.full(int(np.prod(ncell)), -1, dtype=np.int64)
    periodic = np.asarray(box.periodic, dtype=np.bool_)
    length = np.asarray(box.length, dtype=np.float64)
    inserted = np.empty((n, 3))
    created = np.zeros(n, dtype=np.bool_)
    # atom being placed, its tries so far, particles inserted, points in the grid, draws in all
    progress = np.zeros(5, dtype=np.int64)
    for point in existing:
        _grid_add(point, progress, points, link, head, box.lo, length, ncell)
    span = hi - lo
    batch = int(min(max(2 * n, 64), 1 << 16))
    while progress[0] < n:
        if progress[4] >= MAX_DRAWS:
            raise ScriptError(f"random: {progress[2]} of {n} particles placed after {MAX_DRAWS} tries (maxtry "
                              f"{maxtry} each); ask for fewer particles, a smaller overlap or a smaller maxtry")
        candidates = _draw(state, batch, lo, span, zmid, flat)
        usable = (np.ones(batch, dtype=np.bool_) if region is None
                  else np.asarray(region.match(candidates), dtype=np.bool_))
        _place(candidates, usable, progress, n, maxtry, overlap * overlap, check, box.lo, box.hi, periodic, length,
               ncell, head, link, points, inserted, created)
        batch = min(2 * batch, 1 << 16)
    if progress[2] < n:
        sim.warn(f"Only inserted {progress[2]} particles out of {n}")
    return inserted[:progress[2]][created[:progress[2]]]


def _grid_shape(length, reach, flat):
    """Cells per axis for the overlap test: at least ``reach`` wide, so a particle closer than reach
    to a try is in the try's cell or a neighbouring one."""
    if reach <= 0.0:
        return np.ones(3, dtype=np.int64)
    ncell = [max(1, int(min(L / reach, MAX_GRID_CELLS))) for L in length]
    if flat:
        ncell[2] = 1
    while math.prod(ncell) > MAX_GRID_CELLS:
        widest = ncell.index(max(ncell))
        ncell[widest] //= 2
    return np.array(ncell, dtype=np.int64)


@njit(cache=True)
def _draw(state, count, lo, span, zmid, flat):
    out = np.empty((count, 3))
    for k in range(count):
        for d in range(3):
            out[k, d] = lo[d] + park_uniform(state) * span[d]
        if flat:
            out[k, 2] = zmid
    return out


@njit(cache=True)
def _cell(point, box_lo, length, ncell):
    index = 0
    for d in range(3):
        c = int(np.floor((point[d] - box_lo[d]) / length[d] * ncell[d]))
        c = min(max(c, 0), ncell[d] - 1)
        index = index * ncell[d] + c
    return index


@njit(cache=True)
def _grid_add(point, progress, points, link, head, box_lo, length, ncell):
    k = progress[3]
    points[k] = point
    cell = _cell(point, box_lo, length, ncell)
    link[k] = head[cell]
    head[cell] = k
    progress[3] = k + 1


@njit(cache=True)
def _minimum_image(delta, periodic, length):
    # LAMMPS's Domain::minimum_image for an orthogonal box
    if periodic:
        while abs(delta) > 0.5 * length:
            if delta < 0.0:
                delta += length
            else:
                delta -= length
    return delta


@njit(cache=True)
def _cell_range(x, box_lo, periodic, length, ncell):
    """The first and last cell (unwrapped) around x along one axis, each cell once: a periodic axis of
    one or two cells wraps onto itself."""
    home = min(max(int(np.floor((x - box_lo) / length * ncell)), 0), ncell - 1)
    if periodic:
        if ncell == 1:
            return home, home
        if ncell == 2:
            return home - 1, home
        return home - 1, home + 1
    return max(home - 1, 0), min(home + 1, ncell - 1)


@njit(cache=True)
def _wrap(c, n):
    if c < 0:
        return c + n
    if c >= n:
        return c - n
    return c


@njit(cache=True)
def _place(candidates, usable, progress, n, maxtry, odist_sq, check, box_lo, box_hi, periodic, length, ncell, head,
           link, points, inserted, created):
    """Walk the tries in the order drawn, as LAMMPS's add_random: each particle takes tries until one
    passes (region, overlap) or maxtry have failed; an inserted particle outside [lo, hi) (a try
    rounded onto the upper face) is counted but created on no rank."""
    for k in range(len(candidates)):
        if progress[0] >= n:
            return
        progress[1] += 1
        progress[4] += 1
        ok = usable[k]
        if ok and check:
            # LAMMPS's overlap test: a point at a minimum-image distance below the overlap distance
            px, py, pz = candidates[k, 0], candidates[k, 1], candidates[k, 2]
            x0, x1 = _cell_range(px, box_lo[0], periodic[0], length[0], ncell[0])
            y0, y1 = _cell_range(py, box_lo[1], periodic[1], length[1], ncell[1])
            z0, z1 = _cell_range(pz, box_lo[2], periodic[2], length[2], ncell[2])
            for cx in range(x0, x1 + 1):
                for cy in range(y0, y1 + 1):
                    for cz in range(z0, z1 + 1):
                        cell = (_wrap(cx, ncell[0]) * ncell[1] + _wrap(cy, ncell[1])) * ncell[2] + _wrap(cz, ncell[2])
                        j = head[cell]
                        while ok and j >= 0:
                            dx = _minimum_image(px - points[j, 0], periodic[0], length[0])
                            dy = _minimum_image(py - points[j, 1], periodic[1], length[1])
                            dz = _minimum_image(pz - points[j, 2], periodic[2], length[2])
                            ok = dx * dx + dy * dy + dz * dz >= odist_sq
                            j = link[j]
        if ok:
            m = progress[2]
            inside = True
            for d in range(3):
                inserted[m, d] = candidates[k, d]
                if candidates[k, d] < box_lo[d] or candidates[k, d] >= box_hi[d]:
                    inside = False
            created[m] = inside
            if inside:
                _grid_add(inserted[m], progress, points, link, head, box_lo, length, ncell)
            progress[2] = m + 1
        if ok or progress[1] >= maxtry:
            progress[0] += 1
            progress[1] = 0


def _lattice_scale(sim):
    return np.ones(3) if sim.lattice is None else np.asarray(sim.lattice.spacing, dtype=np.float64)


CHUNK_SITES = 1_000_000     # lattice sites made at once by create_atoms


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
    # the box faces as LAMMPS shifts them (periodic: the lower one down, the upper one down twice;
    # shrink-wrapped without a minimum, s: the lower one down, the upper one up twice, so that sites
    # on them are made and the box wraps around them; fixed and m: where they are)
    eps = EPSILON * box.length
    shrink_lo = np.array([word[0] == "s" for word in sim.system.periodicity])
    shrink_hi = np.array([word[-1] == "s" for word in sim.system.periodicity])
    face_lo = box.lo - np.where(box.periodic | shrink_lo, eps, 0.0)
    face_hi = box.hi - np.where(box.periodic, 2.0 * eps, 0.0) + np.where(shrink_hi, 2.0 * eps, 0.0)
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
    dims = sim.dimension
    if region is None:
        # the box holds its volume over a cell's, times the basis, up to a layer at the faces
        cell = lattice.cell[:dims, :dims]
        filled = float(np.prod(box.length[:dims])) / abs(float(np.linalg.det(cell))) * len(lattice.basis)
        if filled > 1.01 * limits.MAX_CREATE:
            raise ScriptError(f"the lattice has about {filled:.3g} sites in the box, more particles than one "
                              f"command makes ({limits.MAX_CREATE})")
    axes = [np.arange(first[d], last[d] + 1) for d in range(3)]
    # LAMMPS's loop order (z outermost, then y, x, basis innermost), so ids follow LAMMPS's; a few
    # z layers at a time, so that a lattice too large for one command stops once it is known to be
    layers = max(1, int(CHUNK_SITES // (len(axes[0]) * len(axes[1]) * len(lattice.basis))))
    chunks, kept = [], 0
    for start in range(0, len(axes[2]), layers):
        k, j, i = np.meshgrid(axes[2][start:start + layers], axes[1], axes[0], indexing="ij")
        cells = np.column_stack([i.ravel(), j.ravel(), k.ravel()])
        x = lattice.sites(cells)
        which = np.tile(np.arange(len(lattice.basis)), len(cells))
        if dims == 2:
            x[:, 2] = 0.0
        inside = np.all((x[:, :dims] >= face_lo[:dims]) & (x[:, :dims] < face_hi[:dims]), axis=1)
        x, which = x[inside], which[inside]
        if region is not None:
            keep = region.match(x)
            x, which = x[keep], which[keep]
        kept += len(x)
        if kept > limits.MAX_CREATE:
            where = "the box" if region is None else "region " + region.id
            raise ScriptError(f"the lattice has more than {limits.MAX_CREATE} sites in {where}, more "
                              "particles than one command makes")
        chunks.append((x, which))
    x = np.concatenate([c[0] for c in chunks]) if chunks else np.zeros((0, 3))
    which = np.concatenate([c[1] for c in chunks]) if chunks else np.zeros(0, dtype=np.int64)
    return x, which


def _add(sim, x, types):
    p = sim.particles
    extra = _sphere_values(sim, {})
    start = p.nlocal
    if len(x):
        p.add(x, int(types[0]), **extra)
        p.type[start:p.nlocal] = types
        if extra and sim.dialect.name == "pdps":
            # the mass command's type masses hold for PDPS spheres (particles.mass)
            masses = sim.mass[p.type[start:p.nlocal]]
            p.rmass[start:p.nlocal] = np.where(masses > 0, masses, p.rmass[start:p.nlocal])
    sim.comm.distribute(p, sim.box)
    sim.groups.update(sim)
    sim.output.message(f"Created {len(x)} atoms")

