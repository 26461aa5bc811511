r"""Fix ``addforce``: Stokes drag and buoyancy on spheres (PDPS manual's fix addforce), or a constant
force (LAMMPS's fix addforce).

Stokes drag with fluid viscosity :math:`\mu` (``drag_stokes``), for a sphere of radius :math:`R`
moving with velocity :math:`\mathbf{v}` through fluid at rest:

.. math::  \mathbf{F}_d = -6\pi\mu R\,\mathbf{v}

The PDPS manual writes the magnitude, :math:`F_d = 6\pi\mu R v`; the force opposes the velocity.

Buoyancy along axis :math:`d` (``buoyancy``), for fluid density :math:`\rho` and gravity :math:`g`:

.. math::  F_{b,d} = \rho\, g\, V, \qquad V = \tfrac43\pi R^3

As in the manual, the force points along +d for g > 0 and against it for g < 0: for gravity
pulling towards -z, buoyancy is ``buoyancy z RHO 9.81``. In 2-d, V is the disc's area
:math:`\pi R^2`, as pdps's sphere masses are then :math:`\rho\pi R^2`, so a particle as dense as the
fluid floats. The manual's example gives :math:`\rho` and :math:`g` as two numbers
(``buoyancy z 0.789 9.81``); a single number is read as the product :math:`\rho g`.

A constant force :math:`(F_x, F_y, F_z)` is added to each particle of the group with LAMMPS's
syntax ``addforce FX FY FZ``; a component written ``v_NAME`` is an equal-style variable evaluated
every step (a force that changes in time). Its potential energy, added to thermo ``pe`` after
``fix_modify ID energy yes`` (LAMMPS), is that of a uniform field,
:math:`E = -\sum_i \mathbf{F}\cdot\mathbf{x}_i` over the particles it acts on, with unwrapped
positions (image flags counted), as LAMMPS's fix addforce. Any of the three parts can be combined in one fix; ``region RID``
(LAMMPS) restricts them to particles inside the region. Applied in ``post_force`` and at setup.
When a component is a variable, ``energy v_E`` names an atom-style variable giving each
particle's potential energy, summed over the particles the force acts on; without it the energy is
-F . x of the values now, as LAMMPS's, and 0 in the LIGGGHTS dialect, as LIGGGHTS 3.8.0's
(``Dialect.variable_force_energy``). The fix's scalar ``f_ID`` is that energy; its vector ``f_ID[1-3]`` the group's
total force before the fix added to it.
Drag and buoyancy need per-particle radii (``particle_style sphere``).

Parameters:

- ``FX FY FZ`` (optional): constant force (force units), each a number or ``v_NAME``.
- ``drag_stokes MU``: dynamic viscosity of the fluid (force*time/area units), >= 0.
- ``buoyancy DIM RHO G`` or ``buoyancy DIM RHO_G``: axis (x, y or z; not z in 2-d), fluid density
  (mass/volume) and gravity (force/mass), or their product.
- ``region RID`` (optional): act only on particles inside region RID.
- ``energy v_E`` (optional, with a variable force): the atom-style variable of the energy.

Syntax::

    fix ID GROUP addforce [FX FY FZ] [drag_stokes MU] [buoyancy DIM RHO G] [region RID] [energy v_E]

Examples::

    fix drag water addforce drag_stokes 1.0950
    fix floating water addforce buoyancy z 0.789 9.81
    fix kick flow addforce 1.0 0.0 0.0
"""

import math

import numpy as np
from pydantic import model_validator

from pdps_core.api import FloatOrVariable, ScriptError, StyleArgs, VariableRef, keyword, param

from ._common import AXES, Axis, ForceFix, chosen, require_plane, require_spheres

