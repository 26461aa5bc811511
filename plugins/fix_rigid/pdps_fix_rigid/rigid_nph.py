r"""Fix ``rigid/nph``: the rigid bodies of fix ``rigid/nve`` at constant pressure, with the barostat of
Kamberaj, Low and Neal as LAMMPS's fix rigid/nph (the equations, the box change and the conserved
quantity, the text rigid/npt shares, from rigid_nh, follow the example). The barostat's masses take the
temperature of all particles at the run's start (1 in lj units, 300 otherwise, where that is 0).

Syntax::

    fix ID GROUP rigid/nph BODYSTYLE [ARGS] iso|aniso|x|y|z PSTART PSTOP PDAMP [couple none|xyz|xy|yz|xz]
        [pchain N] [dilate all|GROUP] [tparam TCHAIN TITER TORDER] [force M X Y Z] [torque M X Y Z]
        [reinit yes|no] [infile FILE]

- ``iso``/``aniso``/``x``/``y``/``z``: the target pressure at the run's start and end (pressure, >= 0)
  and the damping time PDAMP (time, > 0) of every axis (x and y in 2d: iso couples them), or of one.
- ``couple``: axes whose pressures are averaged and driven together; ``pchain``: the barostat chain's
  length (10); ``dilate``: the particles the box change carries (all); ``tparam``: the chain's
  integration (TCHAIN is not used here; TITER 1, TORDER 3 or 5: 3).

Everything else is fix ``rigid``'s and ``rigid/nve``'s (``pdps doc fix rigid``).

Example::

    fix 1 water rigid/nph molecule iso 0.5 0.5 1.0
"""

from pdps_core.api import ScriptError

from .rigid_nh import FixRigidNH, __doc__ as BAROSTAT

__doc__ += "\n" + BAROSTAT


class FixRigidNPH(FixRigidNH):
    name = "rigid/nph"
    usage = ("fix ID GROUP rigid/nph single|molecule|group N G1 .. GN iso|aniso|x|y|z PSTART PSTOP PDAMP "
             "[couple C] [pchain N] [dilate all|GROUP] [tparam TCHAIN TITER TORDER] [force M X Y Z] "
             "[torque M X Y Z] [reinit yes|no] [infile FILE]")
    refused = FixRigidNH.refused | {"temp": "fix rigid/nph controls no temperature (use rigid/npt for temp and "
                                            "pressure; as LAMMPS)"}

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if not any(getattr(args, word) is not None for word in ("iso", "aniso", "x", "y", "z")):
            raise ScriptError("fix rigid/nph needs a pressure: iso, aniso, x, y or z PSTART PSTOP PDAMP")
