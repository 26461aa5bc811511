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

from .body_energies import BodyEnergyCompute, translational


class ComputeKERigid(BodyEnergyCompute):
    name = "ke/rigid"
    usage = "compute ID GROUP ke/rigid FIX_ID"
    energy = staticmethod(translational)
