"""Particle commands: create_particle (PDPS; LAMMPS's create_atoms is in create_atoms.py), read_data,
mass, group (velocity is in velocity.py)."""

import math

import numpy as np
from numba import njit

from ..errors import ScriptError
from ..state import limits
from . import COMMANDS, command
from .geometry import make_box
from .words import choice, count, integer, number, type_range

SPHERE_KEYWORDS = ("diameter", "density")


def _sphere_values(sim, keywords, ptype=None):
    """Per-particle radius and rmass for particle_style sphere (diameter 1, density 1 by default);
    in the PDPS dialect a mass the mass command gave type ``ptype`` holds instead of the density's."""
    if "sphere" not in sim.particle_styles:
        if keywords:
            raise ScriptError(f"{next(iter(keywords))} needs particle_style sphere")
        return {}
    diameter = keywords.get("diameter", 1.0)
    density = keywords.get("density", 1.0)
    radius = 0.5 * diameter
    rmass = density * sphere_volume(sim, radius)
    type_mass = sim.mass[ptype] if ptype is not None else 0.0
    if type_mass > 0:
        if "density" in keywords:
            raise ScriptError(f"type {ptype} has mass {type_mass:g} (mass command), which a density would "
                              "replace: give the mass or the density, not both")
        rmass = float(type_mass)
    return {"radius": radius, "rmass": rmass}


def _split_keywords(args, names):
    """Trailing ``name value`` pairs for the given names -> (rest, {name: float})."""
    values, rest, i = {}, [], 0
    while i < len(args):
        if args[i] in names:
            if i + 1 >= len(args):
                raise ScriptError(f"keyword {args[i]} needs a value")
            values[args[i]] = number(args[i + 1], args[i], low=limits.MIN_SIZE, high=limits.MAX_SIZE)
            i += 2
        else:
            rest.append(args[i])
            i += 1
    return rest, values


@command("create_particle")
def create_particle(sim, args):
    usage = ("create_particle TYPE single X Y Z | spacing REGION | region REGION | box | "
             "random_no_overlap N REGION MIN_DISTANCE SEED  [diameter D] [density RHO]")
    sim.require_box("create_particle")
    args, keywords = _split_keywords(args, SPHERE_KEYWORDS)
    if len(args) < 2:
        raise ScriptError(f"expected a type and a style; usage: {usage}")
    ptype = integer(args[0], "type", low=1, high=sim.ntypes)
    style = choice(args[1], "create_particle style",
                   ("single", "spacing", "region", "box", "random_no_overlap", "random"))
    rest = args[2:]
    if style == "single":
        count(rest, 3, usage)
        x = np.array([[number(w, f"{a}") for a, w in zip("xyz", rest)]])
        if sim.dimension == 2:
            x[:, 2] = 0.0
        if not sim.box.inside(x).all():
            raise ScriptError(f"position {' '.join(rest)} is outside the box")
    elif style in ("spacing", "region", "box"):
        if style == "box":
            count(rest, 0, usage)
            region = None
        else:
            count(rest, 1, usage)
            region = sim.region(rest[0])
        x = _lattice_sites(sim, region)
    else:
        if style == "random_no_overlap":
            count(rest, 4, usage)
            n = integer(rest[0], "N", low=0, high=limits.MAX_CREATE)
            region = sim.region(rest[1])
            dmin = number(rest[2], "minimum distance", low=0.0)
            seed = integer(rest[3], "seed", low=1)
        else:  # LAMMPS: random N SEED REGION [overlap D]
            if len(rest) not in (3, 5) or (len(rest) == 5 and rest[3] != "overlap"):
                raise ScriptError("usage: create_particle TYPE random N SEED REGION [overlap D]")
            n = integer(rest[0], "N", low=0, high=limits.MAX_CREATE)
            seed = integer(rest[1], "seed", low=1)
            region = sim.region(rest[2])
            dmin = number(rest[4], "overlap", low=0.0) if len(rest) == 5 else 0.0
        sim.particles.check_room(n)
        x = _random_no_overlap(sim, n, region, dmin, seed)
    sim.particles.add(x, ptype, **_sphere_values(sim, keywords, ptype))
    sim.comm.distribute(sim.particles, sim.box)
    sim.groups.update(sim)
    sim.output.message(f"Created {len(x)} particles")


