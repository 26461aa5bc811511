r"""Fix ``mesh/surface/stress``: a ``fix mesh/surface`` that also sums the forces the particles exert
on it (LIGGGHTS's fix mesh/surface/stress).

Each step, every wall fix acting through this mesh adds the force of each contact on the wall,
:math:`-\mathbf{F}_c` (:math:`\mathbf{F}_c` the contact force on the particle), to the triangle it
touches, and its torque :math:`(\mathbf{p}_c - \mathbf{r}_0)\times(-\mathbf{F}_c)` about the reference
point :math:`\mathbf{r}_0` (contact point :math:`\mathbf{p}_c` on the triangle). From them:

- the global vector ``f_ID[1..6]`` (LAMMPS/LIGGGHTS dialect; ``f_ID[0..5]`` in PDPS's): total force
  :math:`\sum -\mathbf{F}_c` on the mesh (force units) and total torque about :math:`\mathbf{r}_0`
  (force x distance), as LIGGGHTS lists them, for thermo, variables and fix ave/time;
- per triangle, written by ``dump vtk ... walls yes`` as cell data: ``force`` (3 values),
  ``pressure`` :math:`|\mathbf{F}\cdot\mathbf{n}|/A` and ``shear`` :math:`|\mathbf{F} -
  (\mathbf{F}\cdot\mathbf{n})\mathbf{n}|/A` (pressure units; A the triangle's area, n its normal).

Wear (``wear finnie``, LIGGGHTS's qualitative model after Finnie, Wear 3, 87 (1960)): each contact
of a particle moving towards the wall (:math:`(\mathbf{p}_c - \mathbf{x}_i)\cdot\mathbf{v}_{rel}
\ge 0`, :math:`\mathbf{v}_{rel}` relative to the wall at p) at the angle :math:`\gamma` to the
triangle's plane (:math:`\sin\gamma = |\mathbf{v}_{rel}\cdot\mathbf{n}|/|\mathbf{v}_{rel}|`) adds

.. math::

    \Delta w = 2k\,|\mathbf{v}_{rel}|\,|\mathbf{F}_c|\,f(\gamma)\,\Delta t / A, \qquad
    f(\gamma) = \sin 2\gamma - 3\sin^2\gamma \ (\tan\gamma \le 1/3), \quad
    \cos^2\gamma/3 \ \text{otherwise}

to its triangle's wear (dump per face as ``wear``; kept in restart files), with
:math:`k` = ``k_finnie`` of the type pair (particle, mesh), ``fix property/global k_finnie
peratomtypepair N ...`` (1/pressure, so that w is a depth). Differences from LIGGGHTS: the wear is
a time integral (times :math:`\Delta t`; LIGGGHTS adds it per step, so its value depends on the
time step), and f is Finnie's at every angle (LIGGGHTS's code takes :math:`\cos^2\gamma/3` at all
but normal incidence).

Keywords beyond fix mesh/surface's: ``stress on|off`` (off: a plain mesh/surface), ``reference_point
RX RY RZ`` (distance, default the origin), ``wear finnie|off`` (default off).

Syntax::

    fix ID GROUP mesh/surface/stress file FILE [mesh/surface keywords]
        [stress on|off] [reference_point RX RY RZ] [wear finnie|off]

Example::

    fix floor all mesh/surface/stress file floor.stl type 1 reference_point 0 0 0
    thermo_style custom step atoms f_floor[3]
"""

from typing import Literal

import numpy as np

from pdps_core.api import ScriptError, keyword
from pdps_granular_contact.material import find_property

from .mesh_surface import FixMeshSurface


