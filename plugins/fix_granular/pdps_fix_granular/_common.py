"""What several styles of this pack share: the particles a force fix acts on and when it acts, axis
names, and the checks for finite-size particles."""

from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError

Axis = Literal["x", "y", "z"]
AXES = {"x": 0, "y": 1, "z": 2}


class ForceFix(Fix):
    """A fix whose post_force also acts at a run's setup and in each minimization step (LAMMPS's
    addforce, setforce, viscous)."""

    original = None     # set (np.zeros(3)) by a fix that offers LAMMPS's vector of the force it found

    def keep_original(self, f, selected):
        """Remember this rank's total force on ``selected`` before the fix changes it."""
        self.original[:] = f[selected].sum(axis=0)

    def original_force(self, sim):
        """LAMMPS's vector of addforce, setforce and aveforce (``f_ID[1-3]``): the group's total force
        before the fix changed it, at the last step the fix acted."""
        return sim.comm.sum(self.original)

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)


def chosen(sim, group, region=None):
    """Boolean mask over owned particles: in ``group`` and, when ``region`` is given, inside it now."""
    selected = sim.groups.select(sim, group)
    if region is not None:
        p = sim.particles
        selected &= np.asarray(sim.region(region).match(p.x[: p.nlocal]), dtype=bool)
    return selected


NO_RMASS = np.zeros(0)


@njit(cache=True)
def add_weight(f, type_, type_mass, rmass, mask, groupbit, nlocal, ax, ay, az):
    """f += m a on the group's owned particles, m = rmass[i] when given (non-empty), else the type's
    mass (every step of a granular run: no temporaries; a zero component of a is not added, which
    saves a third of the work per axis)."""
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        if mask[i] & groupbit:
            m = rmass[i] if with_rmass else type_mass[type_[i]]
            if ax != 0.0:
                f[i, 0] += m * ax
            if ay != 0.0:
                f[i, 1] += m * ay
            if az != 0.0:
                f[i, 2] += m * az


@njit(cache=True)
def add_weight_unbound(f, type_, type_mass, rmass, mask, groupbit, bound, nlocal, ax, ay, az):
    """add_weight for the particles outside bodies (``bound[i] < 0``): a fix multisphere applies
    the weight of its bodies' spheres to the bodies themselves (LIGGGHTS's fix gravity skips them)."""
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        if mask[i] & groupbit and bound[i] < 0:
            m = rmass[i] if with_rmass else type_mass[type_[i]]
            f[i, 0] += m * ax
            f[i, 1] += m * ay
            f[i, 2] += m * az


def require_spheres(sim, what):
    """Per-particle radius and mass exist only with particle_style sphere (set before the box)."""
    p = sim.particles
    if not (p.has("radius") and p.has("rmass")):
        raise ScriptError(f"{what} needs finite-size particles (per-particle radius and mass): "
                          "use particle_style sphere before creating the box")


def require_radii(sim, group, what):
    """Every particle of the group must have a radius > 0 (their moment of inertia divides by it)."""
    p = sim.particles
    selected = sim.groups.select(sim, group)
    bad = selected & ~(p.radius[: p.nlocal] > 0.0)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ScriptError(f"{what} needs finite-size particles: particle {int(p.tag[i])} has "
                          f"radius {p.radius[i]:g}")


def require_plane(sim, axis, what):
    if sim.dimension == 2 and axis == "z":
        raise ScriptError(f"{what} along z in a 2-d simulation would move particles out of the plane")