def _lattice_sites(sim, region):
    if sim.lattice is None:
        raise ScriptError("creating particles on a lattice needs a lattice command first")
    spacing, basis = sim.lattice.spacing, sim.lattice.basis
    box = sim.box
    lo, hi = (box.lo, box.hi) if region is None or region.side_out else region.bounds()
    lo, hi = np.maximum(lo, box.lo), np.minimum(hi, box.hi)
    counts = [1 if (sim.dimension == 2 and d == 2) else (hi[d] - lo[d]) / spacing[d] + 2 for d in range(3)]
    sites = math.prod(counts) * len(basis)
    if not sites <= limits.MAX_CREATE:
        raise ScriptError(f"the lattice (spacing {' '.join(f'{a:g}' for a in spacing)}) fills "
                          f"{'the box' if region is None else 'region ' + region.id} with about {sites:.3g} "
                          f"sites, more than {limits.MAX_CREATE} particles at once")
    axes = []
    for d in range(3):
        if sim.dimension == 2 and d == 2:
            axes.append(np.zeros(1))
            continue
        n = int(math.ceil((hi[d] - lo[d]) / spacing[d] - 1e-9)) + 1
        axes.append(np.arange(n) * spacing[d])
    cells = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
    sites = (cells[:, None, :] + basis[None, :, :] * spacing).reshape(-1, 3) + lo * [1, 1, sim.dimension == 3]
    tolerance = 1e-9 * spacing
    keep = np.all((sites >= lo - tolerance) & (sites < hi - tolerance), axis=1)
    sites = sites[keep]
    if region is not None:
        sites = sites[region.match(sites)]
    return sites[box.inside(sites)]


def _random_no_overlap(sim, n, region, dmin, seed, max_misses=10000, batch=256):
    """Random positions in ``region``, none closer than dmin to another (periodic images counted).

    Candidates come from numpy's generator 256 at a time; each is checked, in order, against the
    particles already there and those placed before it by ``_place_free``, which looks only at the
    3^d grid cells (at least dmin wide) around it. After ``max_misses`` rejected candidates in a row
    the region counts as too full: an error, never a hang."""
    rng = np.random.default_rng(seed)
    box = sim.box
    lo, hi = (box.lo, box.hi) if getattr(region, "side_out", False) else region.bounds()
    lo, hi = np.maximum(lo, box.lo), np.minimum(hi, box.hi)
    dims = sim.dimension
    # every rank places the same particles: each must see all existing ones, not only its own
    existing = np.ascontiguousarray(sim.comm.allgather_rows(sim.particles.x[: sim.particles.nlocal]),
                                    dtype=np.float64).reshape(-1, 3)
    total = len(existing) + n
    points = np.zeros((total, 3))
    points[: len(existing)] = existing
    # capped so cell indices stay small; a capped cell is still wider than dmin
    ncell = np.ones(3, dtype=np.int64)
    if dmin > 0:
        ncell[:dims] = [max(1, int(min(L / dmin, 2 ** 20))) for L in box.length[:dims]]
    # cells are found by a hash of their indices, in a table twice the particles' number: a grid of
    # an absurd box costs no memory, and two cells in one bucket only cost a few more distance checks
    buckets = 1 << max(6, int(2 * total).bit_length())
    head = np.full(buckets, -1, dtype=np.int64)
    chain = np.full(total, -1, dtype=np.int64)
    periodic = np.array(box.periodic, dtype=np.bool_)
    geometry = (box.lo.astype(np.float64), box.length.astype(np.float64), periodic, ncell, dims)
    for i in range(len(existing)):
        _file_in_cell(points, i, head, chain, *geometry[:4])
    placed, misses = len(existing), 0
    while placed < total:
        candidates = lo + rng.random((batch, 3)) * (hi - lo)
        if dims == 2:
            candidates[:, 2] = 0.0
        usable = region.match(candidates) & box.inside(candidates)
        placed, misses = _place_free(candidates, usable, points, placed, head, chain, *geometry,
                                     dmin * dmin, misses, max_misses)
        if misses >= max_misses:
            raise ScriptError(f"placed only {placed - len(existing)} of {n} particles in region "
                              f"{region.id} without overlap: {max_misses} random tries in a row failed "
                              f"(minimum distance {dmin:g}); the region is too full")
    return points[len(existing):].copy()


@njit(cache=True)
def _cell_index(p, origin, length, periodic, ncell, d):
    c = np.int64(np.floor((p - origin[d]) / length[d] * ncell[d]))
    if periodic[d]:
        return c % ncell[d]
    return min(max(c, 0), ncell[d] - 1)


