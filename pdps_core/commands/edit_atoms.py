"""LAMMPS's commands that change particles already made: ``set``, ``delete_atoms``, ``displace_atoms``,
and ``write_data`` that writes them.

    set atom|type|group|region ID keyword value ...
        type T | type/fraction T FRACTION SEED | x|y|z|vx|vy|vz VALUE | mass M | diameter D |
        density RHO | image NX NY NZ | omega WX WY WZ     (a value may be v_NAME, an atom-style variable)
    delete_atoms group G | region R | overlap CUTOFF G1 G2  [compress yes|no]
    displace_atoms G move DX DY DZ | ramp DDIM DLO DHI DIM CLO CHI | random DX DY DZ SEED |
        rotate PX PY PZ RX RY RZ THETA  [units box|lattice]
    write_data FILE [nocoeff] [nofix] [nolabelmap] [pair ii|ij]

As in LAMMPS: ``set`` IDs of style atom and type take ranges (``1*10``); ``mass`` sets per-particle
masses (spheres), ``diameter`` a sphere's radius (its mass stays, as LAMMPS's set diameter leaves it;
in the LIGGGHTS dialect its density stays and the mass follows the new size, as LIGGGHTS's) and
``density`` its mass (density times its volume at its present diameter; in 2-d LIGGGHTS's volume is the
disc's area, LAMMPS's the sphere's); ``type/fraction`` decides each particle from LAMMPS's Park-Miller generator seeded from
its coordinates, so the same particles change on any number of ranks. ``delete_atoms ... compress
yes`` (the default) renumbers the ids 1..N in storage order after LAMMPS's way of deleting (the last
particle moves into each deleted one's slot), so a serial script gets LAMMPS's ids; ``overlap`` takes the particles in id
order and deletes a G1 particle when a G2 particle closer than CUTOFF has not been deleted already
(LAMMPS's rule, which for a serial LAMMPS run goes through its particles in the order they were
made). ``displace_atoms`` distances are in lattice
spacings by default (LAMMPS's; box in the LIGGGHTS dialect, as LIGGGHTS 3.8.0: Dialect.command_units); particles are wrapped back into a periodic box as LAMMPS's Domain::remap
wraps them; ``random`` draws, in the LAMMPS dialect, LAMMPS's numbers (a Park-Miller stream seeded
from SEED and each particle's position: the same particles move by the same amounts), in the PDPS
dialect pdps's counter-based ones. ``write_data`` writes what read_data reads back (Masses, Atoms with
image flags, Velocities; ``atom_style sphere``'s diameter and density), not the pair coefficients.
"""

import math

import numpy as np
from numba import njit

from ..errors import ScriptError
from ..random import particle_uniforms
from ..random_park import park_reset_coord, park_uniform
from ..state import limits
from ..state.box import remap
from ..state.particles import style_columns
from . import command
from .particles import sphere_volume
from .words import choice, count, integer, number, type_range, yes_no


# ---- set ---------------------------------------------------------------------------------------------
SET_ARITY = {"type": 1, "type/fraction": 3, "x": 1, "y": 1, "z": 1, "vx": 1, "vy": 1, "vz": 1, "mass": 1,
             "diameter": 1, "density": 1, "image": 3, "omega": 3, "omegax": 1,
             "omegay": 1, "omegaz": 1, "charge": 1, "mol": 1, "property/atom": 2,
             "property/peratom": 2}


def _selection(sim, style, ident):
    p = sim.particles
    n = p.nlocal
    if style == "atom":
        lo, hi = _id_range(ident)
        tags = p.tag[:n]
        return (tags >= lo) & (tags <= hi)
    if style == "type":
        lo, hi = type_range(ident, sim.ntypes)
        return (p.type[:n] >= lo) & (p.type[:n] <= hi)
    if style == "group":
        return sim.groups.select(sim, sim.require_group(ident))
    if style == "region":
        return sim.region(ident).match(p.x[:n])
    if style == "mol":
        lo, hi = _id_range(ident)
        molecule = _molecules(sim, "set mol")
        return (molecule >= lo) & (molecule <= hi)
    raise ScriptError(f"set style must be atom, type, mol, group or region (got {style})")


