"""Fix ``external``: forces a Python program driving pdps sets, added to the group's particles, as
LIGGGHTS's and LAMMPS's fix external adds the forces of a program driving them through their library.

    fix ID GROUP external pf/callback NCALL NAPPLY
    fix ID GROUP external pf/array NAPPLY

The fix keeps an array of forces, one row per owned particle (force units), carried with its
particle from rank to rank. On every step whose number is a multiple of NAPPLY (the run's setup
and each minimization step included) it adds each row to its particle's force when the particle is
in GROUP, in ``post_force``. With ``pf/callback`` it first calls the program's function on steps
that are multiples of NCALL, which fills the array; between calls the rows stay, so with NCALL >
NAPPLY one call's forces serve several steps. With ``pf/array`` the program fills the array itself
between runs (``fix.fexternal``). The fix's scalar ``f_ID`` is the energy the program sets, added
to thermo ``pe`` after ``fix_modify ID energy yes``.

From Python (``pdps_core.api.Simulation``; the fix is ``sim.fixes[ID]``)::

    def forces(caller, step, nlocal, tag, x, fexternal):
        fexternal[:] = -k * x              # this rank's owned particles, in storage order
        sim.fixes["ext"].set_energy(0.5 * k * (x ** 2).sum())

    sim.command("fix ext all external pf/callback 1 1")
    sim.fixes["ext"].set_callback(forces, caller=None)
    sim.command("run 1000")

The function is called as LAMMPS's Python module calls it (``lammps.set_fix_external_callback``):
``(caller, step, nlocal, tag, x, fexternal)`` with numpy views of the owned particles' ids (nlocal),
positions and forces to add (nlocal x 3); ``fexternal`` is written in place. ``set_energy(E)`` sets
the energy of the added forces over all particles (LIGGGHTS's set_energy, LAMMPS's
fix_external_set_energy_global), counted once. A run with ``pf/callback`` and no function set is
refused ("Fix external callback function not set", both programs' words).

Checked against LAMMPS 22 Jul 2025 driven by its Python module with the same function (LAMMPS_CHECKED:
LIGGGHTS 3.8.0 has this fix but no Python module here): plugins/fix_granular/tests/test_external.py.

Example::

    fix ext all external pf/array 10
"""

from typing import Literal

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, param


class FixExternal(Fix):
    name = "external"
    usage = "fix ID GROUP external pf/callback NCALL NAPPLY | fix ID GROUP external pf/array NAPPLY"
    can_energy = True
    extensive = True

    class Args(StyleArgs):
        mode: Literal["pf/callback", "pf/array"] = param()
        every: list[int] = param(default_factory=list, unit="1", alias="NCALL NAPPLY")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        wanted = 2 if args.mode == "pf/callback" else 1
        names = "NCALL NAPPLY" if wanted == 2 else "NAPPLY"
        if len(args.every) != wanted:
            raise ScriptError(f"fix external {args.mode} takes {names} (got {len(args.every)} numbers); usage: "
                              f"{self.usage}")
        if any(n <= 0 for n in args.every):
            raise ScriptError(f"fix external {args.mode}: {names} must be > 0 (got "
                              f"{' '.join(map(str, args.every))})")
        self.ncall = args.every[0] if wanted == 2 else None
        self.napply = args.every[-1]
        self.force_name = f"external_force_{id}"
        # there from the fix's line on: a program may fill it before the first run (pf/array)
        sim.particles.request(self.force_name, 3, ghost=False)
        self.callback, self.caller = None, None
        self.energy = 0.0

    # ---- what the driving program calls -----------------------------------------------------------
    def set_callback(self, function, caller=None):
        """The function called on steps that are multiples of NCALL (pf/callback), and the object
        passed back to it as its first argument."""
        if not callable(function):
            raise ScriptError(f"fix {self.id} (external): the callback must be a function (got {function!r})")
        self.callback, self.caller = function, caller

    @property
    def fexternal(self):
        """The forces to add (nlocal x 3 view of the owned particles, in storage order)."""
        p = self.sim.particles
        return p.arrays[self.force_name][:p.nlocal]

    def set_energy(self, energy):
        """The potential energy of the added forces over all particles (energy units)."""
        energy = float(energy)
        if not np.isfinite(energy):
            raise ScriptError(f"fix {self.id} (external): the energy set is not finite ({energy})")
        self.energy = energy

    # ---- the timestep ---------------------------------------------------------------------------------
    def setup(self, sim):
        if self.args.mode == "pf/callback" and self.callback is None:
            raise ScriptError(f"fix {self.id} (external): Fix external callback function not set "
                              f"(sim.fixes[{self.id!r}].set_callback(function))")
        self.post_force(sim)

    def min_post_force(self, sim):
        if self.args.mode == "pf/callback" and self.callback is None:
            raise ScriptError(f"fix {self.id} (external): Fix external callback function not set")
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        step = sim.step
        if self.ncall is not None and step % self.ncall == 0:
            self.callback(self.caller, step, n, p.tag[:n], p.x[:n], p.arrays[self.force_name][:n])
        if step % self.napply == 0:
            forces = p.arrays[self.force_name][:n]
            if not np.isfinite(forces).all():
                raise ScriptError(f"fix {self.id} (external): the forces set are not finite at step {step}")
            selected = sim.groups.select(sim, self.group)
            p.f[:n][selected] += forces[selected]

    def compute_energy(self, sim):
        return self.energy if sim.comm.is_root else 0.0

    def scalar(self, sim):
        return self.energy