@njit(cache=True)
def _bucket(cx, cy, cz, buckets):
    return ((cx * 73856093) ^ (cy * 19349663) ^ (cz * 83492791)) & (buckets - 1)


@njit(cache=True)
def _file_in_cell(points, i, head, chain, origin, length, periodic, ncell):
    cx = _cell_index(points[i, 0], origin, length, periodic, ncell, 0)
    cy = _cell_index(points[i, 1], origin, length, periodic, ncell, 1)
    cz = _cell_index(points[i, 2], origin, length, periodic, ncell, 2)
    b = _bucket(cx, cy, cz, len(head))
    chain[i] = head[b]
    head[b] = i


@njit(cache=True)
def _neighbour_range(c, m, periodic):
    """The cell indices next to ``c`` along one axis of ``m`` cells, each once: (first, count)."""
    if periodic:
        if m < 3:
            return 0, m
        return c - 1, 3
    first = max(c - 1, 0)
    return first, min(c + 1, m - 1) - first + 1


@njit(cache=True)
def _place_free(candidates, usable, points, placed, head, chain, origin, length, periodic, ncell,
                dims, dmin_sq, misses, max_misses):
    """Takes the usable candidates that keep dmin from every point so far, in order, into
    ``points[placed:]`` until it is full or ``max_misses`` tries in a row failed: (placed, misses)."""
    buckets = len(head)
    cell = np.zeros(3, dtype=np.int64)
    first = np.zeros(3, dtype=np.int64)
    span = np.ones(3, dtype=np.int64)
    for k in range(len(candidates)):
        if placed == len(points):
            break
        free = usable[k]
        if free and dmin_sq > 0.0:
            for d in range(3):
                cell[d] = _cell_index(candidates[k, d], origin, length, periodic, ncell, d)
                first[d], span[d] = _neighbour_range(cell[d], ncell[d], periodic[d])
            for ix in range(span[0]):
                for iy in range(span[1]):
                    for iz in range(span[2]):
                        cx = (first[0] + ix) % ncell[0]
                        cy = (first[1] + iy) % ncell[1]
                        cz = (first[2] + iz) % ncell[2]
                        j = head[_bucket(cx, cy, cz, buckets)]
                        while j >= 0 and free:
                            r_sq = 0.0
                            for d in range(dims):
                                delta = candidates[k, d] - points[j, d]
                                if periodic[d]:
                                    delta -= length[d] * np.rint(delta / length[d])
                                r_sq += delta * delta
                            if r_sq < dmin_sq:
                                free = False
                            j = chain[j]
        if free:
            points[placed] = candidates[k]
            _file_in_cell(points, placed, head, chain, origin, length, periodic, ncell)
            placed += 1
            misses = 0
        else:
            misses += 1
            if misses >= max_misses:
                break
    return placed, misses


def sphere_volume(sim, radius):
    """What a sphere's density multiplies to give its mass, in LAMMPS's order of operations
    (4 pi / 3 r r r), so masses agree with LAMMPS's to the last bit. In 2-d the dialect decides:
    LAMMPS keeps the sphere's volume (create_atoms, read_data, set density and diameter), LIGGGHTS
    and PDPS take the disc's area pi r r."""
    radius = np.asarray(radius, dtype=float) if np.ndim(radius) else float(radius)
    if sim.dimension == 2 and sim.dialect.volume_2d == "disc":
        return math.pi * radius * radius
    return 4.0 * math.pi / 3.0 * radius * radius * radius


def _data_mass(sim, radius, density):
    """A data file's sphere mass from its radius and density."""
    return sphere_volume(sim, radius) * density