def _molecules(sim, what):
    """The owned particles' molecule ids, or an error naming the particle styles that have them."""
    p = sim.particles
    if not p.has("molecule"):
        raise ScriptError(f"{what} needs molecule ids (particle_style molecular, bond, angle or full; "
                          f"this is {sim.particle_style})")
    return p.molecule[:p.nlocal]


def _id_range(word):
    if word == "*":
        return 1, limits.MAX_TAG
    if "*" in word:
        left, _, right = word.partition("*")
        lo = integer(left, "id") if left else 1
        hi = integer(right, "id") if right else limits.MAX_TAG
        return lo, hi
    value = integer(word, "id", low=1)
    return value, value


def _values(sim, word, what, selected):
    """A number, or per particle from v_NAME (an atom-style variable), for the selected particles."""
    if word.startswith("v_"):
        name = word[2:]
        if name not in sim.variables:
            raise ScriptError(f"variable {name} is not defined ({what} {word})")
        return sim.variables.atom_values(name)[selected]
    return number(word, what)


@command("set")
def set_(sim, args):
    usage = "set atom|type|group|region ID keyword value ..."
    sim.require_box("set")
    if len(args) < 4:
        raise ScriptError(f"expected a style, an ID and keyword values; usage: {usage}")
    style = choice(args[0], "set style", ("atom", "type", "group", "region", "mol"))
    selected = _selection(sim, style, args[1])
    k = 2
    while k < len(args):
        key = args[k]
        if key not in SET_ARITY:
            raise ScriptError(f"unknown set keyword {key} (supported: {', '.join(SET_ARITY)})")
        values = args[k + 1:k + 1 + SET_ARITY[key]]
        if len(values) < SET_ARITY[key]:
            raise ScriptError(f"set {key} needs {SET_ARITY[key]} value(s)")
        changed = int(sim.comm.sum(int(_set_one(sim, key, values, selected))))
        sim.output.message(f"Setting atom values ...\n  {changed} settings made for {key}")
        k += 1 + SET_ARITY[key]
    sim.groups.update(sim)


