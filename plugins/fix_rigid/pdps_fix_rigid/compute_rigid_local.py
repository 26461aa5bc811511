r"""Compute ``rigid/local``: one row per rigid body of a fix ``rigid/small`` (or one of its variants),
with the body's values the inputs name, for ``dump local`` (LAMMPS's compute rigid/local).

A row is written for each body whose owner particle (the particle the body is assigned to, nearest
the centre of its bounding box) is in the compute's group, by the rank owning the body. The inputs,
columns in the order given:

- ``id``: the owner particle's id; ``mol``: its molecule id;
- ``mass``: the body's mass (mass);
- ``x y z``: its centre of mass, in the periodic box (distance); ``xu yu zu``: unwrapped by the
  body's image flags, x + ix L_x ... (distance); ``ix iy iz``: the centre of mass's image flags;
- ``vx vy vz``: the centre of mass's velocity (velocity); ``fx fy fz``: the total force on the body
  (force);
- ``omegax omegay omegaz``: angular velocity (1/time); ``angmomx angmomy angmomz``: angular momentum
  about the centre of mass (mass distance^2/time);
- ``quatw quati quatj quatk``: the unit quaternion turning the body frame (principal axes) into the
  box's;
- ``tqx tqy tqz``: the torque about the centre of mass (energy);
- ``inertiax inertiay inertiaz``: the principal moments of inertia (mass distance^2), ascending.

One input gives a vector (``c_ID`` in dump local), several an array (``c_ID[k]``). The values are
those of the last step the fix integrated (forces and torques of that step's force computation).

The compute also reads the bodies of fix ``rigid``, ``rigid/nve`` and ``rigid/nvt`` (which LAMMPS's
does not): all of them, written by the first rank, the group not used; ``id`` is then the body's
number from 1 and ``mol`` its molecule id (bodystyle molecule; 0 otherwise).

Syntax::

    compute ID GROUP rigid/local RIGID_ID INPUT ...

Example::

    compute 1 all rigid/local myRigid mol x y z
    dump 1 all local 1000 rigid.dump c_1[1] c_1[2] c_1[3] c_1[4]
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, param

from .rigid import FixRigid
from .rigid_small import FixRigidSmall

INPUTS = ("id", "mol", "mass", "x", "y", "z", "xu", "yu", "zu", "ix", "iy", "iz", "vx", "vy", "vz", "fx", "fy", "fz",
          "omegax", "omegay", "omegaz", "angmomx", "angmomy", "angmomz", "quatw", "quati", "quatj", "quatk",
          "tqx", "tqy", "tqz", "inertiax", "inertiay", "inertiaz")
# an input's name less its last letter (x, y or z) -> the fix's per-body array
VECTORS = {"": "xcm", "v": "vcm", "f": "fcm", "omega": "omega", "angmom": "angmom", "tq": "torque",
           "inertia": "inertia", "i": "image_body"}


class ComputeRigidLocal(Compute):
    name = "rigid/local"
    usage = "compute ID GROUP rigid/local RIGID_ID INPUT ..."

    class Args(StyleArgs):
        rigid_id: str = param()
        inputs: list[str] = param(default_factory=list, names="input")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not args.inputs:
            raise ScriptError(f"compute rigid/local needs at least one input; usage: {self.usage}")
        for word in args.inputs:
            if word not in INPUTS:
                raise ScriptError(f"unknown input {word} (known: {' '.join(INPUTS)})")
        self.inputs = list(args.inputs)

    def init_run(self, sim):
        self.rigid(sim)

    def rigid(self, sim):
        fix = sim.fixes.get(self.args.rigid_id)
        if fix is None:
            raise ScriptError(f"compute {self.id}: fix {self.args.rigid_id} is not defined")
        if not isinstance(fix, (FixRigid, FixRigidSmall)):
            raise ScriptError(f"compute {self.id}: fix {self.args.rigid_id} ({fix.name}) is not a rigid/small fix "
                              "(or rigid)")
        return fix

    def _bodies(self, sim, fix):
        """(indices of the bodies to write, their ids, their molecule ids)."""
        if isinstance(fix, FixRigid):
            if not fix.set_up or not sim.comm.is_root:
                return np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0)
            chosen = np.arange(fix.nbody)
            mol = fix.body_ids.astype(np.float64) if fix.args.bodystyle == "molecule" else np.zeros(fix.nbody)
            return chosen, chosen + 1.0, mol
        if not fix.set_up or not fix.compact:
            return np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0)
        p = sim.particles
        rows = fix.body_rows[: fix.nlocal_body]
        chosen = np.flatnonzero(p.mask[rows] & sim.groups.bit(self.group))
        rows = rows[chosen]
        return chosen, p.tag[rows].astype(np.float64), p.molecule[rows].astype(np.float64)

    def local(self, sim):
        """This rank's bodies, one row each: (rows,) for one input, (rows, inputs) for more."""
        fix = self.rigid(sim)
        chosen, ids, mol = self._bodies(sim, fix)
        length = np.asarray(sim.box.length, dtype=np.float64)
        columns = []
        for word in self.inputs:
            if word == "id":
                columns.append(ids)
            elif word == "mol":
                columns.append(mol)
            elif word == "mass":
                columns.append(fix.masstotal[chosen])
            elif word.startswith("quat"):
                columns.append(fix.quat[chosen, "wijk".index(word[-1])])
            elif word in ("xu", "yu", "zu"):
                d = "xyz".index(word[0])
                columns.append(fix.xcm[chosen, d] + fix.image_body[chosen, d] * length[d])
            else:
                d = "xyz".index(word[-1])
                columns.append(getattr(fix, VECTORS[word[:-1]])[chosen, d].astype(np.float64))
        values = np.stack(columns, axis=1) if columns else np.zeros((len(chosen), 0))
        return values[:, 0] if len(self.inputs) == 1 else values
