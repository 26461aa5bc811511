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

Keywords beyond fix mesh/surface's: ``stress on|off`` (off: a plain mesh/surface), ``reference_point
RX RY RZ`` (distance, default the origin), ``wear off`` (LIGGGHTS's Finnie wear, ``wear finnie``,
needs its k_finnie material table and is not supported).

Syntax::

    fix ID GROUP mesh/surface/stress file FILE [mesh/surface keywords]
        [stress on|off] [reference_point RX RY RZ] [wear off]

Example::

    fix floor all mesh/surface/stress file floor.stl type 1 reference_point 0 0 0
    thermo_style custom step atoms f_floor[3]
"""

import numpy as np

from pdps_core.api import ScriptError

from .mesh_surface import FixMeshSurface
from .wall_contact import read_numbers


class FixMeshSurfaceStress(FixMeshSurface):
    name = "mesh/surface/stress"
    usage = ("fix ID GROUP mesh/surface/stress file FILE [type N] [scale S] [move DX DY DZ] "
             "[rotate axis AX AY AZ angle DEG] [stress on|off] [reference_point RX RY RZ] [wear off]")
    extra_arity = {"stress": 1, "reference_point": 3, "wear": 1}

    def extra_keywords(self, sim, given):
        self.stress = True
        if "stress" in given:
            if given["stress"][0] not in ("on", "off"):
                raise ScriptError(f"stress must be on or off (got {given['stress'][0]})")
            self.stress = given["stress"][0] == "on"
        if "wear" in given and given["wear"][0] != "off":
            raise ScriptError(f"wear {given['wear'][0]} is not supported (wear off only)")
        self.reference = np.array(read_numbers(given["reference_point"], "reference_point")
                                  if "reference_point" in given else [0.0, 0.0, 0.0])
        self.face_force = np.zeros((len(self.triangles), 3))
        self.torque_sum = np.zeros(3)

    def tally(self):
        """What a wall fix adds this mesh's forces to: (reference point, per-triangle force,
        torque), or None with stress off."""
        return (self.reference, self.face_force, self.torque_sum) if self.stress else None

    # ---- the sums start again at each step, before the walls' post_force ----
    def setup(self, sim):
        self.face_force[:] = 0.0
        self.torque_sum[:] = 0.0

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
        return {"force": force, "pressure": np.abs(normal_part) / area, "shear": shear / area}
