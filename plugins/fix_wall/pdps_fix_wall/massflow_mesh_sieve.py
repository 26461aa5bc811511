r"""Fix ``massflow/mesh/sieve``: a sieve, a face of a ``fix mesh/surface`` with round holes that
lets a particle through with a probability and holds the others back by a spring-dashpot, counting
those that pass as fix massflow/mesh does (LIGGGHTS's fix massflow/mesh/sieve, from its source).

A particle of the group that touches a triangle of the face (distance :math:`d` from its centre to
the triangle :math:`\le R`) for the first time since it last left one is let through with the
probability of holes of diameter :math:`S` (``sieveSize``) at spacing :math:`L` (``sieveSpacing``)
for its diameter :math:`2R`, the area that lets its centre pass over the area per hole:

.. math:: P = \frac{\pi}{4}\,\frac{(S - 2R)^2}{L^2} \quad (S > 2R), \qquad P = 0 \quad (S \le 2R)

(LIGGGHTS's :math:`\pi/4` is 0.78539816339; :math:`P > 1` passes every time). A particle drawn
to pass is never held back by the sieve again. One that is held back feels, while it touches that
triangle, the force

.. math:: \mathbf{F} = -F_n\,\mathbf{n}, \quad F_n = \max(0,\; k\,(R - d) + c\,\mathbf{v}\cdot\mathbf{n}),
          \quad \mathbf{n} = (\mathbf{c} - \mathbf{x})/R

with :math:`k` ``sieveStiffness`` (force/distance), :math:`c` ``sieveDamping`` (force/velocity),
:math:`\mathbf{c}` the closest point of the triangle. A touch counts on a triangle's face (the centre's
projection inside it, to LIGGGHTS's mesh precision, as fix massflow/mesh decides it) and on its
edges and corners only where the edge belongs to no other triangle of the mesh (the sieve's
border): LIGGGHTS leaves the edges between its flat mesh's triangles out (inactive edges), so a
particle off the seam of two triangles touches one, not both (measured: pdps counting both departs
from LIGGGHTS's thermo), and one right over the seam touches both faces and feels both forces. :math:`\mathbf{n}` is divided by :math:`R`
and not by :math:`d`, as in LIGGGHTS, so it is slightly shorter than a unit vector. When it leaves
that triangle it is drawn again at its next touch. The force is added at ``post_force``; particles
counted already with ``count once`` feel none. With ``sieveMultiSphereCanPass`` the spheres of a fix
multisphere's bodies are drawn like the others; without it they are always held back.

The draws are uniform numbers keyed by (seed 15485863, step, particle id): the same on any number of
ranks and in any order, but not LIGGGHTS's numbers, which come from one Park-Miller stream of that
seed drawn in the order of its mesh neighbor lists. So a scene where some pass and some do not
agrees with LIGGGHTS in its statistics, not particle by particle; where :math:`P = 0` or
:math:`P \ge 1` it agrees exactly.

Everything else (counting, output vector, file, delete_atoms) is fix massflow/mesh's.

Checked against LIGGGHTS 3.8.0: the recorded cases sieve_held (probability 0: the bed of cases.py
bounces off a tilted sieve, thermo to 1e-8) and sieve_pass (probability above 1: counted as
massflow/mesh counts), and the share of 1600 spheres let through at P = 0.349 (pdps 561, LIGGGHTS
582, n P = 558.5, one standard deviation 19). The multisphere rule (bodies held back unless
``sieveMultiSphereCanPass``) is LIGGGHTS's source read, not measured.

Syntax::

    fix ID GROUP massflow/mesh/sieve mesh MESH_ID (vec_side VX VY VZ | point_at_outlet PX PY PZ)
        [massflow/mesh keywords] sieveSize S sieveSpacing L sieveStiffness K [sieveDamping C]
        [sieveMultiSphereCanPass]

``sieveSize``, ``sieveSpacing`` and ``sieveStiffness`` are required (0 to 1e5, 1e5 and 1e10, as
LIGGGHTS checks). LIGGGHTS takes the sieve keywords only after all of massflow/mesh's; pdps takes
them in any order.

Example (LIGGGHTS's manual)::

    fix massFlow1 all massflow/mesh/sieve mesh massFlow1M point_at_outlet 0 0 -1000 count once
        delete_atoms no file massFlow1.dat sieveSize 2e-3 sieveSpacing 2.5e-3 sieveStiffness 1e5
        sieveDamping 1e3
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, keyword, particle_uniforms

from .massflow_mesh import COUNTED, FixMassflowMesh, _barycentric_inside
from .mesh import closest_on_triangle

SEED = 15485863            # LIGGGHTS's, written into its source
STREAM = 0
PI_OVER_FOUR = 0.78539816339
# a particle's state with respect to the sieve: free (draw at the next touch), passing
FREE, PASSING = -1.0, 0.0
# a point this close to an edge (squared, relative to the edge's length squared) lies on it
EDGE_TOLERANCE = 1e-20


@njit(cache=True)
def pass_probability(radius, size, spacing):
    opening = size - 2.0 * radius
    if opening > 0.0:
        return opening * opening * PI_OVER_FOUR / (spacing * spacing)
    return 0.0


@njit(cache=True)
def _on_open_edge(point, corners, open_edge):
    """Whether ``point`` (on the triangle's border) lies on one of its edges that no other
    triangle shares."""
    for e in range(3):
        if not open_edge[e]:
            continue
        a = corners[e]
        b = corners[(e + 1) % 3]
        ab = b - a
        s = min(1.0, max(0.0, ((point - a) @ ab) / (ab @ ab)))
        gap = point - (a + s * ab)
        if gap @ gap <= EDGE_TOLERANCE * (ab @ ab):
            return True
    return False


@njit(cache=True)
def sieve_forces(npairs, pair_triangle, pair_particle, x, v, f, radius, tag, counter, held, in_body, can_pass,
                 corners, tolerance, open_edge, size, spacing, stiffness, damping, key, step):
    """The sieve's force on the particles touching it; ``held`` is 1 + the triangle holding a
    particle back, PASSING or FREE."""
    closest = np.empty(3)
    for k in range(npairs):
        t = pair_triangle[k]
        i = pair_particle[k]
        if counter[i] == COUNTED:
            continue
        closest_on_triangle(x[i, 0], x[i, 1], x[i, 2], corners[t, 0], corners[t, 1], corners[t, 2], closest)
        delta = closest - x[i]
        face = _barycentric_inside(x[i], corners[t, 0], corners[t, 1], corners[t, 2], tolerance[t])
        if not face and not _on_open_edge(closest, corners[t], open_edge[t]):
            continue
        overlap = radius[i] - math.sqrt(delta @ delta)
        if overlap >= 0.0:
            if held[i] < 0.0:
                u = particle_uniforms(key, step, tag[i], STREAM)[0]
                if in_body[i] and not can_pass:
                    held[i] = 1.0 + t
                elif u < pass_probability(radius[i], size, spacing):
                    held[i] = PASSING
                    continue
                else:
                    held[i] = 1.0 + t
            elif held[i] == PASSING:
                continue
            normal = delta / radius[i]
            fn = damping * (v[i] @ normal) + stiffness * overlap
            if fn < 0.0:
                fn = 0.0
            f[i] -= fn * normal
        elif held[i] == 1.0 + t:
            held[i] = FREE


class FixMassflowMeshSieve(FixMassflowMesh):
    name = "massflow/mesh/sieve"
    usage = FixMassflowMesh.usage.replace("massflow/mesh", "massflow/mesh/sieve") + (
        " sieveSize S sieveSpacing L sieveStiffness K [sieveDamping C] [sieveMultiSphereCanPass]")

    class Args(FixMassflowMesh.Args):
        sieveSize: float | None = keyword(None, unit="distance")
        sieveSpacing: float | None = keyword(None, unit="distance")
        sieveStiffness: float | None = keyword(None, unit="force/distance")
        sieveDamping: float = keyword(0.0, unit="force/velocity")
        sieveMultiSphereCanPass: bool = keyword(False)

    @classmethod
    def respell(cls, dialect, words):
        flag = "sieveMultiSphereCanPass"
        spelled = []
        for k, word in enumerate(words):
            spelled.append(word)
            if word == flag and (k + 1 == len(words) or words[k + 1] not in ("yes", "no")):
                spelled.append("yes")
        found = FixMassflowMesh.respell.__func__(cls, dialect, spelled)
        return found if found is not None else ((cls, spelled) if flag in words else None)

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        for name, top in (("sieveSize", 1e5), ("sieveSpacing", 1e5), ("sieveStiffness", 1e10)):
            value = getattr(args, name)
            if value is None or not 0.0 <= value <= top:
                raise ScriptError(f"'{name}' is not set, larger than {top:g}, or less than zero"
                                  + ("" if value is None else f" (got {value:g})"))
        if args.sieveSpacing == 0.0:
            raise ScriptError("'sieveSpacing' must be > 0 (it divides the passage probability)")
        if not math.isfinite(args.sieveDamping):
            raise ScriptError(f"'sieveDamping' must be finite (got {args.sieveDamping})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.held_name = f"massflowSieve_{id}"
        sim.particles.request(self.held_name, default=FREE)
        # edges that no other triangle shares: LIGGGHTS's active edges of a flat mesh
        triangles = np.asarray(self.surface.triangles)
        edges = np.sort(np.stack([triangles, np.roll(triangles, -1, axis=1)], axis=2), axis=2).reshape(-1, 2)
        _, where, count = np.unique(edges, axis=0, return_inverse=True, return_counts=True)
        self.open_edge = (count[where.ravel()] == 1).reshape(-1, 3)
        self.no_body = np.zeros(0, dtype=np.bool_)      # no particle in a multisphere body

    def post_force(self, sim):
        p = sim.particles
        if self.surface.moving:
            self._geometry()
        if p.has("body_mass"):
            in_body = p.body_mass[:p.nlocal] > 0.0
        else:
            if len(self.no_body) < p.nlocal:
                self.no_body = np.zeros(p.nlocal + p.nlocal // 4 + 16, dtype=np.bool_)
            in_body = self.no_body
        a = self.args
        sieve_forces(self.npairs, self.pair_triangle, self.pair_particle, p.x, p.v, p.f, p.radius, p.tag,
                     p.arrays[self.counter_name], p.arrays[self.held_name], in_body, a.sieveMultiSphereCanPass,
                     self.corners, self.tolerance, self.open_edge, a.sieveSize, a.sieveSpacing, a.sieveStiffness, a.sieveDamping,
                     sim.random_key(SEED), sim.step)
