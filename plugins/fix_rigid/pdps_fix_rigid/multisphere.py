r"""Fix ``multisphere``: LIGGGHTS's rigid clumps of spheres, inserted whole by the insertion fixes from
a ``fix particletemplate/multisphere`` and moved as rigid bodies.

Each body B has the mass M, the principal moments I_k and axes, and the density of its template
(computed there by Monte Carlo over the union of its spheres, or given), not sums over its
spheres. Each step (LIGGGHTS's fix multisphere, the integration of LAMMPS's original fix rigid):

.. math::

    \mathbf{F}_B = \sum_{i \in B} \mathbf{f}_i + M\mathbf{g}, \qquad
    \boldsymbol{\tau}_B = \sum_{i \in B} (\mathbf{r}_i - \mathbf{X}_B) \times \mathbf{f}_i + \boldsymbol{\tau}_i

(g: the fix gravity's acceleration, one at most, as LIGGGHTS; fix gravity leaves the bodies' spheres alone, so an
overlapping clump weighs M g, not the sum over its spheres). Velocity Verlet on the centre of mass X
and the angular momentum L, the orientation by Richardson iteration of the quaternion from
omega = I^-1 L, then the spheres follow, r_i = X + R d_i, v_i = V + omega x (r_i - X), each sphere's
spin the body's omega. ``CAddRhoFluid CADD RHO``: the displaced fluid's added mass divides both
half-kicks by 1 + CADD RHO / rho_B (rho_B the body's density), as LIGGGHTS's source does.

What the clump's spheres carry (LIGGGHTS's ParticleToInsertMultisphere): each sphere's mass is the
body's mass M and its density (per-atom ``density``: the Rayleigh and Hertz times of
``fix check/timestep/gran`` read it) the body's; so a contact's effective mass is the body's. The
energies count each body once, as a body: thermo's ``ke``, ``compute ke`` and ``compute erotate``
take the bodies' translational and rotational energies for their spheres', and ``compute
erotate/sphere`` and the per-atom energies leave the bodies' spheres out (LIGGGHTS's belongs_to
test; recorded cases multisphere_given and multisphere_mc). ``compute ke/multisphere`` and
``erotate/multisphere`` give the bodies' energies alone. Each body's spheres share its molecule id
(``mol`` in a dump), and the pairs within a body are left out of the neighbor lists (LIGGGHTS's
neigh_modify exclude molecule, which this fix performs; like LIGGGHTS's it leaves the loose spheres,
of no body, in the lists: recorded case multisphere_loose).

A body that loses some of its spheres (a boundary of style f or m, ``delete_atoms``) stops the run
with a line naming it: LIGGGHTS removes the whole body, pdps cannot yet. A body that leaves whole is
no longer integrated and counts in no energy. A temperature counts 3 degrees of freedom for each of
the bodies' spheres, none removed (LIGGGHTS's fix multisphere removes none either, and warns that
its energies are not a body's).

Syntax::

    fix ID GROUP multisphere [allow_group_and_set yes|no] [allow_heatsource yes|no] [CAddRhoFluid CADD RHO]

- ``allow_group_and_set yes|no``: LIGGGHTS allows ``group`` and ``set`` commands on clumps' spheres
  only with yes (default no); pdps reads it and allows them either way.
- ``allow_heatsource yes|no``: LIGGGHTS's check of heat sources on clumps (default no); pdps reads it.
- ``CAddRhoFluid CADD RHO``: the added-mass coefficient (dimensionless, usually 0.5) and the fluid's
  density (mass/distance^3).

One fix multisphere at a time, in 3-d, as LIGGGHTS. LIGGGHTS-PUBLIC runs it on one process only;
pdps keeps every body on every rank (as its fix rigid) and sums their forces over the ranks.

Example::

    fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 4 &
        ntry 1000000 spheres file stone.multisphere scale 0.001 type 1
    fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0
    fix ins all insert/pack seed 32452843 distributiontemplate pdd1 insert_every once &
        overlapcheck yes region bc volumefraction_region 0.0004
    fix integr all multisphere

Reference: LIGGGHTS-PUBLIC 3.8.0, fix multisphere (its manual and source, fix_multisphere.cpp).
"""

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword

from . import bodies
from .quaternion import axes_from_quaternion, omega_from_angmom, quaternion_from_axes, richardson

NO_ARRAY = np.zeros(0)
NO_ARRAY2 = np.zeros((0, 3))