def _set_one(sim, key, values, selected):
    p = sim.particles
    n = p.nlocal
    rows = np.flatnonzero(selected)
    if key == "type":
        p.type[rows] = integer(values[0], "type", low=1, high=sim.ntypes)
        return len(rows)
    if key == "type/fraction":
        new_type = integer(values[0], "type", low=1, high=sim.ntypes)
        fraction = number(values[1], "fraction", low=0.0, high=1.0)
        seed = integer(values[2], "seed", low=1, high=2 ** 31 - 1)
        chosen = rows[_fraction(np.ascontiguousarray(p.x[rows]), seed, fraction)]
        p.type[chosen] = new_type
        return len(chosen)
    if key in ("x", "y", "z", "vx", "vy", "vz"):
        array = p.x if len(key) == 1 else p.v
        d = "xyz".index(key[-1])
        array[rows, d] = _values(sim, values[0], key, selected)
        return len(rows)
    if key in ("omegax", "omegay", "omegaz"):
        # LIGGGHTS's spelling: one component
        key, values = "omega", ["NULL"] * "xyz".index(key[-1]) + list(values)
    if key in ("image", "omega"):
        if key == "omega" and not p.has("omega"):
            raise ScriptError("set omega needs atom_style sphere")
        for d, word in enumerate(values):
            if word == "NULL":
                continue
            if key == "image":
                p.image[rows, d] = integer(word, "image", low=-limits.MAX_IMAGE, high=limits.MAX_IMAGE)
            else:
                p.omega[rows, d] = _values(sim, word, "omega", selected)
        return len(rows)
    if key in ("mass", "diameter", "density"):
        if not p.has("rmass"):
            raise ScriptError(f"set {key} needs per-particle masses (atom_style sphere)")
        value = _values(sim, values[0], key, selected)
        if np.any(np.asarray(value) <= 0) and key != "diameter":
            raise ScriptError(f"{key} must be > 0 (got {values[0]})")
        # as create_particle's and a restart file's: masses and moments of inertia (r^5) stay normal
        low, high = (limits.MIN_SIZE ** 3, limits.MAX_SIZE ** 3) if key == "mass" else (limits.MIN_SIZE, limits.MAX_SIZE)
        if np.any(np.asarray(value) > high) or (key != "diameter" and np.any(np.asarray(value) < low)):
            raise ScriptError(f"{key} must be from {low:g} to {high:g} (got {values[0]})")
        if key == "mass":
            p.rmass[rows] = value
        elif key == "diameter":
            if np.any(np.asarray(value) < limits.MIN_SIZE):
                raise ScriptError(f"diameter must be >= {limits.MIN_SIZE:g} (got {values[0]})")
            radius = 0.5 * np.asarray(value)
            if sim.dialect.set_diameter_keeps == "density":
                # LIGGGHTS keeps each sphere's density, so its mass follows the new size; a point
                # particle (radius 0) has no density to keep
                old = sphere_volume(sim, p.radius[rows])
                density = np.divide(p.rmass[rows], old, out=np.zeros_like(old), where=old > 0)
                p.rmass[rows] = np.where(old > 0, density * sphere_volume(sim, radius), p.rmass[rows])
            # LAMMPS's set diameter keeps the mass (set density after it sets that)
            p.radius[rows] = radius
        else:
            p.rmass[rows] = np.asarray(value) * sphere_volume(sim, p.radius[rows])
        return len(rows)
    if key in ("property/atom", "property/peratom"):
        # LIGGGHTS's per-atom properties that fixes make (heat/gran's Temp, heatSource)
        name = values[0]
        core = ("x", "v", "f", "tag", "type", "mask", "image", "radius", "rmass", "omega", "torque", "q", "molecule")
        if name in core or not p.has(name) or p.arrays[name].ndim != 1:
            raise ScriptError(f"set {key}: {name} is not a per-atom property of one value a fix made (heat/gran "
                              "makes Temp and heatSource)")
        p.arrays[name][rows] = _values(sim, values[1], name, selected)
        return len(rows)
    if key == "charge":
        if not p.has("q"):
            raise ScriptError(f"set charge needs charges (particle_style charge or full; this is "
                              f"{sim.particle_style})")
        p.q[rows] = _values(sim, values[0], key, selected)
        return len(rows)
    _molecules(sim, "set mol")
    if values[0].startswith("v_"):
        ids = np.asarray(_values(sim, values[0], key, selected))
        if not (np.isfinite(ids).all() and (ids >= 0).all() and (ids <= limits.MAX_TAG).all()):
            raise ScriptError(f"set mol: {values[0]} gives molecule ids outside 0..{limits.MAX_TAG}")
        p.molecule[rows] = ids.astype(np.int64)        # LAMMPS truncates a variable's value too
    else:
        p.molecule[rows] = integer(values[0], "molecule id", low=0, high=limits.MAX_TAG)
    return len(rows)


def _fraction(x, seed, fraction):
    """Which particles LAMMPS's set type/fraction picks: a Park-Miller stream seeded from the seed and
    each particle's position, its first uniform below the fraction."""
    from ..random_park import park_reset_coord, park_state, park_uniform
    state = park_state(seed)
    picked = np.zeros(len(x), dtype=bool)
    for k in range(len(x)):
        park_reset_coord(state, seed, x[k])
        picked[k] = park_uniform(state) < fraction
    return picked


