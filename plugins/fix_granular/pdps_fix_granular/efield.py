r"""Fix ``efield``: the force of an external electric field on charged particles (LAMMPS's and
LIGGGHTS's fix efield):

.. math::  \mathbf{F}_i = q_i\,\mathbf{E}\; q_{e2f}

q the per-particle charge (``atom_style charge``, ``full`` or a hybrid with them; ``set ... charge``),
E the field (electric field units), :math:`q_{e2f}` LAMMPS's conversion (23.060549 in real units, 1
in the others). Each component is a number, an equal-style variable ``v_NAME`` evaluated every
step, or an atom-style variable ``v_NAME`` evaluated per particle (a field that varies in space).
Applied in post_force, at a run's setup and in minimization.

- ``region RID``: only particles inside the region (LAMMPS's keyword; LIGGGHTS 3.8.0's fix takes
  no keyword).
- ``energy v_E``: an atom-style variable giving each particle's potential energy in the field, read
  and kept for LAMMPS's minimizer with a variable field; pdps's fix efield adds no energy to pe
  (LIGGGHTS 3.8.0's has none to add).

Syntax::

    fix ID GROUP efield EX EY EZ [region RID] [energy v_E]

Example::

    variable oscillate equal 0.2*sin(2*PI*step/1000)
    fix kick charged efield 0.0 0.0 v_oscillate

Recorded with LIGGGHTS 3.8.0 (case efield, plugins/fix_granular/tests/data/liggghts.cases.json).
"""

import numpy as np

from pdps_core.api import FloatOrVariable, ScriptError, StyleArgs, VariableRef, keyword, param

from ._common import ForceFix, chosen


class FixEfield(ForceFix):
    name = "efield"
    usage = "fix ID GROUP efield EX EY EZ [region RID] [energy v_E]"

    class Args(StyleArgs):
        ex: FloatOrVariable = param(unit="electric field")
        ey: FloatOrVariable = param(unit="electric field")
        ez: FloatOrVariable = param(unit="electric field")
        region: str | None = keyword(None, names="region ID")
        energy: VariableRef | None = keyword(None, unit="energy", names="v_NAME")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not sim.particles.has("q") and "charge" not in sim.particle_styles and "full" not in sim.particle_styles:
            raise ScriptError(f"fix {id} efield needs charges (atom_style charge or full; LAMMPS's 'requires atom "
                              "attribute q')")
        if args.region is not None:
            sim.region(args.region)
        self.components = (args.ex, args.ey, args.ez)

    def init_run(self, sim):
        for c in self.components:
            if isinstance(c, VariableRef) and c.name not in sim.variables:
                raise ScriptError(f"fix {self.id} (efield): variable {c.name} is not defined")

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        selected = chosen(sim, self.group, self.args.region)
        q = p.arrays["q"][:n][selected]
        f = p.f[:n]
        qe2f = sim.units.qe2f
        for d, c in enumerate(self.components):
            if isinstance(c, VariableRef) and sim.variables.style(c.name) == "atom":
                field = np.asarray(sim.variables.atom_values(c.name), dtype=np.float64)[selected]
            else:
                field = sim.evaluate(c)
            f[selected, d] += qe2f * q * field