@njit(cache=True)
def advance_initial(xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, added,
                    fflag, tflag, alive, dtv, dtf, dtq):
    """LIGGGHTS's initial_integrate: half kicks (divided by the added-mass factor), a drift, the
    orientation a full step by Richardson iteration."""
    for b in range(xcm.shape[0]):
        if not alive[b]:
            continue
        dtfm = dtf / (masstotal[b] * added[b])
        dtt = dtf / added[b]
        for d in range(3):
            if fflag[b, d]:
                vcm[b, d] += dtfm * fcm[b, d]
            xcm[b, d] += dtv * vcm[b, d]
            if tflag[b, d]:
                angmom[b, d] += dtt * torque[b, d]
        omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b)
        richardson(quat, angmom, omega, inertia, b, dtq)
        axes_from_quaternion(quat, b, ex, ey, ez)


@njit(cache=True)
def advance_final(vcm, fcm, angmom, torque, omega, ex, ey, ez, inertia, masstotal, added, fflag, tflag, alive, dtf):
    for b in range(vcm.shape[0]):
        if not alive[b]:
            continue
        dtfm = dtf / (masstotal[b] * added[b])
        dtt = dtf / added[b]
        for d in range(3):
            if fflag[b, d]:
                vcm[b, d] += dtfm * fcm[b, d]
            if tflag[b, d]:
                angmom[b, d] += dtt * torque[b, d]
        omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b)


def angmom_from_omega(omega, ex, ey, ez, inertia):
    """L = sum_k I_k (omega . e_k) e_k (LIGGGHTS's angmom_from_omega)."""
    return sum(moment[:, None] * np.einsum("bd,bd->b", omega, axis)[:, None] * axis
               for moment, axis in zip(inertia.T, (ex, ey, ez)))