# ---- delete_atoms --------------------------------------------------------------------------------------
@command("delete_atoms")
def delete_atoms(sim, args):
    usage = "delete_atoms group G | region R | overlap CUTOFF G1 G2 [compress yes|no]"
    sim.require_box("delete_atoms")
    if len(args) < 2:
        raise ScriptError(f"expected a style; usage: {usage}")
    style = choice(args[0], "delete_atoms style", ("group", "region", "overlap", "porosity", "variable",
                                                   "random"))
    p = sim.particles
    n = p.nlocal
    if style == "group":
        doomed, rest = sim.groups.select(sim, sim.require_group(args[1])), args[2:]
    elif style == "region":
        doomed, rest = sim.region(args[1]).match(p.x[:n]), args[2:]
    elif style == "overlap":
        if len(args) < 4:
            raise ScriptError(f"overlap needs CUTOFF G1 G2; usage: {usage}")
        cutoff = number(args[1], "cutoff", low=0.0, strict_low=True, high=limits.MAX_COORDINATE)
        doomed, rest = _overlapping(sim, cutoff, args[2], args[3]), args[4:]
    else:
        raise ScriptError(f"delete_atoms {style} is not supported (supported: group, region, overlap)")
    compress, whole_molecules = True, False
    for key, value in zip(rest[::2], rest[1::2]):
        if key == "compress":
            compress = yes_no(value, "compress")
        elif key == "bond":
            yes_no(value, "bond")          # pdps keeps no bonds: there are none to delete
        elif key == "mol":
            whole_molecules = yes_no(value, "mol")
        else:
            raise ScriptError(f"unknown delete_atoms keyword {key}; usage: {usage}")
    if len(rest) % 2:
        raise ScriptError(f"expected keyword/value pairs after the style; usage: {usage}")
    if whole_molecules:
        doomed = _whole_molecules(sim, doomed)
    deleted = int(sim.comm.sum(int(doomed.sum())))
    p.remove(np.array(doomed, dtype=np.bool_))       # LAMMPS's order: compressed ids follow its
    sim.groups.update(sim)
    if compress:
        _compress_ids(sim)
    sim.output.message(f"Deleted {deleted} atoms, new total = {int(sim.comm.sum(sim.particles.nlocal))}")


def _whole_molecules(sim, doomed):
    """LAMMPS's ``mol yes``: the other particles of every molecule a deleted particle belongs to go
    too, on every rank; molecule id 0 is no molecule."""
    molecule = _molecules(sim, "delete_atoms mol yes")
    hit = np.unique(molecule[doomed & (molecule > 0)]).astype(np.float64).reshape(-1, 1)
    everywhere = sim.comm.allgather_rows(hit)[:, 0].astype(np.int64)
    return doomed | np.isin(molecule, everywhere)


def _overlapping(sim, cutoff, group1, group2):
    """Owned particles to delete, as LAMMPS's delete_atoms overlap decides: particles taken in id
    order, a G1 particle goes when a G2 particle closer than cutoff (periodic images counted) has
    not gone already. Every rank looks at every particle, so all agree."""
    p = sim.particles
    n = p.nlocal
    in1, in2 = sim.groups.select(sim, sim.require_group(group1)), sim.groups.select(sim, sim.require_group(group2))
    x_all = sim.comm.allgather_rows(np.ascontiguousarray(p.x[:n]))
    tag_all = sim.comm.allgather_rows(p.tag[:n].copy())
    in1_all, in2_all = sim.comm.allgather_rows(in1), sim.comm.allgather_rows(in2)
    order = np.argsort(tag_all)
    x_all, tag_all, in1_all, in2_all = x_all[order], tag_all[order], in1_all[order], in2_all[order]
    box = sim.box
    gone = np.zeros(len(tag_all), dtype=bool)
    cutsq = cutoff * cutoff
    for i in np.flatnonzero(in1_all):
        d = x_all - x_all[i]
        for dim in range(3):
            if box.periodic[dim]:
                d[:, dim] -= box.length[dim] * np.round(d[:, dim] / box.length[dim])
        partner = in2_all & (np.einsum("ij,ij->i", d, d) < cutsq) & ~gone
        partner[i] = False
        gone[i] = bool(partner.any())
    doomed_tags = set(tag_all[gone].tolist())
    return np.array([t in doomed_tags for t in p.tag[:n].tolist()], dtype=bool)


