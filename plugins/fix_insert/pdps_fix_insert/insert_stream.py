r"""Fix ``insert/stream``: a stream of particles entering through a face at a rate (LIGGGHTS's fix
insert/stream).

Syntax::

    fix ID GROUP insert/stream seed S distributiontemplate DIST nparticles N|INF | mass M|INF
        particlerate R | massrate R  vel constant VX VY VZ  insertion_face MESH
        insert_every N [duration D] | extrude_length L  [parallel yes|no] [general keywords]

``insertion_face`` names a planar ``fix mesh/surface``; its normal :math:`\hat{\mathbf{n}}` is turned
so that :math:`\mathbf{v}\cdot\hat{\mathbf{n}} > 0`, and the particles enter with the insertion
velocity's normal part :math:`\mathbf{v}_n = (\mathbf{v}\cdot\hat{\mathbf{n}})\hat{\mathbf{n}}`
(LIGGGHTS's ``v_normal``). The particles of each insertion are placed in the volume the face sweeps
when pushed back along :math:`-\hat{\mathbf{n}}` by the extrusion length L, a sphere of radius r at a
point of the face (triangles by area) minus :math:`d\,\hat{\mathbf{n}}`, the depth :math:`d = uL + r`
with ``overlapcheck yes`` and :math:`d = u(L - 2r) + r` without, u uniform on [0, 1) (LIGGGHTS's
``generate_random``). With the overlap check a centre less than r from a face of the simulation box
is a failed try, without it a centre outside the box (LIGGGHTS's tests against its subdomain, here
the box on any rank count). As in LIGGGHTS, exactly one of ``insert_every`` and ``extrude_length``
is given and fixes the other: :math:`L = D\,\Delta t\,|\mathbf{v}_n|` with ``duration`` D (default
insert_every, D <= insert_every; L at least twice the largest radius), or insert_every =
:math:`\lfloor L / (\Delta t\,|\mathbf{v}_n|)\rfloor` (L at least 3 times the largest radius with
the overlap check). A particle flies straight at :math:`\mathbf{v}_n`, with no spin, whatever acts
on it, for :math:`\lfloor d / (\Delta t\,|\mathbf{v}_n|)\rfloor` whole steps: at the end of each its
position is put back where that flight has carried it from its insertion, and its force and torque
are zeroed (LIGGGHTS's ``end_of_step``); at the end of the last it takes the velocity it was
inserted with (``vel constant``, or drawn by ``vel uniform|gaussian`` at the insertion, from the
same stream as its position) and the ``omega`` given, and is free from then on. So the mass
crossing the face per unit time is the inserted rate once the first particles arrive. ``all_in
yes`` is refused.

The count per insertion is rounded at random to the rate as for insert/rate/region
(insert_rate_region.py, as LIGGGHTS). Placement and ranks: insertion.py.

Example (LIGGGHTS's chute tutorial)::

    fix inface all mesh/surface file meshes/insertion_face.stl type 1
    fix ins nve_group insert/stream seed 5330 distributiontemplate pdd1 nparticles 6000 massrate 0.1 &
        insert_every 1000 overlapcheck yes all_in no vel constant 0.0 0.0 -1.0 insertion_face inface
"""

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, TriangleSurface, keyword

from .insertion import FixInsert, YesNo
from .whole_number import WholeNumber
from .insert_rate_region import RateArgs, check_rate, rate_count, read_rate


# columns of the per-particle flight record: in flight (1) or free (0), release time, insertion
# time, insertion position (3), velocity and angular velocity to take at the face (3 + 3)
FLYING, RELEASE, INSERTED, START, VELOCITY, SPIN, FLIGHT_WIDTH = 0, 1, 2, 3, 6, 9, 12


