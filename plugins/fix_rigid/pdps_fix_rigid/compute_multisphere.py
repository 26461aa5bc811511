r"""Computes ``multisphere``, ``rigid`` and ``multisphere/single``: one property of the bodies of the
fix multisphere (LIGGGHTS's compute rigid, whose three names these are).

``multisphere`` and ``rigid`` (the same compute): local data, one row per body, in the order the
bodies were inserted: a local vector for a property of one value, a local array (one column per
component) for the others; read by ``compute reduce`` and ``dump local``. ``multisphere/single id
N``: the property of body N (ids from 1 in insertion order) as a global scalar or vector (zeros
while the body does not exist or after it broke, as LIGGGHTS's sums over processes give; a broken
body's id_multisphere is -1 in the local data, as LIGGGHTS resets it).

Properties (LIGGGHTS's names of the fix multisphere's per-body data; the manual's ``id`` and
``type`` are read as ``id_multisphere`` and ``atomtype``, which LIGGGHTS 3.8.0 itself refuses as
"illegal property name", run 12-03):

- ``xcm`` (distance), ``vcm`` (velocity): the centre of mass and its velocity, 3 values;
- ``fcm`` (force), ``torque`` (energy): the total force (the spheres' forces and the body's weight
  M g) and torque about the centre of mass at the last force computation, 3 values;
- ``angmom`` (mass distance^2/time), ``omega`` (1/time): angular momentum and velocity, 3 values;
- ``quat``: the unit quaternion (w, x, y, z) turning the body frame into the box's, 4 values;
- ``inertia`` (mass distance^2): principal moments; ``ex_space``, ``ey_space``, ``ez_space``:
  the principal axes in the box, 3 values each;
- ``masstotal`` (mass), ``density`` (mass/distance^3), ``atomtype``, ``clumptype`` (the template's
  ``type``), ``nrigid`` (spheres), ``id_multisphere``: 1 value.

The group must be ``all`` (LIGGGHTS's check; bodies belong to no group). A body that has left the
box keeps its row with its last values, as pdps keeps every body it inserted.

Syntax::

    compute ID all multisphere property NAME
    compute ID all rigid property NAME
    compute ID all multisphere/single id N property NAME

Example::

    compute xcm all multisphere property xcm
    compute top all reduce max c_xcm[3]
    compute first all multisphere/single id 1 property vcm
    thermo_style custom step c_top c_first[3]
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, keyword

from .multisphere import FixMultisphere

# LIGGGHTS's property name -> the fix's per-body array (None: computed here)
PROPERTIES = {"xcm": "xcm", "vcm": "vcm", "fcm": "fcm", "torque": "torque", "angmom": "angmom",
              "omega": "omega", "quat": "quat", "inertia": "inertia", "ex_space": "ex", "ey_space": "ey",
              "ez_space": "ez", "masstotal": "masstotal", "density": "density", "atomtype": "atomtype",
              "clumptype": "clumptype", "nrigid": "nrigid", "id_multisphere": None}
ALIASES = {"id": "id_multisphere", "type": "atomtype"}
# LIGGGHTS keeps these too; pdps's bodies do not carry them
NOT_KEPT = ("dragforce_cm", "hdtorque_cm", "imagebody", "remapflag", "fflag", "tflag", "start_step", "v_integrate",
            "r_bound", "xcm_to_xbound", "temp", "temp_old")


def _property(word):
    name = ALIASES.get(word, word)
    if name in NOT_KEPT:
        raise ScriptError(f"property {word}: pdps's fix multisphere does not keep it per body (it has: "
                          f"{', '.join(PROPERTIES)})")
    if name not in PROPERTIES:
        raise ScriptError(f"property must be one of {', '.join([*PROPERTIES, *ALIASES])} (got {word})")
    return name


class ComputeMultisphere(Compute):
    name = "multisphere"
    usage = "compute ID all multisphere property NAME"

    class Args(StyleArgs):
        property: str = keyword(..., names="property NAME")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if group != "all":
            raise ScriptError(f"compute {id} ({self.name}): the group must be all (as LIGGGHTS: bodies belong to "
                              f"no group; got {group})")
        self.property = _property(args.property)

    def multisphere(self, sim):
        fixes = [f for f in sim.fixes.values() if isinstance(f, FixMultisphere)]
        if len(fixes) != 1:
            raise ScriptError(f"compute {self.id} ({self.name}): fix multisphere does not exist")
        return fixes[0]

    def init_run(self, sim):
        self.multisphere(sim)

    def values(self, sim):
        """(bodies,) or (bodies, k) floats: every body's property."""
        fix = self.multisphere(sim)
        if self.property == "id_multisphere":
            # a broken body (multisphere/break) has lost its id, as LIGGGHTS's tagReset makes it -1
            return np.where(fix.nrigid > 0, np.arange(1, fix.nbody + 1), -1).astype(np.float64)
        return np.asarray(getattr(fix, PROPERTIES[self.property]), dtype=np.float64)

    def local(self, sim):
        """Every body's row, on the first rank (each rank keeps every body)."""
        values = self.values(sim)
        return values if sim.comm.is_root else values[:0]


class ComputeRigid(ComputeMultisphere):
    name = "rigid"
    usage = "compute ID all rigid property NAME"


class ComputeMultisphereSingle(ComputeMultisphere):
    name = "multisphere/single"
    usage = "compute ID all multisphere/single id N property NAME"

    class Args(StyleArgs):
        id: int = keyword(..., ge=1, unit="1", names="id N")
        property: str = keyword(..., names="property NAME")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.body = args.id
        self.width = 4 if self.property == "quat" else (3 if self.property in (
            "xcm", "vcm", "fcm", "torque", "angmom", "omega", "inertia", "ex_space", "ey_space", "ez_space") else 1)

    def _row(self, sim):
        values = self.values(sim)
        if self.body > len(values) or self.multisphere(sim).nrigid[self.body - 1] == 0:
            return np.zeros(self.width)
        return np.atleast_1d(values[self.body - 1]).astype(np.float64)

    def scalar(self, sim):
        if self.width != 1:
            raise ScriptError(f"compute {self.id} ({self.name}): property {self.args.property} has {self.width} "
                              f"values: read c_{self.id}[i]")
        return float(self._row(sim)[0])

    def vector(self, sim):
        if self.width == 1:
            raise ScriptError(f"compute {self.id} ({self.name}): property {self.args.property} has one value: "
                              f"read c_{self.id}")
        return self._row(sim)

    def local(self, sim):
        raise ScriptError(f"compute {self.id} ({self.name}) has no local data: compute multisphere property "
                          f"{self.args.property} has every body's")