@command("mass")
def mass(sim, args):
    """``mass TYPE VALUE``. With spheres (particle_style sphere), whose masses are per particle:
    in the PDPS dialect the type's mass holds (PDPS's spheres have no mass of their own), for the
    particles of those types now present and those create_particle makes later; in the LAMMPS and
    LIGGGHTS dialects it is refused as LAMMPS refuses it (their masses come from diameter and
    density). Never ignored."""
    count(args, 2, "mass TYPE VALUE")
    sim.require_box("mass")
    lo, hi = type_range(args[0], sim.ntypes)
    value = number(args[1], "mass", low=0.0, strict_low=True)
    lammps_spheres = "sphere" in sim.particle_styles and sim.dialect.name != "pdps"
    if lammps_spheres and sim.particle_style == "sphere":
        raise ScriptError(f"cannot set a per-type mass for atom_style sphere (LAMMPS's rule): each particle's "
                          f"mass comes from its diameter and density (set type {args[0]} density RHO)")
    sim.mass[lo:hi + 1] = value
    if lammps_spheres:
        # LAMMPS's hybrid of sphere and a per-type-mass style takes the mass and uses the spheres' own
        sim.warn(f"mass {args[0]} {args[1]}: atom_style {sim.particle_style} uses each sphere's own mass "
                 "(diameter and density), not the type's, as LAMMPS does")
    elif "sphere" in sim.particle_styles:
        p = sim.particles
        rows = (p.type[: p.nlocal] >= lo) & (p.type[: p.nlocal] <= hi)
        p.rmass[: p.nlocal][rows] = value
        changed = int(sim.comm.sum(int(rows.sum())))
        sim.output.message(f"mass: {changed} sphere(s) of type {args[0]} now have mass {value:g} (the type's mass "
                           "holds for spheres in the PDPS dialect)")


@command("group")
def group(sim, args):
    """PDPS's group (region and type definitions re-evaluated before each run) and LAMMPS's (static;
    pdps_core/state/groups.py)."""
    usage = ("group ID STYLE ARGS (all, region RID, type T..., id I..., molecule M..., variable NAME, subtract G..., "
             "union G..., intersect G..., empty, clear, delete)")
    if not args:
        raise ScriptError(f"expected a group id; usage: {usage}")
    name, rest = args[0], args[1:]
    if name == "all" and not rest:
        return
    if not rest:
        raise ScriptError(f"expected a group style; usage: {usage}")
    style = choice(rest[0], "group style", ("all", "region", "type", "id", "variable", "subtract", "union",
                                            "intersect", "empty", "clear", "delete", "molecule", "dynamic",
                                            "static", "include"))
    if style in ("dynamic", "include"):
        raise ScriptError(f"group {style} is not supported (supported: region, type, id, molecule, variable, "
                          "subtract, union, intersect, empty, clear, delete)")
    if style == "static":
        count(rest[1:], 0, usage)
        return
    if style == "delete":
        count(rest[1:], 0, usage)
        sim.groups.define(sim, name, ("delete",))
        return
    lammps = sim.dialect.name in ("lammps", "liggghts")
    if not lammps and style in ("all", "region", "type"):
        sim.groups.define(sim, name, _pdps_definition(sim, style, rest[1:], usage))
        return
    sim.require_box(f"group {style}")
    n = sim.particles.nlocal
    if style == "clear":
        count(rest[1:], 0, usage)
        sim.groups.assign(sim, name, np.zeros(n, dtype=bool), replace=True)
        return
    sim.groups.assign(sim, name, _members(sim, style, rest[1:], usage))


def _pdps_definition(sim, style, words, usage):
    if style == "region":
        count(words, 1, usage)
        sim.region(words[0])
        return ("region", words[0])
    if style == "type":
        if not words:
            raise ScriptError(f"expected at least one type; usage: {usage}")
        sim.require_box("group type")
        return ("type", *[type_range(w.replace(":", "*"), sim.ntypes) for w in words])
    count(words, 0, usage)
    return (style,)


def _members(sim, style, words, usage):
    """Owned particles a static group style selects now."""
    p = sim.particles
    n = p.nlocal
    if style in ("all", "empty"):
        count(words, 0, usage)
        return np.full(n, style == "all")
    if style == "region":
        count(words, 1, usage)
        return sim.region(words[0]).match(p.x[:n])
    if style in ("type", "id", "molecule"):
        if style == "molecule" and not p.has("molecule"):
            raise ScriptError(f"group molecule needs molecule ids (particle_style molecular, bond, angle or "
                              f"full; this is {sim.particle_style})")
        values = {"type": p.type, "id": p.tag, "molecule": p.arrays.get("molecule")}[style][:n]
        return _selected(values, words, style, usage)
    if style == "variable":
        count(words, 1, usage)
        if words[0] not in sim.variables or sim.variables.style(words[0]) != "atom":
            raise ScriptError(f"group variable needs an atom-style variable (got {words[0]})")
        return sim.variables.atom_values(words[0]) != 0.0
    groups = [sim.require_group(g) for g in words]
    if not groups or (style == "subtract" and len(groups) < 2) or (style == "intersect" and len(groups) < 2):
        raise ScriptError(f"group {style} needs {'two or more' if style != 'union' else 'one or more'} groups")
    masks = [sim.groups.select(sim, g) for g in groups]
    if style == "union":
        return np.logical_or.reduce(masks)
    if style == "intersect":
        return np.logical_and.reduce(masks)
    return masks[0] & ~np.logical_or.reduce(masks[1:])