class FixAddForce(ForceFix):
    name = "addforce"
    usage = "fix ID GROUP addforce [FX FY FZ] [drag_stokes MU] [buoyancy DIM RHO G] [region RID] [energy v_E]"
    can_energy = True

    class Args(StyleArgs):
        fx: FloatOrVariable | None = param(None, unit="force")
        fy: FloatOrVariable | None = param(None, unit="force")
        fz: FloatOrVariable | None = param(None, unit="force")
        drag_stokes: float | None = keyword(None, ge=0, unit="dynamic viscosity")
        # the manual's example gives RHO and G, its syntax line one value: one is read as RHO*G
        buoyancy: tuple[Axis, float, float] | tuple[Axis, float] | None = keyword(
            None, unit=("1", "density", "acceleration"))
        region: str | None = keyword(None)
        energy: FloatOrVariable | None = keyword(None, unit="energy", names="v_NAME")

        @model_validator(mode="after")
        def _something_to_add(self):
            force = [c for c in (self.fx, self.fy, self.fz) if c is not None]
            if 0 < len(force) < 3:
                raise ValueError("a constant force needs three components FX FY FZ "
                                 f"(got {' '.join(str(c) if isinstance(c, VariableRef) else f'{c:g}' for c in force)})")
            if not force and self.drag_stokes is None and self.buoyancy is None:
                raise ValueError("nothing to add: give FX FY FZ, drag_stokes MU or buoyancy DIM RHO G")
            if self.energy is not None and not isinstance(self.energy, VariableRef):
                raise ValueError(f"energy must be an atom-style variable v_NAME (got {self.energy:g})")
            if self.energy is not None and not any(isinstance(c, VariableRef) for c in force):
                raise ValueError("energy v_E goes with a variable force (LAMMPS: Cannot use variable energy "
                                 "with constant force in fix addforce)")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.original = np.zeros(3)
        if args.drag_stokes is not None:
            require_spheres(sim, "fix addforce drag_stokes")
        if args.buoyancy is not None:
            require_spheres(sim, "fix addforce buoyancy")
            require_plane(sim, args.buoyancy[0], "fix addforce buoyancy")
        if args.region is not None:
            sim.region(args.region)
        self.components = None if args.fx is None else (args.fx, args.fy, args.fz)

    def constant_force(self, sim):
        """(FX, FY, FZ) now, variables evaluated; None when the fix adds no constant force."""
        if self.components is None:
            return None
        return np.array([sim.evaluate(c) for c in self.components], dtype=np.float64)

    def vector(self, sim):
        return self.original_force(sim)

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        selected = chosen(sim, self.group, self.args.region)
        f = p.f[:n]
        self.keep_original(f, selected)
        force = self.constant_force(sim)
        if force is not None:
            f[selected] += force
        if self.args.drag_stokes is not None:
            radius = p.radius[:n][selected]
            f[selected] -= (6.0 * math.pi * self.args.drag_stokes * radius)[:, None] * p.v[:n][selected]
        if self.args.buoyancy is not None:
            axis, rho, g = (*self.args.buoyancy, 1.0)[:3]
            radius = p.radius[:n][selected]
            volume = math.pi * radius ** 2 if sim.dimension == 2 else 4.0 / 3.0 * math.pi * radius ** 3
            f[selected, AXES[axis]] += rho * g * volume

    def compute_energy(self, sim):
        """-F . x over the particles the force acts on (this rank's); for a variable force the
        energy variable's sum over them when given, and 0 without it in LIGGGHTS's dialect."""
        force = self.constant_force(sim)
        if force is None:
            return 0.0
        p = sim.particles
        n = p.nlocal
        selected = chosen(sim, self.group, self.args.region)
        if any(isinstance(c, VariableRef) for c in self.components) and (
                self.args.energy is not None or not sim.dialect.variable_force_energy):
            if self.args.energy is None:
                return 0.0
            name = self.args.energy.name
            if sim.variables.style(name) != "atom":
                raise ScriptError(f"fix {self.id} (addforce): energy variable {name} is not atom-style")
            return float(np.asarray(sim.variables.atom_values(name))[selected].sum())
        unwrapped = p.x[:n][selected] + p.image[:n][selected] * sim.box.length
        return -float((unwrapped @ force).sum())

    def scalar(self, sim):
        """``f_ID``: the potential energy of the added force (compute_energy over every rank)."""
        return float(sim.comm.sum(self.compute_energy(sim)))