@njit(cache=True)
def fly(record, time, dt, x, v, omega, f, torque, v_normal):
    """LIGGGHTS's flight to the face (its end_of_step): a particle in flight is where the insertion
    velocity's normal part has carried it, moving at it, with no spin, force or torque; at its
    release step it is put where the flight ends, takes the velocity and spin it was inserted with,
    with no force or torque, and is free from then on."""
    for i in range(record.shape[0]):
        if record[i, FLYING] == 0.0:
            continue
        release = record[i, RELEASE]
        flying = time < release - 0.5 * dt
        flown = (time if flying else release) - record[i, INSERTED]
        for d in range(3):
            x[i, d] = record[i, START + d] + v_normal[d] * flown
            f[i, d] = 0.0
            torque[i, d] = 0.0
            if flying:
                v[i, d] = v_normal[d]
                omega[i, d] = 0.0
            else:
                v[i, d] = record[i, VELOCITY + d]
                omega[i, d] = record[i, SPIN + d]
        if not flying:
            record[i, FLYING] = 0.0


class FixInsertStream(FixInsert):
    name = "insert/stream"
    usage = ("fix ID GROUP insert/stream seed S distributiontemplate DIST nparticles N|INF | mass M|INF "
             "particlerate R | massrate R vel constant VX VY VZ insertion_face MESH "
             "insert_every N [duration D] | extrude_length L [keywords]")
    once_by_default = False

    class Args(RateArgs):
        insertion_face: str = keyword(..., names="fix mesh/surface ID")
        extrude_length: float | None = keyword(None, gt=0, unit="distance")
        duration: WholeNumber | None = keyword(None, ge=1, unit="timesteps")
        # LIGGGHTS's share of the extrusion among its ranks; pdps places the same particles on any
        # rank count, so it is read and has no effect
        parallel: YesNo = keyword("no")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if args.extrude_length is not None and args.insert_every is not None:
            raise ScriptError("must not provide both 'insert_every' and 'extrude_length' (LIGGGHTS)")
        if args.extrude_length is None and args.insert_every is None:
            raise ScriptError("must define either 'insert_every' or 'extrude_length' (LIGGGHTS)")
        if args.extrude_length is not None and args.duration is not None:
            raise ScriptError("must not provide both 'extrude_length' and 'duration' (LIGGGHTS)")
        if args.duration is not None and isinstance(args.insert_every, int) and args.duration > args.insert_every:
            raise ScriptError(f"duration must not exceed insert_every (got {args.duration} > {args.insert_every})")
        if args.vel is None:
            raise ScriptError("insert/stream needs vel constant|uniform|gaussian: the particles cross the face at it")
        if args.all_in == "yes":
            raise ScriptError("all_in yes is not supported by insert/stream")
        check_rate(cls, args)

    def read_style(self, sim, args):
        name = args.insertion_face
        self.face = sim.fixes.get(name)
        if not isinstance(self.face, TriangleSurface):
            raise ScriptError(f"insertion_face {name} is not a fix mesh/surface")
        self.extrude_length, self.duration = args.extrude_length, args.duration
        normals = self.face.face_normal
        if not (np.abs(normals @ normals[0]) > 1.0 - 1e-6).all():
            raise ScriptError(f"insertion_face {name} must be planar (LIGGGHTS)")
        self.face_point = self.face.vertices[self.face.triangles[0, 0]]
        normal = normals[0] if normals[0] @ self.velocity_mean >= 0 else -normals[0]
        along = float(normal @ self.velocity_mean)
        if along < 1e-3:
            raise ScriptError(f"the insertion velocity projected on the face normal is {along:.3g}, less "
                              "than 1e-3 (LIGGGHTS): no particle would cross the face")
        self.normal = normal
        self.v_normal = along * normal                # LIGGGHTS's v_normal: the particles' flight
        self.speed = along
        read_rate(self, args)
        self.wanted_so_far = 0
        # with the overlap check a centre keeps its radius from the box's faces, without it it keeps
        # inside the box (LIGGGHTS's tests against its subdomain)
        self.border = 1.0 if self.overlap_check else 0.0
        self.flight_name = f"flight_{self.id}"
        sim.particles.request(self.flight_name, width=FLIGHT_WIDTH, ghost=False)
        self.release_watchers = []

    def watch_releases(self, callback):
        """Have ``callback(sim, rows, release_steps)`` called on every rank after each insertion, with
        the rows of the particles this rank added (a slice; empty on the ranks that add none) and the
        steps at which they cross the face (LIGGGHTS's tracer callback of fix insert/stream, which
        fix property/atom/tracer/stream marks by)."""
        self.release_watchers.append(callback)

    def setup(self, sim):
        largest = self.distribution.max_radius
        if self.extrude_length is not None:
            self.every = int((self.extrude_length + 1e-13) / (sim.dt * self.speed))
            if self.every < 1:
                raise ScriptError("insertion velocity too high or extrude_length too low (LIGGGHTS)")
            if self.overlap_check and self.extrude_length < 3.0 * largest:
                raise ScriptError(f"extrude_length {self.extrude_length:g} is too small: at least 3 times the "
                                  f"largest radius {largest:g} with overlapcheck yes (LIGGGHTS)")
        elif (self.duration or self.every) * sim.dt * self.speed < 2.0 * largest:
            raise ScriptError(f"insert_every or vel is too small, or the particles too large: the extrusion "
                              f"{(self.duration or self.every) * sim.dt * self.speed:g} is less than twice the "
                              f"largest radius {largest:g} (LIGGGHTS)")
        super().setup(sim)

    @property
    def depth(self):
        """The extrusion length: given, or the flight of ``duration`` steps (default insert_every)."""
        if self.extrude_length is not None:
            return self.extrude_length
        return (self.duration or self.every) * self.sim.dt * self.speed

    def wanted(self, sim):
        return rate_count(self, sim)

    def _corners(self):
        corners = self.face.vertices[self.face.triangles]
        area = 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
        if not area.sum() > 0:
            raise ScriptError(f"insertion_face {self.face.id} has no area")
        return corners, area

    def extent(self, sim):
        corners, _ = self._corners()
        points = corners.reshape(-1, 3)
        back = points - (self.depth + self.distribution.max_radius) * self.normal
        both = np.vstack([points, back])
        return both.min(axis=0), both.max(axis=0)

    def draw_points(self, rng, n):
        return self.draw_candidates(rng, n)[0]

    def draw_candidates(self, rng, n):
        """A point of the face (triangles by area) pushed back by u L, and the shift by the sphere's
        radius: back by r more with the overlap check, by r (1 - 2u) without (LIGGGHTS's depths
        u L + r and u (L - 2r) + r)."""
        corners, area = self._corners()
        which = rng.choice(len(area), size=n, p=area / area.sum())
        u, w = rng.random(n), rng.random(n)
        flip = u + w > 1.0
        u[flip], w[flip] = 1.0 - u[flip], 1.0 - w[flip]
        a, b, c = corners[which, 0], corners[which, 1], corners[which, 2]
        on_face = a + u[:, None] * (b - a) + w[:, None] * (c - a)
        back = rng.random(n)
        points = on_face - (self.depth * back)[:, None] * self.normal
        reach = np.ones(n) if self.overlap_check else 1.0 - 2.0 * back
        return points, -reach[:, None] * self.normal

    def clearance(self, points, reach):
        return np.full(len(points), np.inf)

    def _insert(self, sim, count):
        before = sim.particles.nlocal
        super()._insert(sim, count)
        p = sim.particles
        steps = np.zeros(0)
        if p.nlocal > before:       # rank 0, which added them in the order they were placed
            new = slice(before, p.nlocal)
            record = p.arrays[self.flight_name]
            # released at the last step before the face: LIGGGHTS's whole steps of flight
            depth = (self.face_point - p.x[new]) @ self.normal
            steps = np.floor((depth + 1e-14) / (self.speed * sim.dt))
            record[new, FLYING] = 1.0
            record[new, RELEASE] = sim.time + steps * sim.dt
            record[new, INSERTED] = sim.time
            record[new, START:START + 3] = p.x[new]
            record[new, VELOCITY:VELOCITY + 3] = p.v[new]
            record[new, SPIN:SPIN + 3] = p.omega[new]
            p.v[new] = self.v_normal
            p.omega[new] = 0.0
        for callback in self.release_watchers:
            callback(sim, slice(before, p.nlocal), sim.step + steps.astype(np.int64))

    def end_of_step(self, sim):
        p = sim.particles
        n = p.nlocal
        fly(p.arrays[self.flight_name][:n], sim.time, sim.dt, p.x, p.v, p.omega, p.f, p.torque, self.v_normal)
