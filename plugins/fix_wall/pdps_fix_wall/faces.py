"""Flat walls on box faces, as LAMMPS's fix wall/* give them: ``face coord`` with coord a number or
EDGE, scaled by the lattice spacing in ``units lattice``."""

from typing import Literal

import numpy as np

from pdps_core.api import ScriptError

FACES = ("xlo", "xhi", "ylo", "yhi", "zlo", "zhi")
Face = Literal["xlo", "xhi", "ylo", "yhi", "zlo", "zhi"]


def check_walls(walls):
    """The entries ``face coord epsilon sigma cutoff`` of wall/harmonic and wall/lj*: each cutoff > 0,
    each face once."""
    for face, _, _, _, cutoff in walls:
        if cutoff <= 0:
            raise ValueError(f"wall {face}: cutoff must be > 0 (got {cutoff:g})")
    once_each((face, coord) for face, coord, *_ in walls)


def once_each(walls):
    """The walls ``[(face, coord), ...]`` as ``{face: coord}`` in the order given; a face given
    twice is an error."""
    given = {}
    for face, value in walls:
        if face in given:
            raise ValueError(f"wall {face} is given twice")
        given[face] = value
    return given


def wall_planes(sim, coords, units):
    """(axes, lower, positions) arrays of the walls ``{face: number or "EDGE"}``, in that order."""
    spacing = sim.lattice.spacing if (units == "lattice" and sim.lattice is not None) else np.ones(3)
    axes, lower, positions = [], [], []
    for face, value in coords.items():
        axis = FACES.index(face) // 2
        if axis == 2 and sim.dimension == 2:
            raise ScriptError(f"wall {face} in a 2-d simulation")
        is_lo = face.endswith("lo")
        if value == "EDGE":
            value = float((sim.box.lo if is_lo else sim.box.hi)[axis])
        else:
            value *= float(spacing[axis])
        axes.append(axis)
        lower.append(is_lo)
        positions.append(value)
    return np.array(axes, dtype=np.int64), np.array(lower, dtype=np.bool_), np.array(positions, dtype=np.float64)