LOGICAL = {"<": np.less, "<=": np.less_equal, ">": np.greater, ">=": np.greater_equal, "==": np.equal,
           "!=": np.not_equal}


def _selected(values, words, style, usage):
    if not words:
        raise ScriptError(f"group {style} needs values; usage: {usage}")
    if words[0] in LOGICAL:
        count(words, 2, usage)
        return LOGICAL[words[0]](values, integer(words[1], style))
    if words[0] == "<>":
        count(words, 3, usage)
        return (values >= integer(words[1], style)) & (values <= integer(words[2], style))
    member = np.zeros(len(values), dtype=bool)
    for word in words:
        parts = word.split(":")
        if len(parts) > 3:
            raise ScriptError(f"{style} range must be A, A:B or A:B:STRIDE (got {word})")
        numbers = [integer(part, style) for part in parts]
        if len(numbers) == 1:
            member |= values == numbers[0]
            continue
        first, last = numbers[0], numbers[1]
        stride = numbers[2] if len(numbers) == 3 else 1
        if stride < 1 or last < first:
            raise ScriptError(f"{style} range {word} must have A <= B and a stride >= 1")
        member |= (values >= first) & (values <= last) & ((values - first) % stride == 0)
    return member


def _data_pair_coeffs(sim, data, name):
    """The data file's Pair Coeffs and PairIJ Coeffs, checked by the pair style before the box is
    made (a bad line leaves no half-read scene): [(I, J, coefficients)]."""
    if not data.pair_coeffs:
        return []
    if sim.pair is None:
        raise ScriptError(f"{name}:{data.pair_coeffs[0][0]}: the data file has pair coefficients: define the "
                          "pair_style before read_data")
    coeffs = []
    for number, words in data.pair_coeffs:
        try:
            coeffs.append((min(int(words[0]), int(words[1])), max(int(words[0]), int(words[1])),
                           sim.pair.parse_coeff(words[2:])))
        except ScriptError as exc:
            raise ScriptError(f"{name}:{number}: pair coefficients: {exc}") from None
    return coeffs


def _data_bonds(sim, data, start):
    """The data file's bonds, each stored on its first particle (rows from ``start``)."""
    p, topology = sim.particles, sim.system.topology
    row_of = {int(tag): start + k for k, tag in enumerate(data.tags)}
    owners = np.array([row_of[int(a)] for a in data.bonds[:, 1]], dtype=np.int64)
    counts = np.bincount(owners - start, minlength=len(data.tags)) if len(owners) else np.zeros(len(data.tags), int)
    topology.nbondtypes = data.nbondtypes
    topology.extra_bonds = data.extra_bonds
    topology.make_arrays(p, int(counts.max(initial=0)) + data.extra_bonds)
    for (kind, _, partner), row in zip(data.bonds.tolist(), owners.tolist()):
        slot = p.num_bond[row]
        p.bond_type[row, slot], p.bond_atom[row, slot] = kind, partner
        p.num_bond[row] = slot + 1


# LAMMPS's read_data's own section names, which a fix's section must not take (its read_data.cpp)
DATA_SECTIONS = frozenset({
    "Atoms", "Velocities", "Masses", "Ellipsoids", "Lines", "Triangles", "Bodies", "Bonds", "Angles", "Dihedrals",
    "Impropers", "Pair Coeffs", "PairIJ Coeffs", "Bond Coeffs", "Angle Coeffs", "Dihedral Coeffs",
    "Improper Coeffs", "BondBond Coeffs", "BondAngle Coeffs", "MiddleBondTorsion Coeffs", "EndBondTorsion Coeffs",
    "AngleTorsion Coeffs", "AngleAngleTorsion Coeffs", "BondBond13 Coeffs", "AngleAngle Coeffs"})


