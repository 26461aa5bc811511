r"""Compute ``temp/ramp``: the temperature of a group after a velocity ramp is taken off, a scalar read
as ``c_ID`` (LAMMPS's compute temp/ramp): the thermal temperature of a sheared flow whose profile is
imposed (``velocity ... ramp``, a moving wall).

.. math::

    T = \frac{\sum_i m_i\,|\mathbf{v}_i - u(c_i)\,\hat{\mathbf{e}}|^2}{N_\mathrm{dof}\, k_B}, \qquad
    u(c) = v_\mathrm{lo} + \phi\,(v_\mathrm{hi} - v_\mathrm{lo}), \quad
    \phi = \min\!\left(1, \max\!\left(0, \frac{c - c_\mathrm{lo}}{c_\mathrm{hi} - c_\mathrm{lo}}\right)\right)

with :math:`\hat{\mathbf{e}}` the velocity component VDIM, c the particle's coordinate along DIM (the
ramp is flat beyond CLO and CHI), and :math:`N_\mathrm{dof} = d N - d - N_\mathrm{fix}` as for compute
temp (``compute_modify extra/dof`` replaces the second d). The ramp is the compute's bias: a thermostat
given this compute (``fix_modify ID temp CID``) scales only the velocities about it, as LAMMPS's
remove_bias/restore_bias.

``units lattice`` (LAMMPS's default, and the LAMMPS dialect's) multiplies VLO, VHI by the lattice
spacing along VDIM and CLO, CHI by the spacing along DIM (1 without a lattice command, as LAMMPS 22 Jul
2025 runs it); ``units box`` takes them as they are (the PDPS and LIGGGHTS dialects' default, their
region units). Compared with LAMMPS 22 Jul 2025 (plugins/compute_thermo/tests/test_temp_ramp.py): a
two-mass LJ solid with a vx ramp in y, lattice and box units, rescaled by temp/rescale about the
ramp, to 10 digits over 200 steps.

The vector ``c_ID[1..6]`` (LAMMPS's indices; from 0 in the PDPS dialect) is the kinetic tensor about
the ramp, :math:`\sum_i m_i u_a u_b` (xx, yy, zz, xy, xz, yz; energy units, extensive: thermo divides
it by N where it normalises, as LAMMPS's).

Syntax::

    compute ID GROUP temp/ramp vx|vy|vz VLO VHI x|y|z CLO CHI [units box|lattice]

Example::

    compute tilt flow temp/ramp vx 0 ${srate} y 0 ${ybox} units box
    fix 3 flow temp/rescale 200 1.0 1.0 0.02 1.0
    fix_modify 3 temp tilt
"""

from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Compute, ScriptError, StyleArgs, keyword, observables, param

AXES = ("x", "y", "z")


