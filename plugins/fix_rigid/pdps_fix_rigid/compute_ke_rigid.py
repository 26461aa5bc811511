r"""Compute ``ke/rigid``: the translational kinetic energy of the rigid bodies of a fix rigid or
rigid/small (or their variants), LAMMPS's compute ke/rigid:

.. math::

    E = \sum_B \tfrac12 M_B V_B^2

in energy units (times ``mvv2e``), M_B the body's mass, V_B its centre-of-mass velocity (module
body_energies). The group is not used (LAMMPS's neither). A global scalar, extensive: thermo prints it
divided by the particle count when it normalises energies (lj units).

Syntax::

    compute ID GROUP ke/rigid FIX_ID

Example::

    fix 1 all rigid/small molecule
    compute trans all ke/rigid 1
    compute rot all erotate/rigid 1
    thermo_style custom step c_trans c_rot
"""

from pdps_core.api import Compute, StyleArgs, param

from .body_energies import rigid_fix, translational


class ComputeKERigid(Compute):
    name = "ke/rigid"
    usage = "compute ID GROUP ke/rigid FIX_ID"
    extensive = True

    class Args(StyleArgs):
        fix_id: str = param()

    def init_run(self, sim):
        rigid_fix(sim, self, self.args.fix_id)

    def scalar(self, sim):
        return translational(sim, rigid_fix(sim, self, self.args.fix_id)) * sim.units.mvv2e
