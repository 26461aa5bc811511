r"""Fix ``enforce2d``: keep a 2-d simulation in its plane: z components of velocities and forces (and
the x, y components of angular velocities and torques of spheres) set to 0 at setup, after the
forces of every step and after minimisation steps (LAMMPS's fix enforce2d).

Syntax::

    fix ID GROUP enforce2d

Example::

    dimension 2
    fix 2d all enforce2d
"""

from pdps_core.api import Fix, ScriptError


class FixEnforce2D(Fix):
    name = "enforce2d"
    usage = "fix ID GROUP enforce2d"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if sim.dimension != 2:
            raise ScriptError("fix enforce2d needs a 2-d simulation (dimension 2)")

    def _flatten(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        p.v[:n][chosen, 2] = 0.0
        p.f[:n][chosen, 2] = 0.0
        if p.has("omega"):
            p.omega[:n][chosen, :2] = 0.0
        if p.has("torque"):
            p.torque[:n][chosen, :2] = 0.0

    def setup(self, sim):
        self._flatten(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        self._flatten(sim)