@njit(cache=True)
def ramp_velocities(x, mask, groupbit, nlocal, coord_dim, coord_lo, coord_hi, v_lo, v_hi, out):
    """out[i] <- u(c_i), the ramp's velocity at each owned particle of the group (0 for the others)."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            fraction = (x[i, coord_dim] - coord_lo) / (coord_hi - coord_lo)
            fraction = min(max(fraction, 0.0), 1.0)
            out[i] = v_lo + fraction * (v_hi - v_lo)
        else:
            out[i] = 0.0


@njit(cache=True)
def thermal_tensor(v, ramp, mass, mask, groupbit, nlocal, v_dim, out):
    """out <- sum m (u_x u_x, u_y u_y, u_z u_z, u_x u_y, u_x u_z, u_y u_z) of the thermal velocities u
    over the owned particles of the group, in row order (LAMMPS's compute_vector)."""
    out[:] = 0.0
    for i in range(nlocal):
        if mask[i] & groupbit:
            t0, t1, t2 = v[i, 0], v[i, 1], v[i, 2]
            if v_dim == 0:
                t0 -= ramp[i]
            elif v_dim == 1:
                t1 -= ramp[i]
            else:
                t2 -= ramp[i]
            m = mass[i]
            out[0] += m * t0 * t0
            out[1] += m * t1 * t1
            out[2] += m * t2 * t2
            out[3] += m * t0 * t1
            out[4] += m * t0 * t2
            out[5] += m * t1 * t2


@njit(cache=True)
def thermal_sum(v, ramp, mass, mask, groupbit, nlocal, v_dim):
    """sum m |v - u e|^2 over the owned particles of the group, in row order (LAMMPS's)."""
    total = 0.0
    for i in range(nlocal):
        if mask[i] & groupbit:
            t0, t1, t2 = v[i, 0], v[i, 1], v[i, 2]
            if v_dim == 0:
                t0 -= ramp[i]
            elif v_dim == 1:
                t1 -= ramp[i]
            else:
                t2 -= ramp[i]
            total += (t0 * t0 + t1 * t1 + t2 * t2) * mass[i]
    return total


class ComputeTempRamp(Compute):
    name = "temp/ramp"
    gives_temperature = True
    usage = "compute ID GROUP temp/ramp vx|vy|vz VLO VHI x|y|z CLO CHI [units box|lattice]"
    extensive_vector = True     # the kinetic tensor, as LAMMPS's extvector
    extra_dof = None        # compute_modify extra/dof (None: the dimension)

    class Args(StyleArgs):
        vdim: Literal["vx", "vy", "vz"] = param(description="the velocity component of the ramp")
        vlo: float = param(unit="velocity")
        vhi: float = param(unit="velocity")
        dim: Literal["x", "y", "z"] = param(description="the coordinate it varies along")
        clo: float = param(unit="distance")
        chi: float = param(unit="distance")
        units: Literal["box", "lattice"] | None = keyword(None)

    def __init__(self, sim, ident, group, args):
        super().__init__(sim, ident, group, args)
        self.v_dim = AXES.index(args.vdim[1])
        self.coord_dim = AXES.index(args.dim)
        if sim.dimension == 2 and 2 in (self.v_dim, self.coord_dim):
            raise ScriptError("a ramp in vz or along z in a 2d simulation, which has no z")
        units = args.units or sim.dialect.region_units
        scale = np.ones(3)
        if units == "lattice" and sim.lattice is not None:
            scale = np.asarray(sim.lattice.spacing, dtype=np.float64)
        self.v_lo, self.v_hi = scale[self.v_dim] * args.vlo, scale[self.v_dim] * args.vhi
        self.coord_lo, self.coord_hi = scale[self.coord_dim] * args.clo, scale[self.coord_dim] * args.chi
        if not self.coord_hi != self.coord_lo:
            raise ScriptError(f"CLO and CHI must differ (got {args.clo:g} and {args.chi:g})")
        self.ramp = np.zeros(0)
        self.tensor = np.zeros(6)

    def _ramp(self, sim):
        p = sim.particles
        if len(self.ramp) < p.nlocal:
            self.ramp = np.zeros(max(p.nlocal, 2 * len(self.ramp)))
        ramp_velocities(p.x, p.mask, sim.groups.bit(self.group), p.nlocal, self.coord_dim, self.coord_lo,
                        self.coord_hi, self.v_lo, self.v_hi, self.ramp)
        return self.ramp

    def dof(self, sim):
        return observables.degrees_of_freedom(sim, self.group, self.extra_dof)

    def scalar(self, sim):
        p = sim.particles
        ramp = self._ramp(sim)
        twice_ke = sim.comm.sum(thermal_sum(p.v, ramp, observables.masses(sim), p.mask, sim.groups.bit(self.group),
                                            p.nlocal, self.v_dim))
        dof = self.dof(sim)
        return twice_ke * sim.units.mvv2e / (dof * sim.units.boltz) if dof > 0 else 0.0

    def vector(self, sim):
        """c_ID[1..6] (LAMMPS's indices): the kinetic tensor about the ramp, sum m u_a u_b mvv2e (xx, yy,
        zz, xy, xz, yz; energy units, extensive: divided by N where thermo normalises)."""
        p = sim.particles
        ramp = self._ramp(sim)
        thermal_tensor(p.v, ramp, observables.masses(sim), p.mask, sim.groups.bit(self.group), p.nlocal,
                       self.v_dim, self.tensor)
        return np.asarray(sim.comm.sum(self.tensor), dtype=np.float64) * sim.units.mvv2e

    def velocity_bias(self, sim):
        """The ramp's velocity at each owned particle: the bias this temperature leaves out."""
        p = sim.particles
        bias = np.zeros((p.nlocal, 3))
        bias[:, self.v_dim] = self._ramp(sim)[:p.nlocal]
        return bias
