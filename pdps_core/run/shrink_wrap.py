"""Shrink-wrapped box faces (``boundary s`` and ``m``, LAMMPS's and LIGGGHTS's): before each
exchange of a neighbor list rebuild (and at a run's setup), such a face moves to the particles'
extent along its axis, less (lower face) or plus (upper face) 1e-4 of the box length the box was
made with (LAMMPS's ``small``, set by create_box, read_data and read_restart, and again by
change_box and replicate, not by later wrapping: recorded, in.crack's volume is LAMMPS's to 8 digits); an ``m`` face never moves inside its
first position (the box command's or the data file's). The extent takes in what fixes say the box
encloses besides the particles (``Fix.box_extent``: LIGGGHTS's meshes, so that a tutorial's box is
its mesh's plus the margin before any particle exists). With neither particles nor such fixes the
faces stay. The new bounds are the same on every rank."""

import math

import numpy as np

SMALL = 1.0e-4
BOUNDARY_STYLES = ("p", "f", "s", "m") + tuple(a + b for a in "fsm" for b in "fsm")


def shrink_faces(periodicity, lo, hi):
    """The shrink-wrapped faces of a box: (axis, 0 lower | 1 upper, "s" or "m", the face's first
    position, its margin) for each face whose boundary word (p, f, s, m, or two letters) says s or m."""
    return tuple((d, side, word[side % len(word)], float((lo, hi)[side][d]), SMALL * float(hi[d] - lo[d]))
                 for d, word in enumerate(periodicity) for side in (0, 1) if word[side % len(word)] in "sm")


def set_initial_box(periodicity, lo, hi):
    """LAMMPS's Domain::set_initial_box, which change_box runs after each operation and replicate
    after making its box: (lo, hi, faces) with every shrink-wrapped face's margin SMALL times its
    axis's length now, an s face moved out by its margin, an m face's first position where it is."""
    lo, hi = np.array(lo, dtype=np.float64), np.array(hi, dtype=np.float64)
    margins = SMALL * (hi - lo)
    faces = []
    for d, word in enumerate(periodicity):
        for side, bound, outward in ((0, lo, -1.0), (1, hi, 1.0)):
            style = word[side % len(word)]
            if style == "s":
                bound[d] += outward * margins[d]
            if style in "sm":
                faces.append((d, side, style, float(bound[d]), float(margins[d])))
    return lo, hi, tuple(faces)


def shrink_wrap(sim):
    faces = sim.system.shrink_faces
    if not faces:
        return
    p = sim.particles
    x = p.x[: p.nlocal]
    box = sim.box
    lo, hi = box.lo.copy(), box.hi.copy()
    beside_lo, beside_hi = np.full(3, math.inf), np.full(3, -math.inf)
    for fix in sim.fixes.values():
        corners = fix.box_extent(sim)
        if corners is not None:
            beside_lo, beside_hi = np.minimum(beside_lo, corners[0]), np.maximum(beside_hi, corners[1])
    for d, side, style, first, margin in faces:
        if side == 0:
            extent = min(sim.comm.min(float(x[:, d].min()) if len(x) else math.inf), float(beside_lo[d]))
            if math.isfinite(extent):
                lo[d] = extent - margin
                if style == "m":
                    lo[d] = min(lo[d], first)
        else:
            extent = max(sim.comm.max(float(x[:, d].max()) if len(x) else -math.inf), float(beside_hi[d]))
            if math.isfinite(extent):
                hi[d] = extent + margin
                if style == "m":
                    hi[d] = max(hi[d], first)
    if not (np.array_equal(lo, box.lo) and np.array_equal(hi, box.hi)):
        box.set_bounds(lo, hi)
