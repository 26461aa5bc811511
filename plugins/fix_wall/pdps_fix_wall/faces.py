"""Flat walls on box faces, as LAMMPS's fix wall/* give them: ``face coord`` with coord a number or
EDGE, scaled by the lattice spacing in ``units lattice``."""

from typing import Literal

import numpy as np

from pydantic import model_validator

from pdps_core.api import Fix, ScriptError, StyleArgs

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


def check_order(faces, coords):
    """Each axis with both walls among ``faces`` (in the order of ``coords``, their positions) has
    its lo wall below its hi wall."""
    position = dict(zip(faces, coords))
    for name in "xyz":
        lo, hi = position.get(f"{name}lo"), position.get(f"{name}hi")
        if lo is not None and hi is not None and not lo < hi:
            raise ScriptError(f"{name}lo must be below {name}hi (got {lo:g} {hi:g})")


class PotentialWallArgs(StyleArgs):
    """What wall/harmonic and wall/lj93, wall/lj126 check of their ``wall`` entries (face coord
    epsilon sigma cutoff ...): each face once, every cutoff > 0."""

    @model_validator(mode="after")
    def _walls(self):
        check_walls(self.wall)
        return self


class PotentialWalls(Fix):
    """What walls with a potential share: forces at setup and in minimization, their energy and
    virial in thermo, f_ID their total energy and f_ID[k] the force on wall k (``wall_energy``,
    ``wall_virial`` and ``wall_force``, which post_force fills)."""
    can_energy = True
    can_virial = True
    extensive = True        # f_ID and f_ID[k] are totals: per particle where thermo normalises (lj)

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def compute_energy(self, sim):
        return self.wall_energy

    def compute_virial(self, sim):
        return self.wall_virial

    def scalar(self, sim):
        """The walls' total energy (f_ID), summed over ranks."""
        return float(sim.comm.sum(self.wall_energy))

    def vector(self, sim):
        """The force on each wall (f_ID[k]), summed over ranks."""
        return np.array(sim.comm.sum(self.wall_force), dtype=float)


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
