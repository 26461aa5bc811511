"""LAMMPS's ``change_box``: give the box new bounds or new faces between runs, one operation after
another, carrying a group's particles with it where the script says ``remap``.

    change_box GROUP-ID OPERATION ... [units lattice|box]
        x|y|z final LO HI        the axis's new bounds
        x|y|z delta DLO DHI      lo += DLO, hi += DHI
        x|y|z scale FACTOR       the length times FACTOR about its midpoint
        x|y|z volume             after another axis's change: this axis (or, given twice, these two
                                 alike) about its midpoint, so the volume (area in 2-d) stays what it
                                 was before that change
        boundary BX BY BZ        faces as the boundary command gives them (p, f, s, m, or two of f, s, m);
                                 an axis no longer periodic sets its image flags to 0
        set                      remember the box as it is now
        remap                    the group's particles from the remembered box to the present one,
                                 each keeping its fractional coordinates (x' = lo' + L' (x - lo) / L),
                                 whatever the faces; the present box is remembered then

As LAMMPS's ChangeBox (22 Jul 2025 and LIGGGHTS 3.8.0, recorded): first the particles are wrapped
into the box along its periodic axes and shrink-wrapped faces fitted to them; the box is
remembered; the operations run in the order written, and after each change of an axis or of the
faces every shrink-wrapped face's margin becomes 1e-4 of its axis's length, an s face moving out by
it (LAMMPS's set_initial_box, also before a volume axis is fitted); then shrink-wrapped faces are
fitted again and every particle is wrapped into the new box along its periodic axes, image flags
counting (a box moved many lengths from its particles included). A box without ``remap`` leaves
particles where they are: one left outside a fixed face is lost at the next run's setup, which
stops with an error, or drops it with ``thermo_modify lost ignore|warn`` (LIGGGHTS's default:
ignore). FINAL and DELTA distances are in lattice spacings (``units lattice``, the default in the
LAMMPS and PDPS dialects; 1 without a lattice command) or box units (``units box``, LIGGGHTS 3.8.0's
default: its change_box.cpp, recorded). ``force`` (LIGGGHTS's: change the box although a restart
file's per-particle fix data is waiting) is read and changes nothing: pdps keeps such data with the
particles. The processor grid stays as it was (LAMMPS's); neighbor lists, ghosts and bins are made
anew at the next run's setup, as after fix deform. pdps boxes are orthogonal: the tilts xy, xz, yz
and ortho/triclinic are refused.

Example::

    change_box all x scale 1.1 y volume z volume remap
    change_box all z final 0.0 0.08 boundary p p f units box
"""

import numpy as np

from ..errors import ScriptError
from ..run.shrink_wrap import BOUNDARY_STYLES, set_initial_box, shrink_wrap
from ..state import limits
from ..state.box import remap
from . import command
from .words import choice, number

USAGE = ("change_box GROUP-ID x|y|z final LO HI|delta DLO DHI|scale F|volume, boundary BX BY BZ, set, remap "
         "... [units lattice|box]")
STYLES = {"final": ("LO", "HI"), "delta": ("DLO", "DHI"), "scale": ("FACTOR",), "volume": ()}
TILTED = "pdps boxes are orthogonal (no tilt); change_box takes x, y, z, boundary, set and remap"
REFUSED = dict.fromkeys(("xy", "xz", "yz", "ortho", "triclinic"), TILTED)


def _operations(sim, words):
    """The operations as (kind, axis, style, values, volume axes) in order, and the units word."""
    operations, units, k = [], None, 0
    while k < len(words) and words[k] != "units":
        word = words[k]
        if word in REFUSED:
            raise ScriptError(f"{word}: {REFUSED[word]}")
        if word == "force":
            k += 1
        elif word in ("x", "y", "z"):
            axis = "xyz".index(word)
            if k + 1 >= len(words):
                raise ScriptError(f"{word} needs a style: final, delta, scale or volume")
            style = choice(words[k + 1], f"{word} style", tuple(STYLES))
            if axis == 2 and sim.dimension == 2:
                raise ScriptError("a 2-d simulation's box cannot change in z")
            names = STYLES[style]
            values = words[k + 2:k + 2 + len(names)]
            if len(values) < len(names) or any(v in ("x", "y", "z", "units") for v in values):
                raise ScriptError(f"{word} {style} needs {' '.join(names)} (got "
                                  f"{' '.join(values) or 'nothing'})")
            values = tuple(number(v, f"{word} {style} {n}", representable=True) for v, n in zip(values, names))
            if style == "scale" and not values[0] > 0:
                raise ScriptError(f"{word} scale FACTOR must be > 0 (got {words[k + 2]})")
            if style == "volume":
                _keep_volume_of(operations, word, axis)
            else:
                operations.append(["xyz", axis, style, values, []])
            k += 2 + len(names)
        elif word == "boundary":
            faces = words[k + 1:k + 4]
            if len(faces) < 3:
                raise ScriptError(f"boundary needs BX BY BZ (got {' '.join(faces) or 'nothing'})")
            for axis, face in zip("xyz", faces):
                choice(face, f"boundary {axis}", BOUNDARY_STYLES)
            if sim.dimension == 2 and faces[2] != "p":
                raise ScriptError(f"a 2-d simulation needs a periodic z boundary (got boundary z {faces[2]})")
            operations.append(["boundary", None, None, tuple(faces), []])
            k += 4
        elif word in ("set", "remap"):
            operations.append([word, None, None, (), []])
            k += 1
        else:
            raise ScriptError(f"unknown operation {word}; usage: {USAGE}")
    if not operations:
        raise ScriptError(f"expected at least one operation; usage: {USAGE}")
    rest = words[k:]
    for key, value in zip(rest[::2], rest[1::2]):
        units = choice(value, "units", ("box", "lattice"))
    if len(rest) % 2 or any(key != "units" for key in rest[::2]):
        raise ScriptError(f"after the operations only units lattice|box may follow; usage: {USAGE}")
    return operations, units


