"""The hooks a fix (or analyze style) can join, in the order the timestep calls them.

A style implements a hook by defining a method of that name taking ``sim``; no decorator is needed.
Within a hook, styles run in the order the script defined them (as in LAMMPS).

Dispatch is LAMMPS's: when a run is set up, each hook gets the tuple of the methods the styles
define for it (LAMMPS's per-fix masks and its ``list_post_force``...), and the loop calls that
tuple. pluggy did the same job before (issue 31): its call costs about 7 us a hook a step against
0.3 us for the tuple (benchmarks/dispatch_overhead.py), and pdps used neither its wrappers nor its
plugin registry, so the loop had come to bypass it; one mechanism is left. ``TimestepSpec`` below
stays as the hooks' documentation.
"""

# The order of one timestep; `setup` runs once at the start of each run, after the first forces.
HOOKS = ("setup", "initial_integrate", "post_integrate", "pre_exchange", "pre_neighbor", "post_neighbor",
         "pre_force", "pre_reverse", "post_force", "final_integrate", "end_of_step", "post_run",
         "min_post_force")
# fixes that change forces in a run through these hooks must say what they do in a minimization
FORCE_HOOKS = ("pre_force", "pre_reverse", "post_force")


def implements(style, hook):
    """Whether ``style`` joins ``hook`` (its class defines a method of that name)."""
    return callable(getattr(type(style), hook, None))


def hookspec(function):
    return function


class TimestepSpec:
    @hookspec
    def setup(self, sim):
        """After the setup forces of a run (force fixes usually apply their post_force here)."""

    @hookspec
    def initial_integrate(self, sim):
        """First half of the step: half-kick and drift (fix nve)."""

    @hookspec
    def post_integrate(self, sim):
        """After positions moved, before neighbor decisions (fix wall/reflect)."""

    @hookspec
    def pre_exchange(self, sim):
        """On rebuild steps, before particles are wrapped and migrated (insertion, deletion)."""

    @hookspec
    def pre_neighbor(self, sim):
        """On rebuild steps, after ghosts are made, before lists are built."""

    @hookspec
    def post_neighbor(self, sim):
        """On rebuild steps (and in a run's setup), right after the neighbor lists are built:
        what is made from a list (LAMMPS's post_neighbor)."""

    @hookspec
    def pre_force(self, sim):
        """After forces were cleared, before the pair style."""

    @hookspec
    def pre_reverse(self, sim):
        """After the pair style's forces, before ghosts' forces are summed onto their owners
        (LAMMPS's pre_reverse): forces added here on ghosts reach their owners."""

    @hookspec
    def post_force(self, sim):
        """After pair forces are complete on owned particles (addforce, setforce, walls)."""

    @hookspec
    def final_integrate(self, sim):
        """Second half-kick."""

    @hookspec
    def end_of_step(self, sim):
        """After integration: analyze styles, computes that accumulate."""

    @hookspec
    def min_post_force(self, sim):
        """During ``minimize``, after the forces of each energy evaluation, the setup's included
        (LAMMPS's min_setup and min_post_force): the fix's forces (and energy) join those the
        minimizer follows. Only fixes defining it act in a minimization; ``setup`` and the other
        hooks are not called there (as LAMMPS)."""

    @hookspec
    def post_run(self, sim):
        """Once after the last step of a run (summaries, closing per-run state)."""
