r"""Compute ``erotate/rigid``: the rotational kinetic energy of the rigid bodies of a fix rigid or
rigid/small (or their variants), LAMMPS's compute erotate/rigid:

.. math::

    E = \sum_B \tfrac12 \sum_{k=1}^3 I_{B,k}\, \omega_{B,k}^2

in energy units (times ``mvv2e``): I_{B,k} the body's principal moments of inertia, omega_{B,k} its
angular velocity about each principal axis (module body_energies; spheres of a clump add their own
2/5 m R^2 to the moments, as the fix counts them). The group is not used (LAMMPS's neither). A global
scalar, extensive: thermo prints it divided by the particle count when it normalises energies (lj
units).

Syntax::

    compute ID GROUP erotate/rigid FIX_ID

Example::

    fix 1 all rigid single
    compute rot all erotate/rigid 1
    thermo_style custom step ke c_rot
"""

from .body_energies import BodyEnergyCompute, rotational


class ComputeERotateRigid(BodyEnergyCompute):
    name = "erotate/rigid"
    usage = "compute ID GROUP erotate/rigid FIX_ID"
    energy = staticmethod(rotational)
