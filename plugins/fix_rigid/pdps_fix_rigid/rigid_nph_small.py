r"""Fix ``rigid/nph/small``: the small bodies of fix ``rigid/nve/small`` at constant pressure, with fix
``rigid/nph``'s barostat, as LAMMPS's fix rigid/nph/small. The bodies, their owners and their
communication are fix ``rigid/small``'s; the barostat, its keywords and limits are fix ``rigid/nph``'s
(``pdps doc fix rigid/nph``); what the two share is below.

Syntax::

    fix ID GROUP rigid/nph/small molecule iso|aniso|x|y|z PSTART PSTOP PDAMP [couple none|xyz|xy|yz|xz]
        [pchain N] [dilate all|GROUP] [reinit yes|no] [infile FILE]

- ``iso``/``aniso``/``x``/``y``/``z``: the target pressure at the run's start and end (pressure, >= 0)
  and the damping time PDAMP (time, > 0); ``couple``, ``pchain``, ``dilate`` as fix rigid/nph's
  (``tparam`` is refused, as LAMMPS's rigid/nph/small does). The barostat's masses take the
  temperature of all particles at the run's start.

Example::

    fix 1 water rigid/nph/small molecule iso 0.5 0.5 1.0
"""

from pdps_core.api import ScriptError

from .rigid_nh_small import REFUSED, FixRigidNHSmall, __doc__ as SHARED
from .rigid_small import THERMOSTAT_ONLY

__doc__ += "\n" + SHARED


class FixRigidNPHSmall(FixRigidNHSmall):
    name = "rigid/nph/small"
    usage = ("fix ID GROUP rigid/nph/small molecule iso|aniso|x|y|z PSTART PSTOP PDAMP [couple C] [pchain N] "
             "[dilate all|GROUP] [reinit yes|no] [infile FILE]")
    refused = REFUSED | {"temp": "fix rigid/nph/small controls no temperature (use rigid/npt/small for temp "
                                 "and pressure; as LAMMPS)",
                         "tparam": THERMOSTAT_ONLY}

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if not any(getattr(args, word) is not None for word in ("iso", "aniso", "x", "y", "z")):
            raise ScriptError("fix rigid/nph/small needs a pressure: iso, aniso, x, y or z PSTART PSTOP PDAMP")