def _compress_ids(sim):
    """Ids 1..N as LAMMPS's compress gives them for atomic systems (Atom::tag_extend): rank by rank,
    each rank's particles in their storage order."""
    p = sim.particles
    n = p.nlocal
    counts = sim.comm.allgather_rows(np.array([n], dtype=np.int64))
    first = int(np.sum(counts[:sim.comm.rank])) + 1
    p.tag[:n] = np.arange(first, first + n, dtype=p.tag.dtype)
    p.next_tag = int(np.sum(counts)) + 1


# ---- displace_atoms ------------------------------------------------------------------------------------
@command("displace_atoms")
def displace_atoms(sim, args):
    usage = ("displace_atoms G move DX DY DZ | ramp DDIM DLO DHI DIM CLO CHI | random DX DY DZ SEED | "
             "rotate PX PY PZ RX RY RZ THETA [units box|lattice]")
    sim.require_box("displace_atoms")
    if len(args) < 2:
        raise ScriptError(f"expected a group and a style; usage: {usage}")
    chosen = sim.groups.select(sim, sim.require_group(args[0]))
    style = choice(args[1], "displace_atoms style", ("move", "ramp", "random", "rotate"))
    need = {"move": 3, "ramp": 6, "random": 4, "rotate": 7}[style]
    words, rest = args[2:2 + need], args[2 + need:]
    if len(words) < need:
        raise ScriptError(f"displace_atoms {style} needs {need} values; usage: {usage}")
    units = sim.dialect.command_units
    for key, value in zip(rest[::2], rest[1::2]):
        if key != "units":
            raise ScriptError(f"unknown displace_atoms keyword {key}; usage: {usage}")
        units = choice(value, "units", ("box", "lattice"))
    if len(rest) % 2:
        raise ScriptError(f"expected keyword/value pairs; usage: {usage}")
    scale = sim.lattice.spacing if (units == "lattice" and sim.lattice is not None) else np.ones(3)
    p = sim.particles
    n = p.nlocal
    x = p.x[:n].copy()
    image = p.image[:n].astype(np.int64)
    rows = np.flatnonzero(chosen)
    if style == "move":
        shift = np.array([_values(sim, w, f"d{a}", chosen) if w.startswith("v_") else number(w, f"d{a}")
                          for a, w in zip("xyz", words)], dtype=object)
        for d in range(3):
            x[rows, d] += np.asarray(shift[d], dtype=np.float64) * scale[d]
    elif style == "ramp":
        ddim = "xyz".index(choice(words[0], "ramp dimension", ("x", "y", "z")))
        if ddim == 2 and sim.dimension == 2:
            raise ScriptError("a 2-d system's particles cannot be displaced in z (ramp z)")
        dlo, dhi = number(words[1], "dlo") * scale[ddim], number(words[2], "dhi") * scale[ddim]
        cdim = "xyz".index(choice(words[3], "coordinate dimension", ("x", "y", "z")))
        clo, chi = number(words[4], "clo") * scale[cdim], number(words[5], "chi") * scale[cdim]
        if not chi > clo:
            raise ScriptError(f"chi must be > clo (got {clo:g} {chi:g})")
        fraction = np.clip((x[rows, cdim] - clo) / (chi - clo), 0.0, 1.0)
        x[rows, ddim] += dlo + fraction * (dhi - dlo)
    elif style == "random":
        amplitude = np.array([number(w, f"d{a}", low=0.0) for a, w in zip("xyz", words[:3])]) * scale
        if amplitude[2] != 0.0 and sim.dimension == 2:
            raise ScriptError(f"a 2-d system's particles cannot be displaced in z (dz = {words[2]})")
        if sim.dialect.name == "lammps":
            seed = integer(words[3], "seed", low=1, high=2 ** 31 - 1)
            _park_displace(x, rows, amplitude, seed)
        else:
            seed = integer(words[3], "seed", low=1)
            for k in rows:
                u0, u1, u2, _ = particle_uniforms(seed, sim.step, int(p.tag[k]), 3)
                x[k] += amplitude * (2.0 * np.array([u0, u1, u2]) - 1.0)
    else:
        point = np.array([number(w, "P") for w in words[:3]]) * scale
        axis = np.array([number(w, "R") for w in words[3:6]])
        length = float(np.linalg.norm(axis))
        if length == 0.0:
            raise ScriptError("the rotation axis must not be zero")
        axis /= length
        theta = math.radians(number(words[6], "theta"))
        x[rows] = _rotate(x[rows] + image[rows] * sim.box.length, point, axis, theta)
        image[rows] = 0
    if sim.dimension == 2:
        x[:, 2] = 0.0
    # every rank agrees before anything changes: an error leaves the particles where they were
    if sim.comm.sum(int(not np.isfinite(x).all())):
        raise ScriptError("displace_atoms gives non-finite positions")
    box = sim.box
    shifts = np.zeros((n, 3), dtype=np.int64)
    remap(x, shifts, box.lo, box.hi, np.asarray(box.periodic, dtype=np.bool_))
    image += shifts
    if sim.comm.sum(int(np.abs(image).max(initial=0) > limits.MAX_IMAGE)):
        raise ScriptError(f"displace_atoms moves particles more than {limits.MAX_IMAGE} box lengths")
    if sim.comm.sum(int(not box.inside(x).all())):
        raise ScriptError("displace_atoms moves particles outside a non-periodic box")
    p.x[:n] = x
    p.image[:n] = image
    sim.comm.exchange(p, box, sim.step)      # particles that crossed into another rank's sub-domain move
    sim.groups.update(sim)