class FixMeshSurfaceStress(FixMeshSurface):
    name = "mesh/surface/stress"
    minimize_idle = True         # it only measures the mesh's forces
    usage = ("fix ID GROUP mesh/surface/stress file FILE [type N] [scale S] [move DX DY DZ] "
             "[rotate axis AX AY AZ angle DEG] [stress on|off] [reference_point RX RY RZ] [wear finnie|off]")

    class Args(FixMeshSurface.Args):
        stress: Literal["on", "off"] = keyword("on")
        reference_point: tuple[float, float, float] = keyword((0.0, 0.0, 0.0), unit="distance")
        wear: Literal["finnie", "off"] = keyword("off")

    def extra_keywords(self, sim, args):
        self.stress = args.stress == "on"
        self.wear = args.wear == "finnie"
        self.reference = np.array(args.reference_point)
        self.face_force = np.zeros((len(self.triangles), 3))
        self.torque_sum = np.zeros(3)
        self.face_wear = np.zeros(len(self.triangles))
        self.face_area = np.ascontiguousarray(self.face_areas())
        self.wear_k = np.zeros(0)

    def tally(self):
        """What a wall fix adds this mesh's forces to: (reference point, per-triangle force,
        torque, Finnie's k per particle type (empty: no wear), per-triangle wear, triangle areas),
        or None with stress off."""
        if not self.stress:
            return None
        return (self.reference, self.face_force, self.torque_sum, self.wear_k, self.face_wear,
                self.face_area)

    def _read_k_finnie(self, sim):
        """k_finnie of each particle type against this mesh's type, from fix property/global."""
        ntypes = sim.ntypes
        fix = find_property(sim, "k_finnie")
        if fix is None:
            raise ScriptError(f"fix {self.id} (wear finnie) needs k_finnie: fix ID all property/global "
                              f"k_finnie peratomtypepair {ntypes} V11 ... V{ntypes}{ntypes}")
        if fix.style != "per_type_pair" or fix.columns != ntypes:
            raise ScriptError(f"k_finnie (fix {fix.id}) must be a peratomtypepair table of {ntypes} x {ntypes} "
                              "values")
        table = np.asarray(fix.values, dtype=float).reshape(ntypes, ntypes)
        if (table < 0).any():
            raise ScriptError(f"k_finnie (fix {fix.id}) must be >= 0 (got {table[table < 0][0]:g})")
        return np.concatenate([[0.0], table[:, self.material_type - 1]])

    # ---- the sums start again at each step, before the walls' post_force ----
    def setup(self, sim):
        self.face_force[:] = 0.0
        self.torque_sum[:] = 0.0
        if self.wear and self.stress:
            self.wear_k = self._read_k_finnie(sim)

    def pre_force(self, sim):
        self.face_force[:] = 0.0
        self.torque_sum[:] = 0.0

    def vector(self, sim):
        force = sim.comm.sum(self.face_force.sum(axis=0))
        torque = sim.comm.sum(self.torque_sum)
        return np.concatenate([np.asarray(force, dtype=float), np.asarray(torque, dtype=float)])

    def face_data(self, sim):
        """Per-triangle cell data for dumps: force, pressure, shear (summed over ranks)."""
        force = np.asarray(sim.comm.sum(self.face_force), dtype=float).reshape(-1, 3)
        area = self.face_areas()
        normal_part = np.einsum("ij,ij->i", force, self.face_normal)
        shear = np.linalg.norm(force - normal_part[:, None] * self.face_normal, axis=1)
        data = {"force": force, "pressure": np.abs(normal_part) / area, "shear": shear / area}
        if self.wear:
            data["wear"] = np.asarray(sim.comm.sum(self.face_wear), dtype=float)
        return data

    # ---- restart files: the wear so far (every rank's part summed; rank 0 carries it on) ----
    def state(self):
        return {"face_wear": np.asarray(self.sim.comm.sum(self.face_wear), dtype=float)}

    def restore(self, state):
        saved = np.asarray(state["face_wear"], dtype=float)
        if saved.shape != self.face_wear.shape:
            raise ScriptError(f"fix {self.id} (mesh/surface/stress): the saved wear holds {saved.size} value(s) "
                              f"for {len(self.triangles)} triangles")
        self.face_wear = saved.copy() if self.sim.comm.is_root else np.zeros_like(saved)
