r"""Fix ``wall/reflect``: flat walls at fixed coordinates that send back the particles crossing them
(PDPS manual 2.2.8.6; LAMMPS's fix wall/reflect).

After the positions have moved (``post_integrate``), a particle of the group found beyond a wall at
:math:`x = c` (below a ``lo`` wall, above a ``hi`` wall; the same for y and z) is sent back by the
style's rule, with :math:`x^\ast = 2c - x` the mirror image of its position:

- ``specular``: the position is mirrored, :math:`x \to x^\ast`, and only the normal components of the
  velocity and of the force are reversed, :math:`v_x \to -v_x`, :math:`f_x \to -f_x`.
- ``bounce_forward``: the position is mirrored as for specular, and every component of the velocity
  and of the force is reversed, :math:`\mathbf{v} \to -\mathbf{v}`, :math:`\mathbf{f} \to -\mathbf{f}`.
- ``bounce_back``: the position is reversed back along the path the particle took during the step,
  from :math:`\mathbf{x}_{old}` (its position before the step) through the point :math:`\mathbf{c}`
  where the path crossed the wall: :math:`\mathbf{x} \to 2\mathbf{c} - \mathbf{x}`, whose normal
  coordinate is the mirror image :math:`x^\ast` and whose tangential coordinates went back as far as
  they had gone past :math:`\mathbf{c}`. Every component of the velocity and of the force is reversed.
  A particle that was already beyond the wall before the step (no crossing point) is mirrored as for
  specular.

Reading of the manual. "Position reversed" (bounce_back) is taken as PDPS's own code does it: back
along the path by the distance travelled beyond the wall, so the particle retraces its step; "specular
reflected" is the mirror image across the wall; "velocity and force components reversed" is every
component (bounce_back, bounce_forward), "only the normal direction" the normal one (specular). The
manual says the force is reversed too; PDPS's code does not do it, pdps does as the manual says. The
force reversed is the force of the previous step still in the force array after the drift: the
velocity-Verlet loop clears and recomputes forces before it uses them again, so this reversal shows
to fixes that read forces between ``post_integrate`` and ``pre_force`` but does not change the
trajectory. In 2-d, z components are left alone.

LAMMPS form: without a style word the walls are specular as LAMMPS's fix wall/reflect (position
mirrored, normal velocity reversed, forces untouched), and coordinates are in lattice units unless
``units box`` is given (LAMMPS's default ``units lattice``; without a lattice command the lattice
spacing is 1).

A wall coordinate is a number (distance units), ``EDGE`` (the box face where the fix is defined) or,
in the LAMMPS form, ``v_NAME``: an equal-style variable evaluated every step (in lattice units unless
``units box``, as the numbers), so a wall can move. Several walls may be given, each face at most once;
they act one after the other in the order given.

Syntax::

    fix ID GROUP wall/reflect STYLE face coord [face coord ...]          (PDPS)
    fix ID GROUP wall/reflect face coord [face coord ...] [units box|lattice]   (LAMMPS)

    STYLE = bounce_back | bounce_forward | specular
    face  = xlo | xhi | ylo | yhi | zlo | zhi,  coord = number | EDGE | v_NAME (LAMMPS form)

Example::

    fix 3 mobile wall/reflect bounce_back xlo 0 xhi 40 ylo 0 yhi 40
    fix 4 all wall/reflect zlo EDGE zhi EDGE
    variable top equal 20.0-0.01*step
    fix 5 all wall/reflect zhi v_top units box
"""

from typing import Literal

from numba import njit
from pydantic import model_validator

from pdps_core.api import Fix, FloatOrVariable, ScriptError, StyleArgs, VariableRef, keyword, param

from .faces import Face, check_order, once_each, wall_planes

STYLES = ("specular", "bounce_forward", "bounce_back")
SPECULAR, BOUNCE_FORWARD, BOUNCE_BACK = range(3)


