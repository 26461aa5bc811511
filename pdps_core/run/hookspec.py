"""The hooks a fix (or analyze style) can join, in the order the timestep calls them.

A style implements a hook by defining a method of that name taking ``sim``; no decorator is needed.
Within a hook, styles run in the order the script defined them (as in LAMMPS).

Dispatch is LAMMPS's: when a run is set up, each hook gets the tuple of the methods the styles
define for it (LAMMPS's per-fix masks and its ``list_post_force``...), and the loop calls that
tuple. pluggy did the same job before (issue 31): its call costs about 7 us a hook a step against
0.3 us for the tuple (benchmarks/dispatch_overhead.py), and pdps used neither its wrappers nor its
plugin registry, so the loop had come to bypass it; one mechanism is left. ``HOOK_DOCS`` below
is the hooks' documentation.
"""

# The order of one timestep, and what each hook is for; `setup` runs once at the start of each run,
# after the first forces. A style joins a hook by defining a method of its name taking (self, sim).
HOOK_DOCS = {
    "setup": "After the setup forces of a run (force fixes usually apply their post_force here).",
    "initial_integrate": "First half of the step: half-kick and drift (fix nve).",
    "post_integrate": "After positions moved, before neighbor decisions (fix wall/reflect).",
    "pre_exchange": "On rebuild steps, before particles are wrapped and migrated (insertion, deletion).",
    "pre_neighbor": "On rebuild steps, after ghosts are made, before lists are built.",
    "post_neighbor": "On rebuild steps (and in a run's setup), right after the neighbor lists are built: "
                     "what is made from a list (LAMMPS's post_neighbor).",
    "pre_force": "After forces were cleared, before the pair style.",
    "pre_reverse": "After the pair style's forces, before ghosts' forces are summed onto their owners "
                   "(LAMMPS's pre_reverse): forces added here on ghosts reach their owners.",
    "post_force": "After pair forces are complete on owned particles (addforce, setforce, walls).",
    "final_integrate": "Second half-kick.",
    "end_of_step": "After integration: analyze styles, computes that accumulate.",
    "post_run": "Once after the last step of a run (summaries, closing per-run state).",
    "min_post_force": "During minimize, after the forces of each energy evaluation, the setup's included "
                      "(LAMMPS's min_setup and min_post_force): the fix's forces (and energy) join those the "
                      "minimizer follows. Only fixes defining it act in a minimization; setup and the other "
                      "hooks are not called there (as LAMMPS).",
}
HOOKS = tuple(HOOK_DOCS)
# fixes that change forces in a run through these hooks must say what they do in a minimization
FORCE_HOOKS = ("pre_force", "pre_reverse", "post_force")


def implements(style, hook):
    """Whether ``style`` joins ``hook``: its class defines a method of that name, and the style has
    not left it for now (its ``idle_hooks``: LAMMPS's fix mask, which fix_modify may change, as
    fix rigid's bodyforces early|late does)."""
    return callable(getattr(type(style), hook, None)) and hook not in getattr(style, "idle_hooks", ())
