r"""Fix ``multisphere/break``: fix multisphere whose bodies break apart when a per-atom trigger
reaches a threshold (LIGGGHTS 3.8.0's fix multisphere/break).

It moves the clumps as fix multisphere does (``pdps doc fix multisphere``). At the end of every step
after ``trigger_timeStep``, a body of two or more spheres one of whose spheres has a trigger value
at or above ``trigger_threshold`` breaks: all its spheres are released at once, where they are and
as they move (no fragments), each taking the mass of its own volume at the body's density,
:math:`m = \tfrac43\pi r^3\rho_B`, and no longer belonging to a body (molecule id 0: their pairs
enter the neighbor lists at the next build, as in LIGGGHTS). The body itself stays, as LIGGGHTS
keeps it, until its centre leaves the box through a fixed face: it goes on moving under its weight
alone, and its energies count in ke/multisphere, erotate/multisphere and thermo's ke beside those of
its released spheres (LIGGGHTS 3.8.0 prints them so: recorded case multisphere_break). LIGGGHTS 3.8.0
also gives the released spheres and the body no weight for the one step after the break (measured,
thermo every step); pdps gives it. A released sphere moves only if an
integrator acts on it: LIGGGHTS's manual asks for a ``fix nve/sphere`` on the spheres, whose motion of
a body's spheres the fix multisphere, defined after it, overrides (measured in LIGGGHTS 3.8.0: a
``fix nve/sphere all`` before ``fix multisphere`` changes no printed digit; in pdps neither).

The trigger (``trigger_name``) is a per-atom value: ``f_NAME`` (a fix property/atom's scalar),
``f_NAME[k]`` (its vector's column k), or ``v_NAME`` (an atom-style variable);
``trigger_fixName NAME`` is LIGGGHTS's deprecated spelling of ``trigger_name f_NAME`` (a warning says
so). LIGGGHTS's manual asks that the spheres of a breakable body not overlap.

Syntax::

    fix ID GROUP multisphere/break trigger_name f_NAME|f_NAME[k]|v_NAME [trigger_threshold X]
        [trigger_timeStep N] [fix multisphere's keywords]

- ``trigger_threshold X`` (the trigger's unit, default 0), ``trigger_timeStep N`` (timesteps,
  default 0: from the first step on).

Example::

    variable hot atom z<0.02
    fix integr all nve/sphere
    fix ms all multisphere/break trigger_name v_hot trigger_threshold 0.5
"""

import math

import numpy as np

from pdps_core.api import PeratomReference, ScriptError, keyword

from .multisphere import FixMultisphere


class FixMultisphereBreak(FixMultisphere):
    name = "multisphere/break"
    usage = ("fix ID GROUP multisphere/break trigger_name f_NAME|f_NAME[k]|v_NAME [trigger_threshold X] "
             "[trigger_timeStep N] [allow_group_and_set yes|no] [allow_heatsource yes|no] [CAddRhoFluid CADD RHO]")

    class Args(FixMultisphere.Args):
        trigger_threshold: float = keyword(0.0, unit="as the property")
        trigger_timeStep: int = keyword(0, unit="timesteps")
        trigger_name: str | None = keyword(None)
        trigger_fixName: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        if args.trigger_name is None and args.trigger_fixName is None:
            raise ScriptError("No setting made for 'trigger_name'. You must make this setting! (as LIGGGHTS)")
        if args.trigger_name is not None and args.trigger_fixName is not None:
            raise ScriptError("give trigger_name or the deprecated trigger_fixName, not both (as LIGGGHTS)")
        if args.trigger_name is not None and not args.trigger_name.startswith(("f_", "v_")):
            raise ScriptError(f"trigger_name must be f_NAME, f_NAME[k] or v_NAME (got {args.trigger_name})")
        super().__init__(sim, id, group, args)
        if args.trigger_fixName is not None:
            sim.warn(f"fix {id} (multisphere/break): trigger_fixName is deprecated (LIGGGHTS); it reads as "
                     f"trigger_name f_{args.trigger_fixName}")
        self.trigger_word = args.trigger_name or f"f_{args.trigger_fixName}"
        self.trigger = None

    def init_run(self, sim):
        super().init_run(sim)
        self.trigger = PeratomReference(sim, self.trigger_word, f"fix {self.id} trigger_name {self.trigger_word}")

    def final_integrate(self, sim):
        super().final_integrate(sim)
        if not self.nbody or sim.step <= self.args.trigger_timeStep:
            return
        p = sim.particles
        n = p.nlocal
        body = p.arrays[self.body_name][:n]
        values = np.asarray(self.trigger.values(sim), dtype=np.float64)
        hit = body[(body >= 0) & (values >= self.args.trigger_threshold)]
        flags = np.zeros(self.nbody, dtype=np.int64)
        flags[hit] = 1
        broken = (np.asarray(sim.comm.sum(flags)) > 0) & self.alive & (self.nrigid >= 2)
        if not broken.any():
            return
        released = np.flatnonzero((body >= 0) & broken[np.maximum(body, 0)])
        radius = p.radius[released]
        p.rmass[released] = 4.0 / 3.0 * math.pi * radius ** 3 * p.arrays["density"][released]
        body[released] = -1
        p.arrays["molecule"][released] = 0
        # the body stays, spheres gone, until its centre leaves the box (fix multisphere's count)
        self.nrigid[broken] = 0
        self.atom_arrays = None
