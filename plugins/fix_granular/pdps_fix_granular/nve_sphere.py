r"""Fix ``nve/sphere``: velocity-Verlet integration of translation and rotation of finite-size
spheres (LAMMPS's and LIGGGHTS's fix nve/sphere).

.. math::

    \mathbf{v} \mathrel{+}= \tfrac{\Delta t}{2m}\mathbf{F}, \quad
    \boldsymbol{\omega} \mathrel{+}= \tfrac{\Delta t}{2I}\mathbf{T}, \quad
    \mathbf{x} \mathrel{+}= \Delta t\,\mathbf{v} \qquad \text{(initial\_integrate)}

    \mathbf{v} \mathrel{+}= \tfrac{\Delta t}{2m}\mathbf{F}, \quad
    \boldsymbol{\omega} \mathrel{+}= \tfrac{\Delta t}{2I}\mathbf{T} \qquad \text{(final\_integrate)}

with the moment of inertia of a solid sphere :math:`I = \tfrac25 m R^2`, or of a disc
:math:`I = \tfrac12 m R^2` with the ``disc`` keyword (2-d only, as LAMMPS; without it a 2-d run
uses the sphere's value, as LAMMPS does). :math:`m` is the per-particle mass ``rmass`` and
:math:`R` the radius, both from ``particle_style sphere``; :math:`\mathbf{T}` is the ``torque``
the pair style and fixes accumulate. Orientation is not tracked (spheres need none). Like velocity
Verlet for the centre of mass, the scheme is exact for constant force and torque.

Parameters:

- ``disc`` (optional word): treat particles as discs, :math:`I = \tfrac12 m R^2`.
- ``update dipole|dipole/dlm``: LAMMPS's and LIGGGHTS's turning of each particle's dipole moment
  with its spin; refused at the line, as pdps's atom styles keep no dipole moment (LIGGGHTS 3.8.0's
  neither: its fix nve/sphere update dipole stops with "requires atom attribute mu", run 12-03).

Syntax::

    fix ID GROUP nve/sphere [update dipole|dipole/dlm] [disc]

Example::

    particle_style sphere
    ...
    fix 1 all nve/sphere
"""

from typing import Literal

from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword

from ._common import require_radii, require_spheres

SPHERE_INERTIA = 0.4     # I = 2/5 m R^2
DISC_INERTIA = 0.5       # I = 1/2 m R^2


@njit(cache=True)
def sphere_kick(x, v, f, omega, torque, radius, mass, mask, groupbit, nlocal, dt, inertia, ftm2v, drift):
    """Half a step of v by the force and of omega by the torque; with ``drift`` (the first half,
    initial_integrate) also a whole step of x by the new v."""
    half = 0.5 * dt * ftm2v
    # the divisions are the loop's cost: redone only when mass or radius changes from the last
    # particle (never, in a packing of equal spheres), with the same result as for each one
    m_last, r_last, dtfm, dtirotate = -1.0, -1.0, 0.0, 0.0
    for i in range(nlocal):
        if mask[i] & groupbit:
            if mass[i] != m_last or radius[i] != r_last:
                m_last, r_last = mass[i], radius[i]
                dtfm = half / m_last
                dtirotate = half / (inertia * m_last * r_last * r_last)
            for d in range(3):
                v[i, d] += dtfm * f[i, d]
                if drift:
                    x[i, d] += dt * v[i, d]
            # most spheres touch nothing: with no torque their spin stays as it is
            if torque[i, 0] != 0.0 or torque[i, 1] != 0.0 or torque[i, 2] != 0.0:
                for d in range(3):
                    omega[i, d] += dtirotate * torque[i, d]


def inertia_factor(sim, disc, what):
    """The factor k of I = k m R^2: a disc's 1/2 (2-d only) or a solid sphere's 2/5."""
    if disc and sim.dimension != 2:
        raise ScriptError(f"{what} disc needs a 2-d simulation (dimension 2)")
    return DISC_INERTIA if disc else SPHERE_INERTIA


class FixNVESphere(Fix):
    name = "nve/sphere"
    time_integrate = True
    usage = "fix ID GROUP nve/sphere [update dipole|dipole/dlm] [disc]"
    per_atom = ("omega", "torque")

    class Args(StyleArgs):
        inertia: Literal["disc"] | None = None
        update: Literal["dipole", "dipole/dlm"] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.update is not None:
            raise ScriptError(f"update {args.update} needs each particle's dipole moment (atom attribute mu), which "
                              "pdps's atom styles do not keep (nor LIGGGHTS 3.8.0's)")
        require_spheres(sim, "fix nve/sphere")
        self.inertia = inertia_factor(sim, args.inertia == "disc", "fix nve/sphere")

    def setup(self, sim):
        require_radii(sim, self.group, "fix nve/sphere")

    def initial_integrate(self, sim):
        self.kick(sim, drift=True)

    def final_integrate(self, sim):
        self.kick(sim, drift=False)

    def kick(self, sim, drift):
        p = sim.particles
        a = p.arrays
        sphere_kick(a["x"], a["v"], a["f"], a["omega"], a["torque"], a["radius"], a["rmass"], a["mask"],
                    sim.groups.bit(self.group), p.nlocal, sim.dt, self.inertia, sim.units.ftm2v, drift)
