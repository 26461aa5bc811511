r"""Fix ``insert/stream``: a stream of particles entering through a face at a rate (LIGGGHTS's fix
insert/stream).

Syntax::

    fix ID GROUP insert/stream seed S distributiontemplate DIST nparticles N|INF | mass M|INF
        particlerate R | massrate R  insert_every N  vel constant VX VY VZ
        insertion_face MESH  [extrude_length L | duration D]  [general keywords]

``insertion_face`` names a ``fix mesh/surface`` (its triangles as they are at the insertion, moved
or not). The particles of each insertion are placed in the volume the face sweeps when it is pushed
back against the velocity by the extrusion length L: ``extrude_length L`` (distance), or the way
the particles fly in ``duration D`` steps, :math:`L = D\,\Delta t\,|\mathbf{v}|` (LIGGGHTS's default:
D = insert_every, so each insertion fills what the stream empties until the next): a point of the face, drawn with
probability proportional to the triangles' areas, minus :math:`s\,\hat{\mathbf{v}}` with s uniform
on [0, L]. Until it reaches the face, after :math:`s/|\mathbf{v}|`, a particle flies straight at the
insertion velocity, whatever acts on it (its force and torque are zeroed after every force
computation and its velocity reset at the end of the step: LIGGGHTS's release at the face), so the
mass crossing the face per unit time is the inserted rate once the first particles arrive (after
L/|v|), and a stream never overlaps the particles it follows. ``vel constant`` (not parallel to the
face) is required; ``vel uniform|gaussian`` and ``all_in yes`` are refused (a particle must cross
the face at its own depth).

The counts per insertion follow the rate's line as for insert/rate/region (insert_rate_region.py:
never a whole particle off the rate); ``insert_every`` is required. Placement and ranks:
insertion.py.

Example::

    fix inface all mesh/surface file insertion_face.stl type 1
    fix ins all insert/stream seed 32452843 distributiontemplate pdd nparticles 5000 massrate 0.1 &
        insert_every 1000 overlapcheck yes vel constant 0. 0. -1.0 insertion_face inface extrude_length 0.06
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError

from .insertion import FixInsert, number, whole_number
from .insert_rate_region import RATE_ARITY, rate_count, read_rate


@njit(cache=True)
def hold_in_flight(release, time, f, torque):
    """Zero the force and torque of the particles not yet released (release time after ``time``)."""
    for i in range(len(release)):
        if release[i] > time:
            for d in range(3):
                f[i, d] = 0.0
                torque[i, d] = 0.0


@njit(cache=True)
def keep_flying(release, time, v, omega, velocity):
    for i in range(len(release)):
        if release[i] > time:
            for d in range(3):
                v[i, d] = velocity[d]
                omega[i, d] = 0.0


class FixInsertStream(FixInsert):
    name = "insert/stream"
    usage = ("fix ID GROUP insert/stream seed S distributiontemplate DIST nparticles N|INF | mass M|INF "
             "particlerate R | massrate R insert_every N vel constant VX VY VZ insertion_face MESH "
             "[extrude_length L | duration D] [keywords]")
    STYLE_ARITY = {**RATE_ARITY, "insertion_face": 1, "extrude_length": 1, "duration": 1}
    once_by_default = False

    def read_style(self, sim, given):
        if "duration" in given and "extrude_length" in given:
            raise ScriptError("give extrude_length or duration, not both (LIGGGHTS)")
        if "insertion_face" not in given:
            raise ScriptError(f"missing keyword insertion_face; usage: {self.usage}")
        name = given["insertion_face"][0]
        self.face = sim.fixes.get(name)
        if not hasattr(self.face, "triangles") or not hasattr(self.face, "vertices"):
            raise ScriptError(f"insertion_face {name} is not a fix mesh/surface")
        self.extrude_length, self.duration = None, None
        if "extrude_length" in given:
            self.extrude_length = number(given["extrude_length"][0], "extrude_length")
            if not self.extrude_length > 0:
                raise ScriptError(f"extrude_length must be > 0 (got {given['extrude_length'][0]})")
        elif "duration" in given:
            self.duration = whole_number(given["duration"][0], "duration", low=1)
        if "vel" not in given or self.velocity_style != "constant":
            raise ScriptError("insert/stream needs vel constant VX VY VZ (the particles cross the face at it)")
        speed = float(np.linalg.norm(self.velocity_mean))
        if speed == 0.0:
            raise ScriptError("vel constant must not be zero: the particles must cross the insertion face")
        self.direction = self.velocity_mean / speed
        self.speed = speed
        if self.all_in:
            raise ScriptError("all_in yes is not supported by insert/stream")
        read_rate(self, given)
        self.wanted_so_far = 0
        self.release_name = f"release_{self.id}"
        sim.particles.request(self.release_name, ghost=False)

    @property
    def depth(self):
        """The extrusion length: given, or the flight of ``duration`` steps (default insert_every)."""
        if self.extrude_length is not None:
            return self.extrude_length
        return (self.duration or self.every) * self.sim.dt * self.speed

    def events_done_after(self):
        return self.events + 1

    def wanted(self, sim):
        return rate_count(self, sim)

    def _corners(self):
        corners = self.face.vertices[self.face.triangles]
        area = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
        if not area.sum() > 0:
            raise ScriptError(f"insertion_face {self.face.id} has no area")
        normal_part = np.abs(self.face.face_normal @ self.direction)
        if not (normal_part * area).sum() > 1e-12 * area.sum():
            raise ScriptError("vel constant is parallel to the insertion face: no particle would cross it")
        return corners, area

    def extent(self, sim):
        corners, _ = self._corners()
        points = corners.reshape(-1, 3)
        back = points - self.depth * self.direction
        both = np.vstack([points, back])
        return both.min(axis=0), both.max(axis=0)

    def draw_points(self, rng, n):
        corners, area = self._corners()
        which = rng.choice(len(area), size=n, p=area / area.sum())
        u, w = rng.random(n), rng.random(n)
        flip = u + w > 1.0
        u[flip], w[flip] = 1.0 - u[flip], 1.0 - w[flip]
        a, b, c = corners[which, 0], corners[which, 1], corners[which, 2]
        on_face = a + u[:, None] * (b - a) + w[:, None] * (c - a)
        self.pool_depth = self.depth * rng.random(n)
        return on_face - self.pool_depth[:, None] * self.direction

    def clearance(self, points, reach):
        return np.full(len(points), np.inf)

    def _insert(self, sim, count):
        before = sim.particles.nlocal
        super()._insert(sim, count)
        p = sim.particles
        if p.nlocal > before:       # rank 0, which added them in the order they were placed
            flight = self.pool_depth[self.placed_rows] / self.speed
            p.arrays[self.release_name][before:p.nlocal] = sim.time + flight

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        hold_in_flight(p.arrays[self.release_name][:n], sim.time, p.f, p.torque)

    def end_of_step(self, sim):
        p = sim.particles
        n = p.nlocal
        keep_flying(p.arrays[self.release_name][:n], sim.time, p.v, p.omega, self.velocity_mean)
