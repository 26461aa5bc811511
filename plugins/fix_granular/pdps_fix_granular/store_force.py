r"""Fix ``store/force``: each particle's force as it stands when the fix's turn comes in the step,
kept as per-particle values (LAMMPS's and LIGGGHTS's fix store/force).

``f_ID[1]`` ``f_ID[2]`` ``f_ID[3]`` (``[0]`` .. ``[2]`` in the PDPS dialect) are the force's x, y,
z components (force units) after the pair style and the fixes defined before this one have acted
in ``post_force``, and before those defined after it; 0 for particles outside the group. Kept at
setup and in each minimization step too.

Syntax::

    fix ID GROUP store/force

Example::

    fix pairs all store/force
    dump 1 all custom 100 f.dump id f_pairs[1] f_pairs[2] f_pairs[3]
"""

from ._common import ForceFix


class FixStoreForce(ForceFix):
    name = "store/force"
    usage = "fix ID GROUP store/force"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.stored_name = f"store_force_{id}"
        sim.particles.request(self.stored_name, width=3, default=0.0, ghost=False)

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        stored = p.arrays[self.stored_name][:n]
        stored[:] = 0.0
        chosen = sim.groups.select(sim, self.group)
        stored[chosen] = p.f[:n][chosen]

    def peratom(self, sim):
        return sim.particles.arrays[self.stored_name][:sim.particles.nlocal]
