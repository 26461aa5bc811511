r"""Fix ``rigid/npt``: the rigid bodies of fix ``rigid/nve`` at constant temperature and pressure, with
the Nose-Hoover chains of fix ``rigid/nvt`` on their translation and rotation and the barostat of
Kamberaj, Low and Neal, as LAMMPS's fix rigid/npt. The barostat, the box change, the pressure it
reads and f_ID/ecouple (the text both styles share, from rigid_nh) follow the examples.

Syntax::

    fix ID GROUP rigid/npt BODYSTYLE [ARGS] temp TSTART TSTOP TDAMP iso|aniso|x|y|z PSTART PSTOP PDAMP
        [couple none|xyz|xy|yz|xz] [pchain N] [dilate all|GROUP] [tparam TCHAIN TITER TORDER]
        [force M X Y Z] [torque M X Y Z] [reinit yes|no] [infile FILE]

- ``temp``: target temperature at the run's start and end (temperature; TSTART >= 0, TSTOP > 0) and
  damping time TDAMP (time, > 0), required; ``tparam`` as fix rigid/nvt's.
- ``iso``/``aniso``/``x``/``y``/``z``, ``couple``, ``pchain``, ``dilate``: as fix rigid/nph's.

Examples::

    fix 1 rods rigid/npt molecule temp 300.0 300.0 100.0 iso 0.5 0.5 10.0
    fix 1 particles rigid/npt molecule temp 1.0 1.0 5.0 x 0.5 0.5 1.0 z 0.5 0.5 1.0 couple xz
"""

from pdps_core.api import ScriptError

from .rigid_nh import FixRigidNH, __doc__ as BAROSTAT

__doc__ += "\n" + BAROSTAT


class FixRigidNPT(FixRigidNH):
    name = "rigid/npt"
    usage = ("fix ID GROUP rigid/npt single|molecule|group N G1 .. GN temp TSTART TSTOP TDAMP "
             "iso|aniso|x|y|z PSTART PSTOP PDAMP [couple C] [pchain N] [dilate all|GROUP] "
             "[tparam TCHAIN TITER TORDER] [force M X Y Z] [torque M X Y Z] [reinit yes|no] [infile FILE]")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if args.temp is None or not any(getattr(args, word) is not None for word in ("iso", "aniso", "x", "y", "z")):
            raise ScriptError("fix rigid/npt needs temp TSTART TSTOP TDAMP and a pressure: iso, aniso, x, y or z "
                              "PSTART PSTOP PDAMP")