@njit(cache=True)
def _park_displace(x, rows, amplitude, seed):
    """LAMMPS's displace_atoms random: a Park-Miller stream seeded from the seed and the particle's
    position, three uniforms u, each coordinate moved by d 2 (u - 1/2) (so the same particles move
    by the same amounts on any number of ranks)."""
    state = np.zeros(3)
    coord = np.empty(3)
    for k in rows:
        for d in range(3):
            coord[d] = x[k, d]
        park_reset_coord(state, seed, coord)
        for d in range(3):
            x[k, d] += amplitude[d] * 2.0 * (park_uniform(state) - 0.5)


def _rotate(x, point, axis, theta):
    """Rodrigues' rotation of points about the axis through point."""
    d = x - point
    c, s = math.cos(theta), math.sin(theta)
    return point + d * c + np.cross(axis, d) * s + np.outer(d @ axis, axis) * (1.0 - c)


# ---- write_data --------------------------------------------------------------------------------------
@command("write_data")
def write_data(sim, args):
    count(args, 1, "write_data FILE [nocoeff] [nofix] [nolabelmap] [pair ii|ij]", at_most=6)
    sim.require_box("write_data")
    k = 1
    while k < len(args):
        if args[k] in ("nocoeff", "nofix", "nolabelmap", "nolattice"):
            k += 1
        elif args[k] == "pair" and k + 1 < len(args):
            choice(args[k + 1], "pair", ("ii", "ij"))
            k += 2
        else:
            raise ScriptError(f"unknown write_data keyword {args[k]}")
    p = sim.particles
    n = p.nlocal
    sphere = "sphere" in sim.particle_styles
    values = {"id": p.tag[:n], "type": p.type[:n], "x": p.x[:n, 0], "y": p.x[:n, 1], "z": p.x[:n, 2]}
    if sphere:
        volume = sphere_volume(sim, p.radius[:n])
        values["diameter"] = 2.0 * p.radius[:n]
        values["density"] = np.where(volume > 0, p.rmass[:n] / np.where(volume > 0, volume, 1.0), p.rmass[:n])
    for name in ("molecule", "q"):
        if p.has(name):
            values[name] = p.arrays[name][:n]
    names = style_columns(sim.particle_style)
    whole = {"id", "type", "molecule"}
    columns = [values[name].astype(np.float64) for name in names]
    atoms = sim.comm.gather_rows(np.column_stack(columns + list(p.image[:n].T.astype(np.float64))))
    # spheres' lines carry their angular velocity too, as LAMMPS writes them
    spin = [p.omega[:n]] if sphere else []
    velocities = sim.comm.gather_rows(np.column_stack([p.tag[:n].astype(np.float64), p.v[:n]] + spin))
    bonds = None
    if p.has("num_bond"):
        # every stored bond (turned-off ones with their negative type, as LAMMPS writes them)
        slots = np.arange(p.bond_type.shape[1])[None, :] < p.num_bond[:n, None]
        owners = np.repeat(p.tag[:n], p.num_bond[:n])
        bonds = sim.comm.gather_rows(np.column_stack([p.bond_type[:n][slots], owners, p.bond_atom[:n][slots]])
                                     .astype(np.float64)).astype(np.int64).reshape(-1, 3)
        bonds = bonds[bonds[:, 0] != 0]        # broken ones are gone
    if not sim.comm.is_root:
        return
    atoms = atoms[np.argsort(atoms[:, 0])]
    velocities = velocities[np.argsort(velocities[:, 0])]
    box = sim.box
    lines = [f"LAMMPS data file via pdps write_data, timestep = {sim.step}, units = {sim.units.name}", "",
             f"{len(atoms)} atoms", f"{sim.ntypes} atom types"]
    if bonds is not None:
        topology = sim.system.topology
        lines += [f"{len(bonds)} bonds", f"{topology.nbondtypes} bond types"]
        width = p.bond_type.shape[1]
        most = int(np.unique(bonds[:, 1], return_counts=True)[1].max()) if len(bonds) else 0
        lines += [f"{width - most} extra bond per atom"]
    lines += [""]
    lines += [f"{lo!r} {hi!r} {a}lo {a}hi" for lo, hi, a in zip(box.lo.tolist(), box.hi.tolist(), "xyz")]
    if not sphere:
        lines += ["", "Masses", ""]
        lines += [f"{t} {float(sim.mass[t])!r}" for t in range(1, sim.ntypes + 1) if not np.isnan(sim.mass[t])]
    lines += ["", f"Atoms # {sim.particle_style.split()[0]}", ""]
    for row in atoms.tolist():
        numbers = [f"{int(v)}" if name in whole else repr(v) for name, v in zip(names, row)]
        lines.append(" ".join(numbers + [f"{int(v)}" for v in row[-3:]]))
    lines += ["", "Velocities", ""]
    lines += [" ".join([f"{int(row[0])}"] + [repr(v) for v in row[1:]]) for row in velocities.tolist()]
    if bonds is not None and len(bonds):
        bonds = bonds[np.lexsort((bonds[:, 2], bonds[:, 1]))]
        lines += ["", "Bonds", ""]
        lines += [f"{k + 1} {kind} {a} {b}" for k, (kind, a, b) in enumerate(bonds.tolist())]
    path = sim.resolve(args[0])
    try:
        with open(path, "w") as handle:
            handle.write("\n".join(lines) + "\n")
    except OSError as exc:
        raise ScriptError(f"cannot write data file {args[0]}: {exc.strerror}") from None