def _data_fix_readers(sim, words, usage):
    """{SECTION: fix} of read_data's ``fix ID NULL SECTION`` keywords (LAMMPS's: the fix reads the
    section's lines); any other keyword is refused."""
    readers = {}
    k = 0
    while k < len(words):
        if words[k] != "fix":
            raise ScriptError(f"read_data keyword {words[k]} is not supported; usage: {usage}")
        if len(words) < k + 4:
            raise ScriptError(f"fix needs ID NULL SECTION; usage: {usage}")
        ident, header, section = words[k + 1:k + 4]
        fix = sim.fixes.get(ident)
        if fix is None:
            raise ScriptError(f"fix {ident} is not defined (read_data fix)")
        if not callable(getattr(fix, "read_data_section", None)):
            raise ScriptError(f"fix {ident} ({fix.name}) reads no data file section")
        if header != "NULL":
            raise ScriptError(f"fix {ident} {header}: a fix's header keyword is not supported (give NULL)")
        if section in DATA_SECTIONS:
            raise ScriptError(f"fix {ident}: section {section} is one of read_data's own sections (LAMMPS refuses "
                              "it too): name the fix's section otherwise")
        readers[section] = fix
        k += 4
    return readers


@command("read_data")
def read_data(sim, args):
    from ..state.data_file import read_data_file
    usage = "read_data FILE [fix ID NULL SECTION ...]"
    if not args:
        raise ScriptError(f"expected a file; usage: {usage}")
    readers = _data_fix_readers(sim, args[1:], usage)
    if sim.box is not None:
        raise ScriptError("read_data needs no box to exist yet (it creates it)")
    data = read_data_file(sim.resolve(args[0]), sim.particle_style, tuple(readers))
    if sim.particle_style == "sphere" and data.masses:
        # LAMMPS's read_data refuses them too; in the PDPS dialect the mass command after read_data
        # gives a type's spheres one mass
        raise ScriptError(f"{args[0]}: Masses: cannot set a per-type mass for atom_style sphere (LAMMPS's rule): "
                          "each particle's mass comes from its diameter and density columns")
    coeffs = _data_pair_coeffs(sim, data, args[0])
    if data.bond_coeffs and sim.styles.bond is None:
        raise ScriptError(f"{args[0]}:{data.bond_coeffs[0][0]}: the data file has bond coefficients: define the "
                          "bond_style before read_data")
    make_box(sim, data.lo, data.hi, data.ntypes)
    for i, j, coeff in coeffs:
        sim.pair.coeff(i, j, coeff)
    for t, value in data.masses.items():
        sim.mass[t] = value
    if data.masses and "sphere" in sim.particle_styles:
        sim.warn(f"read_data {args[0]}: Masses are kept for the types, but atom_style {sim.particle_style} "
                 "uses each sphere's own mass (diameter and density), as LAMMPS does")
    p = sim.particles
    extra = dict(data.per_atom)
    if "sphere" in sim.particle_styles:
        extra.update(radius=0.5 * data.diameter, rmass=_data_mass(sim, 0.5 * data.diameter, data.density))
    start = p.nlocal
    p.add(data.x, data.types, **extra)
    p.tag[start:] = data.tags
    p.image[start:] = data.images
    if readers:
        rows = {int(tag): start + k for k, tag in enumerate(data.tags)}
        for section, fix in readers.items():
            if section not in data.fix_sections:
                raise ScriptError(f"{args[0]}: no section {section} for fix {fix.id}")
            try:
                fix.read_data_section(sim, section, data.fix_sections[section], rows)
            except ScriptError as exc:
                raise ScriptError(f"{args[0]}: {exc.message}") from None
    p.next_tag = int(data.tags.max()) + 1 if len(data.tags) else p.next_tag
    if data.velocities is not None:
        p.v[start:] = data.velocities
    if data.angular_velocities is not None:
        p.omega[start:] = data.angular_velocities
    if data.bonds is not None:
        _data_bonds(sim, data, start)
    sim.comm.distribute(p, sim.box)
    sim.groups.update(sim)
    sim.output.message(f"Read {len(data.tags)} particles from {args[0]}")
    if data.bonds is not None:
        sim.system.topology.build_special(sim)
        sim.output.message(f"  {len(data.bonds)} bonds")
    for number, words in data.bond_coeffs:
        try:
            COMMANDS["bond_coeff"](sim, words)
        except ScriptError as exc:
            raise ScriptError(f"{args[0]}:{number}: Bond Coeffs: {exc}") from None
    if data.skipped:
        listed = ", ".join(f"{amount} {kind}" for kind, amount in data.skipped.items())
        sim.warn(f"read_data {args[0]}: {listed} read past: pdps has no angle styles, so "
                           "they have no effect")