def _keep_volume_of(operations, word, axis):
    """``AXIS volume`` joins the x, y or z change just before it (LAMMPS's rule: another axis, at
    most two volume axes to one change)."""
    last = operations[-1] if operations else None
    if last is None or last[0] != "xyz" or last[1] == axis or len(last[4]) == 2:
        raise ScriptError(f"{word} volume must follow an x, y or z change of another axis "
                          "(with at most one other volume)")
    last[4].append(axis)


def _keep_volume(lo, hi, axes, volume, dimension):
    """LAMMPS's volume_preserve: the axes scaled about their midpoints to give back ``volume``, one
    axis by the ratio, two each by its square root."""
    now = (hi[0] - lo[0]) * (hi[1] - lo[1])
    if dimension == 3:
        now *= hi[2] - lo[2]
    ratio = volume / now
    factor = ratio if len(axes) == 1 else np.sqrt(ratio)
    for d in axes:
        mid = 0.5 * (lo[d] + hi[d])
        lo[d] = mid + factor * (lo[d] - mid)
        hi[d] = mid + factor * (hi[d] - mid)


@command("change_box")
def change_box(sim, args):
    sim.require_box("change_box")
    if not args:
        raise ScriptError(f"expected a group and operations; usage: {USAGE}")
    group = sim.require_group(args[0])
    operations, units = _operations(sim, args[1:])
    units = units or sim.dialect.command_units
    spacing = sim.lattice.spacing if (units == "lattice" and sim.lattice is not None) else np.ones(3)
    box, system, p = sim.box, sim.system, sim.particles
    p.clear_ghosts()
    _wrap(sim)
    shrink_wrap(sim)
    lo, hi, faces, periodicity = box.lo.copy(), box.hi.copy(), system.shrink_faces, system.periodicity
    x, image = p.x[:p.nlocal].copy(), p.image[:p.nlocal].copy()
    chosen = np.flatnonzero(sim.groups.select(sim, group))
    saved_lo, saved_hi = lo.copy(), hi.copy()
    for kind, axis, style, values, volume_axes in operations:
        if kind == "xyz":
            length = hi - lo
            volume = length[0] * length[1] * (length[2] if sim.dimension == 3 else 1.0)
            if style == "final":
                lo[axis], hi[axis] = spacing[axis] * values[0], spacing[axis] * values[1]
            elif style == "delta":
                lo[axis] += spacing[axis] * values[0]
                hi[axis] += spacing[axis] * values[1]
            else:
                mid = 0.5 * (lo[axis] + hi[axis])
                lo[axis] = mid + values[0] * (lo[axis] - mid)
                hi[axis] = mid + values[0] * (hi[axis] - mid)
            word = f"{'xyz'[axis]} {style} {' '.join(f'{v:g}' for v in values)}".rstrip()
            _check_bounds(lo, hi, word)
            if volume_axes:
                lo, hi, faces = set_initial_box(periodicity, lo, hi)
                _keep_volume(lo, hi, volume_axes, volume, sim.dimension)
                _check_bounds(lo, hi, f"{word} with {' '.join('xyz'[d] for d in volume_axes)} volume")
            lo, hi, faces = set_initial_box(periodicity, lo, hi)
        elif kind == "boundary":
            # an axis no longer periodic forgets its image flags (LAMMPS's Domain::set_boundary)
            closed = [d for d in range(3) if periodicity[d] == "p" and values[d] != "p"]
            image[:, closed] = 0
            periodicity = values
            lo, hi, faces = set_initial_box(periodicity, lo, hi)
        elif kind == "set":
            saved_lo, saved_hi = lo.copy(), hi.copy()
        else:
            lamda = (x[chosen] - saved_lo) * (1.0 / (saved_hi - saved_lo))
            x[chosen] = (hi - lo) * lamda + lo
            saved_lo, saved_hi = lo.copy(), hi.copy()
    if sim.comm.sum(int(not np.isfinite(x).all())):
        raise ScriptError("remap gives non-finite positions")
    p.x[:p.nlocal], p.image[:p.nlocal] = x, image
    box.set_bounds(lo, hi)
    box.set_periodic([word == "p" for word in periodicity])
    system.periodicity, system.shrink_faces = tuple(periodicity), faces
    shrink_wrap(sim)
    _wrap(sim)
    sim.comm.migrate(p, box)
    sim.groups.update(sim)
    sim.run_state.box_changed = True
    sim.output.message("Changing box ...\n  orthogonal box = ({}) to ({})".format(
        " ".join(f"{v:.8g}" for v in box.lo), " ".join(f"{v:.8g}" for v in box.hi)))


def _check_bounds(lo, hi, word):
    limits.check_box(lo, hi, f"{word}: the box's")


def _wrap(sim):
    """Every owned particle into the box along its periodic axes, image flags counting (LAMMPS's
    Domain::remap); none refused: what lies outside a fixed face is for the next run to decide."""
    p, box = sim.particles, sim.box
    n = p.nlocal
    x, shifts = p.x[:n].copy(), np.zeros((n, 3), dtype=np.int64)
    remap(x, shifts, box.lo, box.hi, np.asarray(box.periodic, dtype=np.bool_))
    image = p.image[:n] + shifts
    if sim.comm.sum(int(np.abs(image).max(initial=0) > limits.MAX_IMAGE)):
        raise ScriptError(f"the box leaves particles more than {limits.MAX_IMAGE} box lengths from the box")
    p.x[:n], p.image[:n] = x, image
