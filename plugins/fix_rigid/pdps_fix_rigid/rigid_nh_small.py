r"""What fixes ``rigid/nph/small`` and ``rigid/npt/small`` share (LAMMPS's fix rigid/nh/small): the small
bodies of fix ``rigid/nve/small`` (``pdps doc fix rigid/small``: one body per molecule, owned by the
rank of its owner particle) under the barostat of fix ``rigid/nph`` and, with ``temp``, the
Nose-Hoover chains of fix ``rigid/npt`` (``pdps doc fix rigid/npt`` gives the equations). The
bodies' kinetic sums, the degrees of freedom and the pressure are summed over all ranks, so 1 and N
ranks take the same steps. The box changes about its centre twice a step, carrying the centres of
mass of every rigid fix's bodies (each rank its own bodies; the ghost copies follow) and the
``dilate`` group's particles.

``f_ID`` (extensive) and thermo ``ecouple``: fix rigid/nve/small's kinetic part of Kamberaj's
Hamiltonian, sum M V^2 + sum_k (p . P_k q)^2 / (8 I_k), plus the chains' energies and the
barostat's, sum_a W epsilon_dot_a^2 / (2 d_p) + P_0 V + its chain's (LAMMPS's compute_scalar of
rigid/nh/small).
"""

import numpy as np

from .rigid_nh import BarostatArgs, NoseHooverBarostat
from .rigid_nve_small import FixRigidNVESmall
from .rigid_small import NOT_YET

REFUSED = {"langevin": "fix rigid/nph/small and rigid/npt/small take no langevin (as LAMMPS)"} | NOT_YET


class FixRigidNHSmall(NoseHooverBarostat, FixRigidNVESmall):
    """Fix rigid/nve/small with the barostat (and, with ``temp``, the thermostat) of LAMMPS's fix
    rigid/nh/small."""
    refused = REFUSED

    class Args(FixRigidNVESmall.Args, BarostatArgs):
        pass

    def _nh_bodies(self):
        nl = self.nlocal_body
        return (self.xcm[:nl], self.vcm[:nl], self.fcm[:nl], self.angmom[:nl], self.torque[:nl], self.omega[:nl],
                self.quat[:nl], self.conjqm[:nl], self.ex[:nl], self.ey[:nl], self.ez[:nl], self.inertia[:nl],
                self.masstotal[:nl], self.fflag[:nl], self.tflag[:nl])

    def _nh_sum(self, sim, values):
        return np.asarray(sim.comm.sum(values))

    def _nh_base_scalar(self, sim):
        return FixRigidNVESmall.scalar(self, sim)

    def initial_integrate(self, sim):
        self.advance_initial(sim)
        # the box change carries the bodies' centres and shares them with their ghost copies
        if self.pstat:
            self._remap(sim)
        else:
            self._share(sim)
        self.place_particles(sim)
        if self.pstat:
            self._remap(sim)