@njit(cache=True)
def reflect(x, v, f, x_old, mask, groupbit, nlocal, axes, lower, coords, style, reverse_force,
            dimension):
    for w in range(len(axes)):
        d = axes[w]
        c = coords[w]
        for i in range(nlocal):
            if not mask[i] & groupbit:
                continue
            if (lower[w] and x[i, d] >= c) or (not lower[w] and x[i, d] <= c):
                continue
            mirrored = 2.0 * c - x[i, d]
            if style == BOUNCE_BACK:
                crossed = x_old[i, d] >= c if lower[w] else x_old[i, d] <= c
                if crossed:
                    # back along the path x -> x_old until the normal coordinate is mirrored
                    back = (mirrored - x[i, d]) / (x_old[i, d] - x[i, d])
                    for j in range(dimension):
                        if j != d:
                            x[i, j] += back * (x_old[i, j] - x[i, j])
            x[i, d] = mirrored
            if style == SPECULAR:
                v[i, d] = -v[i, d]
                if reverse_force:
                    f[i, d] = -f[i, d]
            else:
                for j in range(dimension):
                    v[i, j] = -v[i, j]
                    if reverse_force:
                        f[i, j] = -f[i, j]


class FixWallReflect(Fix):
    name = "wall/reflect"
    usage = ("fix ID GROUP wall/reflect [bounce_back|bounce_forward|specular] face coord "
             "[face coord ...] [units box|lattice]")

    class Args(StyleArgs):
        style: Literal["specular", "bounce_forward", "bounce_back"] | None = param(None)
        wall: list[tuple[Face, FloatOrVariable | Literal["EDGE"]]] = param(min_length=1, unit=("1", "distance"))
        units: Literal["box", "lattice"] | None = keyword(None)

        @model_validator(mode="after")
        def _forms(self):
            if self.style is not None and self.units is not None:
                raise ValueError(f"unknown keyword units with style {self.style} (the PDPS form is in box units; "
                                 "units box|lattice is LAMMPS's form, without a style word)")
            once_each(self.wall)
            moving = next((coord for _, coord in self.wall if isinstance(coord, VariableRef)), None)
            if self.style is not None and moving is not None:
                raise ValueError(f"a wall at {moving} with style {self.style}: variable walls are LAMMPS's form, "
                                 "without a style word")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        pdps_form = args.style is not None
        self.style = STYLES.index(args.style) if pdps_form else SPECULAR
        # the PDPS manual reverses forces; LAMMPS's wall/reflect leaves them alone
        self.reverse_force = pdps_form
        units = "box" if pdps_form else (args.units or "lattice")
        walls = once_each(args.wall)
        # the walls that move: (index, variable, lattice spacing along the wall's axis)
        self.moving = []
        for k, (face, coord) in enumerate(walls.items()):
            if isinstance(coord, VariableRef):
                axis = "xyz".index(face[0])
                spacing = sim.lattice.spacing[axis] if (units == "lattice" and sim.lattice is not None) else 1.0
                self.moving.append((k, coord, float(spacing)))
        axes, lower, coords = wall_planes(sim, {face: 0.0 if isinstance(coord, VariableRef) else coord
                                                for face, coord in walls.items()}, units)
        fixed = [k for k, coord in enumerate(walls.values()) if not isinstance(coord, VariableRef)]
        check_order([list(walls)[k] for k in fixed], coords[fixed])
        self.axes, self.lower, self.coords = axes, lower, coords
        self.old_name = f"wall_reflect_{id}_x_old"
        if self.style == BOUNCE_BACK:
            # positions before the step, in a per-atom array so they follow sorting and migration
            sim.particles.request(self.old_name, width=3)

    def _remember(self, sim):
        if self.style == BOUNCE_BACK:
            p = sim.particles
            p.arrays[self.old_name][: p.nlocal] = p.x[: p.nlocal]

    def setup(self, sim):
        for _, variable, _ in self.moving:
            if variable.name not in sim.variables:
                raise ScriptError(f"fix {self.id} {self.name}: variable {variable.name} is not defined")
        self._remember(sim)

    def end_of_step(self, sim):
        self._remember(sim)

    def post_integrate(self, sim):
        for k, variable, spacing in self.moving:
            self.coords[k] = float(sim.variables.value(variable.name)) * spacing
        p = sim.particles
        x_old = p.arrays[self.old_name] if self.style == BOUNCE_BACK else p.x
        reflect(p.x, p.v, p.f, x_old, p.mask, sim.groups.bit(self.group), p.nlocal, self.axes,
                self.lower, self.coords, self.style, self.reverse_force, sim.dimension)
