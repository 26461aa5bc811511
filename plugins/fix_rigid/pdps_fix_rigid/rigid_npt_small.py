r"""Fix ``rigid/npt/small``: the small bodies of fix ``rigid/nve/small`` at constant temperature and
pressure, with fix ``rigid/npt``'s Nose-Hoover chains and barostat, as LAMMPS's fix rigid/npt/small.
The bodies, their owners and their communication are fix ``rigid/small``'s; the thermostat and
barostat, their keywords and limits fix ``rigid/npt``'s (``pdps doc fix rigid/npt``); what the two
share is below.

Syntax::

    fix ID GROUP rigid/npt/small molecule temp TSTART TSTOP TDAMP iso|aniso|x|y|z PSTART PSTOP PDAMP
        [couple none|xyz|xy|yz|xz] [pchain N] [dilate all|GROUP] [tparam TCHAIN TITER TORDER]
        [reinit yes|no] [infile FILE]

- ``temp``: target temperature at the run's start and end (temperature; TSTART >= 0, TSTOP > 0) and
  damping time TDAMP (time, > 0), required; ``tparam`` as fix rigid/nvt's.
- ``iso``/``aniso``/``x``/``y``/``z``, ``couple``, ``pchain``, ``dilate``: as fix rigid/nph's.

Example::

    fix 1 rods rigid/npt/small molecule temp 1.0 1.0 1.0 iso 0.5 0.5 10.0
"""

from pdps_core.api import ScriptError

from .rigid_nh_small import FixRigidNHSmall, __doc__ as SHARED

__doc__ += "\n" + SHARED


class FixRigidNPTSmall(FixRigidNHSmall):
    name = "rigid/npt/small"
    usage = ("fix ID GROUP rigid/npt/small molecule temp TSTART TSTOP TDAMP iso|aniso|x|y|z PSTART PSTOP PDAMP "
             "[couple C] [pchain N] [dilate all|GROUP] [tparam TCHAIN TITER TORDER] [reinit yes|no] [infile FILE]")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if args.temp is None or not any(getattr(args, word) is not None for word in ("iso", "aniso", "x", "y", "z")):
            raise ScriptError("fix rigid/npt/small needs temp TSTART TSTOP TDAMP and a pressure: iso, aniso, x, y or "
                              "z PSTART PSTOP PDAMP")