class FixMultisphere(Fix):
    name = "multisphere"
    usage = ("fix ID GROUP multisphere [allow_group_and_set yes|no] [allow_heatsource yes|no] "
             "[CAddRhoFluid CADD RHO]")
    time_integrate = True

    class Args(StyleArgs):
        allow_group_and_set: bool = keyword(False)
        allow_heatsource: bool = keyword(False)
        CAddRhoFluid: tuple[float, float] | None = keyword(None, unit=("dimensionless", "density"))

    FIELDS = {"masstotal": 0, "density": 0, "added": 0, "xcm": 3, "vcm": 3, "fcm": 3, "torque": 3, "angmom": 3,
              "omega": 3, "inertia": 3, "ex": 3, "ey": 3, "ez": 3, "quat": 4, "fflag": 3, "tflag": 3,
              "image_body": 3, "nrigid": 0, "clumptype": 0, "atomtype": 0, "alive": 0, "sums": 6}
    TYPES = {"image_body": np.int64, "nrigid": np.int64, "clumptype": np.int64, "atomtype": np.int64, "alive": np.bool_,
             "fflag": np.bool_, "tflag": np.bool_}

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {id} ({self.name})")
        if sim.dimension != 3:
            raise ScriptError(f"fix {id} multisphere needs a 3-d simulation (as LIGGGHTS)")
        others = [f.id for f in sim.fixes.values() if isinstance(f, FixMultisphere) and f.id != id]
        if others:
            raise ScriptError(f"fix {id}: only one fix multisphere at a time (as LIGGGHTS); fix {others[0]} is one")
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"fix {id} multisphere needs spheres (atom_style sphere or granular; got "
                              f"{sim.particle_style})")
        if args.CAddRhoFluid is not None and (args.CAddRhoFluid[0] < 0 or args.CAddRhoFluid[1] < 0):
            raise ScriptError(f"CAddRhoFluid: CADD and RHO must be >= 0 (got {args.CAddRhoFluid[0]:g} "
                              f"{args.CAddRhoFluid[1]:g})")
        p = sim.particles
        self.body_name = f"multisphere_body_{id}"
        self.displace_name = f"multisphere_displace_{id}"
        p.request(self.body_name, dtype=np.int64, default=-1, ghost=False)
        p.request(self.displace_name, width=3, ghost=False)
        p.request("molecule")
        p.request("density")
        sim.neighbor.exclude_molecules(group, "body")
        self.nbody = 0
        for name, width in self.FIELDS.items():
            dtype = self.TYPES.get(name, np.float64)
            setattr(self, name, np.zeros((0, width) if width else 0, dtype=dtype))
        self.step_virial = np.zeros(6)
        self.gvec = np.zeros(3)
        self.atom_arrays = None

    # ---- bodies from the insertion fixes --------------------------------------------------------
    def add_bodies(self, sim, xcm, vcm, omega, ex, ey, ez, inertia, mass, density, nrigid, fflag, tflag, clumptype,
                   displace, atomtype=None):
        """Take n new bodies (every rank calls it with the same bodies): centres, velocities, angular
        velocities, principal axes (n, 3) each, moments (n, 3), masses, densities, sphere counts,
        force and torque flags (n, 3), template types, the spheres' places in their body's frame
        (sum of the counts, 3), body by body, and the spheres' particle types (n; 0 unknown).
        Returns the per-atom values of their spheres, body by body in order: {name: array} for
        ``add_particles``."""
        n = len(mass)
        first = self.nbody
        quat = np.zeros((n, 4))
        for b in range(n):
            quaternion_from_axes(ex[b], ey[b], ez[b], quat[b])
        added = np.ones(n)
        if self.args.CAddRhoFluid is not None:
            cadd, rho = self.args.CAddRhoFluid
            added = 1.0 + cadd * rho / np.asarray(density)
        new = {"masstotal": mass, "density": density, "added": added, "xcm": xcm, "vcm": vcm,
               "fcm": np.zeros((n, 3)), "torque": np.zeros((n, 3)),
               "angmom": angmom_from_omega(omega, ex, ey, ez, inertia), "omega": omega, "inertia": inertia,
               "ex": ex, "ey": ey, "ez": ez, "quat": quat, "fflag": fflag, "tflag": tflag,
               "image_body": np.zeros((n, 3), dtype=np.int64), "nrigid": nrigid, "clumptype": clumptype,
               "atomtype": np.zeros(n, dtype=np.int64) if atomtype is None else atomtype,
               "alive": np.ones(n, dtype=np.bool_), "sums": np.zeros((n, 6))}
        for name, values in new.items():
            dtype = self.TYPES.get(name, np.float64)
            setattr(self, name, np.ascontiguousarray(np.concatenate([getattr(self, name),
                                                                      np.asarray(values, dtype=dtype)])))
        self.nbody += n
        self.atom_arrays = None
        index = np.repeat(np.arange(first, first + n, dtype=np.int64), nrigid)
        return {self.body_name: index, "molecule": index + 1, self.displace_name: np.asarray(displace),
                "density": np.repeat(np.asarray(density, dtype=np.float64), nrigid)}

    # ---- the timestep ---------------------------------------------------------------------------
    def _atoms(self, sim):
        if self.atom_arrays is None:
            p = sim.particles
            a = p.arrays
            self.atom_arrays = (a["x"], a["v"], a["f"], a["image"], a[self.body_name], a[self.displace_name],
                                a["type"], sim.mass, a["rmass"], a["omega"], a["torque"],
                                np.asarray(sim.box.length, dtype=np.float64))
        return self.atom_arrays

    def extract(self, name):
        """"clump_body": the per-atom body index property (-1 outside a body) of the clumps' spheres,
        which fix gravity and the particle energies leave out (LIGGGHTS's belongs_to); "clump_energies":
        the bodies' (translational, rotational) kinetic energies, which those energies add instead."""
        if name == "clump_body":
            return self.body_name
        if name == "clump_energies":
            return (self.kinetic_energy(self.sim), self.rotational_energy(self.sim))
        return None

    def reset_dt(self, sim):
        self.dtv = sim.dt
        self.dtf = 0.5 * sim.dt * sim.units.ftm2v
        self.dtq = 0.5 * sim.dt

    def init_run(self, sim):
        self.reset_dt(sim)
        pulls = [f for f in sim.fixes.values() if f.extract("gvec") is not None]
        if len(pulls) > 1:
            raise ScriptError(f"fix {self.id} multisphere takes one fix gravity (as LIGGGHTS); fixes "
                              f"{' and '.join(f.id for f in pulls)} are two")
        self.gvec = np.zeros(3) if not pulls else np.asarray(pulls[0].extract("gvec"), dtype=np.float64)
        self.atom_arrays = None

    def _count_spheres(self, sim):
        """Bodies whole, gone, or broken (a line naming the first broken body stops the run)."""
        if not self.nbody:
            return
        p = sim.particles
        body = p.arrays[self.body_name][: p.nlocal]
        counts = np.asarray(sim.comm.sum(np.bincount(body[body >= 0], minlength=self.nbody).astype(np.int64)))
        broken = np.flatnonzero((counts > 0) & (counts < self.nrigid))
        if broken.size:
            b = int(broken[0])
            raise ScriptError(f"fix {self.id}: multisphere body {b + 1} lost {self.nrigid[b] - counts[b]} of its "
                              f"{self.nrigid[b]} spheres at step {sim.step}; LIGGGHTS removes the whole body, pdps "
                              "cannot yet (keep the bodies inside the box, or let them leave through a periodic face)")
        # a broken body (fix multisphere/break: no spheres left, nrigid 0) stays until its centre
        # leaves the box, as LIGGGHTS keeps it
        lo, hi = np.asarray(sim.box.lo), np.asarray(sim.box.hi)
        fixed = ~np.asarray(sim.box.periodic, dtype=bool)
        outside = ((self.xcm < lo) | (self.xcm >= hi))[:, fixed].any(axis=1)
        gone = self.alive & (counts == 0) & ((self.nrigid > 0) | outside)
        if gone.any():
            self.alive[gone] = False
            self.vcm[gone] = self.angmom[gone] = self.omega[gone] = 0.0

    def _sum_force_torque(self, sim):
        x, v, f, image, body, displace, *_, torque_atom, length = self._atoms(sim)
        bodies.force_torque(x, f, torque_atom, image, body, length, self.xcm, self.image_body,
                            sim.particles.nlocal, self.sums)
        total = sim.comm.sum(self.sums) if self.nbody else self.sums
        self.fcm[:] = total[:, :3] + self.masstotal[:, None] * self.gvec
        self.torque[:] = total[:, 3:]

    def setup(self, sim):
        self.atom_arrays = None
        self._count_spheres(sim)
        self._sum_force_torque(sim)

    def initial_integrate(self, sim):
        if not self.nbody:
            return
        advance_initial(self.xcm, self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat, self.ex,
                        self.ey, self.ez, self.inertia, self.masstotal, self.added, self.fflag, self.tflag,
                        self.alive, self.dtv, self.dtf, self.dtq)
        x, v, f, image, body, displace, type_, mass, rmass, omega_atom, _, length = self._atoms(sim)
        bodies.set_xv(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, self.xcm, self.vcm,
                      self.omega, self.ex, self.ey, self.ez, self.image_body, sim.particles.nlocal, self.dtf,
                      self.step_virial, False)

    def final_integrate(self, sim):
        if not self.nbody:
            return
        self._sum_force_torque(sim)
        advance_final(self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.ex, self.ey, self.ez,
                      self.inertia, self.masstotal, self.added, self.fflag, self.tflag, self.alive, self.dtf)
        x, v, f, image, body, displace, type_, mass, rmass, omega_atom, _, length = self._atoms(sim)
        bodies.set_v(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, self.vcm, self.omega,
                     self.ex, self.ey, self.ez, self.image_body, sim.particles.nlocal, self.dtf, self.step_virial,
                     False)

    def pre_neighbor(self, sim):
        self.atom_arrays = None
        self._count_spheres(sim)
        bodies.remap_centres(self.xcm, self.image_body, np.asarray(sim.box.lo, dtype=np.float64),
                             np.asarray(sim.box.hi, dtype=np.float64), np.asarray(sim.box.length, dtype=np.float64),
                             np.asarray(sim.box.periodic, dtype=np.bool_))

    # ---- the bodies' energies (compute ke/multisphere, erotate/multisphere) ---------------------
    def kinetic_energy(self, sim):
        """sum_B 1/2 M V^2 times mvv2e (LIGGGHTS's extract_ke)."""
        return 0.5 * sim.units.mvv2e * float(np.sum(self.masstotal[self.alive] * np.sum(self.vcm[self.alive] ** 2, 1)))

    def rotational_energy(self, sim):
        """sum_B 1/2 sum_k I_k w_k^2, w the angular momentum in the body frame over I (LIGGGHTS's
        extract_rke, which leaves out mvv2e)."""
        alive = self.alive
        projected = np.stack([np.einsum("bd,bd->b", axis[alive], self.angmom[alive])
                              for axis in (self.ex, self.ey, self.ez)], 1)
        inertia = self.inertia[alive]
        wbody = np.divide(projected, inertia, out=np.zeros_like(projected), where=inertia != 0.0)
        return 0.5 * float(np.sum(inertia * wbody ** 2))
