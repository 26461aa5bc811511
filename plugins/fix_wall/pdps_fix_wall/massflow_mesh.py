r"""Fix ``massflow/mesh``: the mass and the number of particles that pass through a face, a
triangulated surface of a ``fix mesh/surface`` (LIGGGHTS's fix massflow/mesh). It exerts no force.

Each step, after the positions have moved (``post_integrate``), each particle of the group near a
triangle of the face is looked at. The face is planar, and its side is the normal :math:`\mathbf{n}`
of its first triangle, turned to point along ``vec_side`` :math:`\mathbf{s}` (:math:`\mathbf{n}\cdot
\mathbf{s} > 0`). A particle is on that side when :math:`(\mathbf{x}_i - \mathbf{p}_0)\cdot\mathbf{n}
> 0`, :math:`\mathbf{p}_0` the first node of the first triangle. It is counted, its mass
:math:`m_i` added to the mass and 1 to the number, when it comes onto that side from the other one
with the projection of its centre on the triangle's plane inside the triangle; with ``count once`` it
is counted at most once, with ``count multiple`` each time it comes through again.

With ``point_at_outlet PX PY PZ`` the face need not be planar: a particle whose centre is closer
than twice its radius to a triangle (closest point :math:`\mathbf{c}`) is on the outlet side when
:math:`(\mathbf{c} - \mathbf{x}_i)\cdot(\mathbf{x}_i - \mathbf{P}) > 0` (``inside_out``: when it is
< 0), so for a point P outside a closed surface the particles leaving it are counted.

Which particles are near a triangle is decided when the neighbor lists are built, as LIGGGHTS's
mesh neighbor lists do: those whose centre is within :math:`R_i + s/2` (``neighbor SKIN`` s; s for
a moving mesh) of the triangle's plane and of each of its edges. A particle is placed on a side the
first time it is near; one first seen on the counting side is not counted.

Output, the global vector ``f_ID[1..6]`` (``f_ID[0..5]`` in the PDPS dialect): the mass counted
(mass), the number counted, the mass and number rates since the last time the vector was read (mass
per time, 1 per time: the change over the time stepped since then; 0 at the first reading), the mass
and number deleted (``delete_atoms yes``); ``f_ID[7]`` with ``sum_property ID``: the sum of that
``fix property/atom`` scalar over the particles counted.

``file FILE`` (``append FILE``: appended to) writes a line for each particle counted: ID, [time,]
diameter, x y z, vx vy vz, and the value of a per-atom property named color when there is one,
each at %4.4g (LIGGGHTS's columns; with more than one rank each writes FILE.RANK); ``screen yes``
prints the same on screen. ``delete_atoms yes`` (``count once`` only) deletes the particles counted
at the next neighbor list build.

Syntax::

    fix ID GROUP massflow/mesh mesh MESH_ID vec_side VX VY VZ [count once|multiple]
        [point_at_outlet PX PY PZ [inside_out]] [sum_property PROPERTY_ID] [file FILE | append FILE]
        [writeTime] [screen yes|no] [delete_atoms yes|no]

Example::

    fix outlet all mesh/surface file outlet.stl type 1
    fix flow all massflow/mesh mesh outlet count once vec_side 0 0 -1 file flow.txt writeTime
    thermo_style custom step atoms f_flow[1] f_flow[3]

Differences from LIGGGHTS 3.8.0: the number counted is kept in restart files too (LIGGGHTS keeps
the mass and not the number).
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword

from .mesh import closest_on_triangle, face_normals, mesh_fix

# a particle's place with respect to the face: never near it, on the other side, on the counting
# side, counted already (count once)
UNSEEN, BEHIND, AHEAD, COUNTED = -1.0, 0.0, 1.0, 2.0
# barycentric coordinates down to -PRECISION / (2 R_bound) count as inside a triangle (LIGGGHTS's
# precision of its meshes)
PRECISION = 1e-8
PLANAR_TOLERANCE = 1e-8


@njit(cache=True)
def _barycentric_inside(x, a, b, c, tolerance):
    """Whether the projection of x on the plane of triangle abc lies inside it (to ``tolerance``)."""
    e0 = b - a
    e1 = c - a
    p = x - a
    d00 = e0 @ e0
    d01 = e0 @ e1
    d11 = e1 @ e1
    d20 = p @ e0
    d21 = p @ e1
    denominator = d00 * d11 - d01 * d01
    v = (d11 * d20 - d01 * d21) / denominator
    w = (d00 * d21 - d01 * d20) / denominator
    return v > -tolerance and w > -tolerance and 1.0 - v - w > -tolerance


@njit(cache=True)
def near_pairs(x, radius, mask, groupbit, nlocal, corners, normal, edge_normal, reach, pair_triangle,
               pair_particle):
    """The (triangle, particle) pairs of the group's owned particles near each triangle, in triangle
    order: the centre within R + reach of the triangle's plane (through its centroid) and outside
    none of its edges by more than that. Returns their number (the arrays are grown by the caller
    when it is their length)."""
    n = 0
    most = len(pair_triangle)
    for t in range(len(corners)):
        centre = (corners[t, 0] + corners[t, 1] + corners[t, 2]) / 3.0
        for i in range(nlocal):
            if not mask[i] & groupbit:
                continue
            limit = radius[i] + reach
            if abs((x[i] - centre) @ normal[t]) > limit:
                continue
            outside = False
            for e in range(3):
                d = (x[i] - corners[t, e]) @ edge_normal[t, e]
                if d > 0.0 and d * d > limit * limit:
                    outside = True
                    break
            if outside:
                continue
            if n < most:
                pair_triangle[n] = t
                pair_particle[n] = i
            n += 1
    return n


@njit(cache=True)
def pass_through(npairs, pair_triangle, pair_particle, x, radius, rmass, counter, corners, tolerance, side,
                 reference, at_outlet, outlet, inside_out, once, delete, counted):
    """One step's crossings: updates ``counter`` and writes the rows counted into ``counted``;
    returns how many."""
    ncounted = 0
    closest = np.empty(3)
    for k in range(npairs):
        t = pair_triangle[k]
        i = pair_particle[k]
        if counter[i] == COUNTED:
            continue
        a = corners[t, 0]
        b = corners[t, 1]
        c = corners[t, 2]
        if at_outlet:
            closest_on_triangle(x[i, 0], x[i, 1], x[i, 2], a, b, c, closest)
            gap = math.sqrt(((closest - x[i]) ** 2).sum())
            # LIGGGHTS compares the gap less the radius with the radius
            if not gap - radius[i] < radius[i]:
                continue
            dot = (closest - x[i]) @ (x[i] - outlet)
            if inside_out:
                dot = -dot
        else:
            dot = (x[i] - reference) @ side
        if counter[i] == UNSEEN:
            counter[i] = BEHIND if dot <= 0.0 else AHEAD
            continue
        if dot > 0.0 and _barycentric_inside(x[i], a, b, c, tolerance[t]):
            if counter[i] == BEHIND:
                counted[ncounted] = i
                ncounted += 1
                if delete:
                    # seen afresh until it is deleted (LIGGGHTS)
                    counter[i] = UNSEEN
                    continue
            if not delete:
                counter[i] = COUNTED if once else AHEAD
        elif dot <= 0.0:
            counter[i] = BEHIND
    return ncounted


class FixMassflowMesh(Fix):
    name = "massflow/mesh"
    minimize_idle = True
    usage = ("fix ID GROUP massflow/mesh mesh MESH_ID vec_side VX VY VZ [count once|multiple] "
             "[point_at_outlet PX PY PZ [inside_out]] [sum_property ID] [file FILE | append FILE] [writeTime] "
             "[screen yes|no] [delete_atoms yes|no]")

    class Args(StyleArgs):
        mesh: str = keyword(...)
        vec_side: tuple[float, float, float] | None = keyword(None, unit="1")
        count: Literal["once", "multiple"] = keyword("multiple")
        point_at_outlet: tuple[float, float, float] | None = keyword(None, unit="distance")
        inside_out: bool = keyword(False)
        sum_property: str | None = keyword(None)
        file: str | None = keyword(None)
        append: str | None = keyword(None)
        writeTime: bool = keyword(False)
        screen: Literal["yes", "no"] = keyword("no")
        delete_atoms: Literal["yes", "no"] = keyword("no")

    @classmethod
    def respell(cls, dialect, words):
        # writeTime and inside_out stand alone in LIGGGHTS's syntax: yes for the keyword's value
        flags = ("writeTime", "inside_out")
        if not any(word in flags for word in words):
            return None
        spelled = []
        for k, word in enumerate(words):
            spelled.append(word)
            if word in flags and (k + 1 == len(words) or words[k + 1] not in ("yes", "no")):
                spelled.append("yes")
        return cls, spelled

    @classmethod
    def check_args(cls, args):
        once = args.count == "once"
        if args.delete_atoms == "yes" and not once:
            raise ScriptError("delete_atoms yes needs count once")
        if args.point_at_outlet is not None and not once:
            raise ScriptError("point_at_outlet needs count once")
        if args.inside_out and args.point_at_outlet is None:
            raise ScriptError("inside_out has no meaning without point_at_outlet")
        if args.point_at_outlet is None:
            if args.vec_side is None:
                raise ScriptError("expected keyword vec_side (or point_at_outlet)")
            if not any(args.vec_side):
                raise ScriptError("vec_side must not be the zero vector")
        if args.file is not None and args.append is not None:
            raise ScriptError("file and append name the same output: give one")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if "sphere" not in sim.particle_styles:
            raise ScriptError("fix massflow/mesh needs atom_style sphere (per-particle radius and mass)")
        self.surface = mesh_fix(sim, args.mesh)
        self.once = args.count == "once"
        self.delete = args.delete_atoms == "yes"
        self.at_outlet = args.point_at_outlet is not None
        self.outlet = np.array(args.point_at_outlet or (0.0, 0.0, 0.0))
        self.inside_out = args.inside_out
        self.vec_side = np.array(args.vec_side or (0.0, 0.0, 0.0))
        self.property = None
        if args.sum_property is not None:
            self.property = sim.fixes.get(args.sum_property)
            # a fix property/atom scalar, or any fix with one value per particle
            if self.property is None or not callable(getattr(self.property, "peratom", None)):
                raise ScriptError(f"sum_property {args.sum_property}: no fix property/atom of that ID")
        self.screen = args.screen == "yes"
        self.write_time = args.writeTime
        self.output = None
        path = args.file or args.append
        if path is not None:
            shown = path if sim.comm.nprocs == 1 else f"{path}.{sim.comm.rank}"
            try:
                self.output = open(sim.resolve(shown), "a" if args.append else "w")
            except OSError as exc:
                raise ScriptError(f"cannot open {shown}: {exc.strerror}") from None
            self.output.write("# ID" + (" time " if self.write_time else "")
                              + " diameter x y z u v w  (ex ey ez, color)\n")
            self.output.flush()
        self.counter_name = f"massflow_{id}"
        sim.particles.request(self.counter_name, default=UNSEEN)
        self.mass = self.number = self.property_sum = 0.0
        self.mass_last = self.number_last = 0.0
        self.time_counted = self.time_between = 0.0
        self.read_since = True          # LIGGGHTS's reset_t_count_: read since the last step
        self.mass_deleted = self.number_deleted = 0.0
        self.doomed = []                # tags counted with delete_atoms yes, deleted at the next build
        self.pair_triangle = np.zeros(64, dtype=np.int64)
        self.pair_particle = np.zeros(64, dtype=np.int64)
        self.npairs = 0
        self.counted = np.zeros(64, dtype=np.int64)
        self._geometry()

    def _geometry(self):
        """The triangles' corners, normals, outward edge normals and inside tolerances now, the
        reference point and the counting side."""
        surface = self.surface
        corners = np.ascontiguousarray(surface.vertices[surface.triangles])
        normal = face_normals(surface.vertices, surface.triangles)
        edges = np.roll(corners, -1, axis=1) - corners
        edge_normal = np.cross(edges, normal[:, None, :])
        edge_normal /= np.linalg.norm(edge_normal, axis=2)[:, :, None]
        centre = corners.mean(axis=1)
        bound = np.linalg.norm(corners - centre[:, None, :], axis=2).max(axis=1)
        self.corners, self.normal, self.edge_normal = corners, normal, np.ascontiguousarray(edge_normal)
        self.tolerance = PRECISION / (2.0 * bound)
        self.reference = corners[0, 0].copy()
        self.side = normal[0].copy()
        if not self.at_outlet:
            dot = float(self.side @ self.vec_side)
            if abs(dot) < 1e-6:
                raise ScriptError(f"fix {self.id} massflow/mesh: vec_side lies in (or too close to) the plane of "
                                  f"mesh {self.surface.id}")
            if dot < 0.0:
                self.side = -self.side

    def init_run(self, sim):
        if not self.at_outlet:
            distance = np.abs((self.corners.reshape(-1, 3) - self.reference) @ self.side)
            size = float(np.ptp(self.corners.reshape(-1, 3), axis=0).max())
            if distance.max() > PLANAR_TOLERANCE * size:
                raise ScriptError(f"fix {self.id} massflow/mesh: mesh {self.surface.id} is not planar (a node "
                                  f"lies {distance.max():.3g} from the plane of its first triangle): use "
                                  "point_at_outlet")

    def setup(self, sim):
        self._near(sim)

    def pre_neighbor(self, sim):
        self._near(sim)

    def _near(self, sim):
        """The pairs of particles and triangles near each other, as at a neighbor list build."""
        if self.surface.moving:
            self._geometry()
        reach = sim.neighbor.skin if self.surface.moving else 0.5 * sim.neighbor.skin
        p = sim.particles
        args = (p.x, p.radius, p.mask, sim.groups.bit(self.group), p.nlocal, self.corners, self.normal,
                self.edge_normal, reach)
        n = near_pairs(*args, self.pair_triangle, self.pair_particle)
        if n > len(self.pair_triangle):
            self.pair_triangle = np.zeros(n + n // 4, dtype=np.int64)
            self.pair_particle = np.zeros(n + n // 4, dtype=np.int64)
            near_pairs(*args, self.pair_triangle, self.pair_particle)
        self.npairs = n
        if len(self.counted) < p.nlocal:
            self.counted = np.zeros(p.nlocal + p.nlocal // 4 + 16, dtype=np.int64)

    def post_integrate(self, sim):
        p = sim.particles
        if self.surface.moving:
            self._geometry()
        self.time_counted += sim.dt
        if not self.read_since:
            self.mass_last, self.number_last = self.mass, self.number
            self.read_since = True
        counter = p.arrays[self.counter_name]
        n = pass_through(self.npairs, self.pair_triangle, self.pair_particle, p.x, p.radius, p.rmass, counter,
                         self.corners, self.tolerance, self.side, self.reference, self.at_outlet, self.outlet,
                         self.inside_out, self.once, self.delete, self.counted)
        rows = self.counted[:n]
        mass = float(p.rmass[rows].sum()) if n else 0.0
        value = float(self.property.peratom(sim)[rows].sum()) if (n and self.property is not None) else 0.0
        if n:
            if self.delete:
                self.doomed.extend(int(t) for t in p.tag[rows])
            if self.output is not None or self.screen:
                self._write(sim, rows)
        mass, number, value = sim.comm.sum(np.array([mass, float(n), value]))
        self.mass += mass
        self.number += number
        self.property_sum += value

    def _write(self, sim, rows):
        p = sim.particles
        colors = p.arrays["color"][: p.nlocal] if p.has("color") else None
        for i in rows:
            values = (2.0 * p.radius[i], *p.x[i], *p.v[i])
            if self.screen:
                sim.info(f" {int(p.tag[i])} " + " ".join(f"{v:4.4g}" for v in values))
            if self.output is not None:
                time = f"  {sim.dt * sim.step:4.4g} " if self.write_time else ""
                line = f"{int(p.tag[i])}{time} " + " ".join(f"{v:4.4g}" for v in values)
                if colors is not None:
                    line += f"    {colors[i]:4.0g} "
                self.output.write(line + "\n")
        if self.output is not None:
            self.output.flush()

    def pre_exchange(self, sim):
        if not self.delete or not self.doomed:
            return
        p = sim.particles
        gone = np.isin(p.tag[:p.nlocal], np.array(self.doomed, dtype=np.int64))
        mass, number = sim.comm.sum(np.array([float(p.rmass[:p.nlocal][gone].sum()), float(gone.sum())]))
        self.doomed = []
        if number:
            sim.delete_particles(np.flatnonzero(gone))
        self.mass_deleted += mass
        self.number_deleted += number

    def vector(self, sim):
        if self.read_since:
            self.time_between, self.time_counted = self.time_counted, 0.0
            self.read_since = False
        between = self.time_between
        rates = ((self.mass - self.mass_last) / between, (self.number - self.number_last) / between) \
            if between else (0.0, 0.0)
        values = [self.mass, self.number, *rates, self.mass_deleted, self.number_deleted]
        if self.property is not None:
            values.append(self.property_sum)
        return np.array(values)

    def state(self):
        return {"mass": self.mass, "number": self.number, "time_counted": self.time_counted,
                "mass_last": self.mass_last, "number_last": self.number_last, "mass_deleted": self.mass_deleted,
                "number_deleted": self.number_deleted, "property_sum": self.property_sum}

    def restore(self, state):
        self.mass, self.number = state["mass"], state["number"]
        self.time_counted, self.mass_last, self.number_last = (state["time_counted"], state["mass_last"],
                                                               state["number_last"])
        self.mass_deleted, self.number_deleted = state["mass_deleted"], state["number_deleted"]
        self.property_sum = state["property_sum"]
