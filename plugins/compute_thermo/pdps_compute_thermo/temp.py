r"""Compute ``temp``: the temperature of a group, a scalar read as ``c_ID``.

.. math::

    T = \frac{\sum_i m_i v_i^2}{N_\mathrm{dof}\, k_B}, \qquad N_\mathrm{dof} = d\,N - d

with N the particles in the group and d the dimension (the centre-of-mass motion is not counted), as
LAMMPS's compute temp. The PDPS manual's :math:`T = \langle v^2\rangle / 3k_B` is the same for unit
masses and large N.

Syntax::

    compute ID GROUP temp

Example::

    compute 1 all temp
    thermo_style custom step c_1
"""

from pdps_core.api import Compute, observables


class ComputeTemp(Compute):
    name = "temp"
    gives_temperature = True
    usage = "compute ID GROUP temp"
    extra_dof = None        # degrees of freedom taken off besides the fixes' (compute_modify extra/dof)

    def scalar(self, sim):
        return observables.temperature(sim, self.group, self.extra_dof)
