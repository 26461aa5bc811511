"""Simulation: the one object a script or a Python user drives.

    from pdps_core.api import Simulation
    sim = Simulation(log=None)
    sim.file("in.water")            # a whole script
    sim.command("run 100")          # one or more lines of script
    sim.run(100)                    # the same, as a typed call
    sim.x, sim.v, sim.f             # numpy views of the owned particles

It is a facade over parts with one job each, made once in the constructor (LAMMPS's Input, Atom and
Domain, Force and Modify, Update; HOOMD's State and Operations):

- ``script`` (Script): the dialect, the variables, where in which script the reading is;
- ``system`` (System): particles, types and masses, the box, groups, regions, units;
- ``styles`` (StyleTables): the pair style, fixes, computes, analyze styles;
- ``run_state`` (RunState): the step, the time, the run's bounds, what was computed when;
- the services ``comm``, ``neighbor``, ``output``, ``timers``.

The names of ``pdps_core.api.CONTRACT`` read through to the part that keeps them (``sim.step`` is
``sim.run_state.step``); they are read-only here: the core writes into the parts. Neither the
facade nor a part takes an attribute its constructor did not make (``__slots__``).
"""

import math
import os
from operator import attrgetter

from .comm import world
from .errors import ScriptError, ScriptQuit, SimulationError
from .neighbor.neighbor import Neighbor
from .output.output import Output
from .run import driver
from .run.state import RunState
from .run.timers import Timers
from .script.interpreter import Script
from .state.style_tables import StyleTables
from .state.system import System
from .styles import VariableRef

# part -> the names the facade reads through to it
READ_THROUGH = {
    "system": ("particles", "units", "dimension", "box", "ntypes", "mass", "particle_style",
               "particle_styles", "lattice", "groups", "require_box", "require_group", "change_box",
               "add_particles", "delete_particles", "stiffness_checks", "periodicity", "molecule_template"),
    "run_state": ("step", "time", "dt", "run_first_step", "run_last_step", "ramp", "eflag", "vflag",
                  "virial", "pe", "in_setup", "random_key"),
    "styles": ("pair", "pair_list", "fixes", "computes", "analyzes", "compute_value", "fix_value",
               "compute_needs"),
    "script": ("variables", "dialect", "dialect_index", "substitute", "resolve"),
    "output": ("warnings",),
}


class Simulation:
    # __weakref__: a Python user's (or a test's) records may be kept per simulation in a WeakKeyDictionary
    __slots__ = ("script", "system", "styles", "run_state", "comm", "neighbor", "output", "timers",
                 "__weakref__")

    def __init__(self, *, screen=None, log="log.pdps", variables=None, comm=None, dialect=None):
        """``screen``: a text stream (default stdout) or False for silence; ``log``: a path or None;
        ``variables``: {name: value} defined as index variables, as ``-var NAME VALUE`` does;
        ``dialect``: "lammps" or "pdps" for every script this simulation reads, or None (the default):
        the first script file's own lines decide (pdps_core.script.dialect), commands typed from
        Python are read as PDPS until then."""
        self.comm = comm if comm is not None else world()
        self.script = Script(self, dialect, variables)
        self._new_state()
        self.output = Output(self, screen=screen, log=log)

    def _new_state(self):
        """Every part but the script, the communicator and the output: what ``clear`` renews."""
        self.system = System(self)
        self.styles = StyleTables(self)
        self.run_state = RunState(self.system.units.dt)
        self.neighbor = Neighbor(skin=0.3)
        self.timers = Timers()

    # ---- numpy views of the owned particles -------------------------------------------------------
    @property
    def nlocal(self):
        return self.system.particles.nlocal

    def _owned(self, name):
        particles = self.system.particles
        return particles.arrays[name][: particles.nlocal]

    x = property(lambda self: self._owned("x"), doc="positions of owned particles (n x 3 view)")
    v = property(lambda self: self._owned("v"), doc="velocities of owned particles (n x 3 view)")
    f = property(lambda self: self._owned("f"), doc="forces on owned particles (n x 3 view)")
    tag = property(lambda self: self._owned("tag"), doc="global ids of owned particles")
    type = property(lambda self: self._owned("type"), doc="types of owned particles")

    # ---- scripts ----------------------------------------------------------------------------------
    def file(self, path):
        """Run a whole script file."""
        self.script.file(path)
        return self

    def command(self, text):
        """Run one or more lines of script text (a ``quit`` among them ends them there)."""
        try:
            self.script.text(text, "<command>", os.getcwd())
        except ScriptQuit as exc:
            self.script.exit_status = exc.status
        return self

    def execute(self, words):
        """Run one command given as words: the single path scripts and typed calls share."""
        self.script.execute(words)

    def evaluate(self, value):
        """A style argument's value now: a number as it is, ``v_NAME`` (a ``VariableRef``) evaluated."""
        if isinstance(value, VariableRef):
            if value.name not in self.script.variables:
                raise ScriptError(f"variable {value.name} is not defined (argument v_{value.name})")
            return float(self.script.variables.value(value.name))
        return value

    def info(self, message):
        """A line on screen and in the log (a style's summary or notice)."""
        self.output.message(message)

    def change_timestep(self, dt):
        """A new time step in the middle of a run (fix dt/reset): the pair style and every fix that
        keeps constants of the step redo them in their ``reset_dt(sim)`` (LAMMPS's reset_dt), and
        the time goes on with the new step."""
        self.run_state.dt = dt
        for style in (self.pair, *self.fixes.values()):
            reset = getattr(style, "reset_dt", None)
            if reset is not None:
                reset(self)

    def warn(self, message):
        """A warning on screen and in the log, kept in ``sim.warnings``; the run goes on."""
        self.output.warn(message)

    def region(self, id, style=None, *args):
        """``region(id)`` looks a region up; ``region(id, style, *args)`` defines one."""
        if style is not None:
            return self._call("region", id, style, *args)
        return self.system.region(id)

    # ---- typed calls for the common commands (the same path as script lines) ----------------------
    def _call(self, name, *args):
        self.script.execute([name, *(_word(a) for a in args)])
        return self

    def units_style(self, style: str):
        return self._call("units", style)

    def set_dimension(self, n: int):
        return self._call("dimension", n)

    def boundary(self, x: str, y: str, z: str):
        return self._call("boundary", x, y, z)

    def create_box(self, ntypes: int, region: str):
        return self._call("create_box", ntypes, region)

    def create_particle(self, type: int, style: str, *args):
        return self._call("create_particle", type, style, *args)

    def read_data(self, path: str):
        return self._call("read_data", path)

    def set_mass(self, type, value: float):
        return self._call("mass", type, value)

    def group(self, id: str, *definition):
        return self._call("group", id, *definition)

    def pair_style(self, style: str, *args):
        return self._call("pair_style", style, *args)

    def pair_coeff(self, i, j, *args):
        return self._call("pair_coeff", i, j, *args)

    def velocity(self, group: str, style: str, *args):
        return self._call("velocity", group, style, *args)

    def fix(self, id: str, group: str, style: str, *args):
        return self._call("fix", id, group, style, *args)

    def unfix(self, id: str):
        return self._call("unfix", id)

    def compute(self, id: str, group: str, style: str, *args):
        return self._call("compute", id, group, style, *args)

    def timestep(self, dt: float):
        return self._call("timestep", dt)

    def thermo(self, every: int):
        return self._call("thermo", every)

    def thermo_style(self, *keywords):
        return self._call("thermo_style", *keywords)

    def dump(self, id: str, group: str, style: str, every: int, path: str, *columns):
        return self._call("dump", id, group, style, every, path, *columns)

    def run(self, nsteps: int):
        return self._call("run", nsteps)

    def variable(self, name: str, style: str, *args):
        return self._call("variable", name, style, *args)

    # ---- neighbor lists for any style ------------------------------------------------------------
    def request_neighbor_list(self, kind="full", cutoff=None, *, occasional=False, group="all"):
        """A neighbor list for a fix, compute or analyze style, asked for in its ``init_run(sim)``
        (at the start of every run): ``kind`` "half" or "full"; ``cutoff`` a number or a
        (ntypes+1)^2 matrix (distance units); ``occasional`` True for a list built only when the
        style calls ``build_neighbor_list`` (LAMMPS's occasional lists), else it is rebuilt with
        the pair list; ``group``: only particles of that group have neighbors. Ghosts reach the
        largest cutoff asked for. Returns the ``NeighborList``."""
        if not self.run_state.in_init:
            raise ScriptError("neighbor lists are requested in a style's init_run(sim), at the start of a run")
        if cutoff is None:
            raise ScriptError("a neighbor list request needs a cutoff")
        return self.neighbor.request(kind, cutoff, ntypes=self.system.ntypes, occasional=occasional,
                                     groupbit=self.system.groups.bit(group))

    def build_neighbor_list(self, nlist):
        """Build an occasional list from the current positions (once per step; call it whenever the
        style needs the list, e.g. when a compute is read)."""
        if not any(nlist is r for r in self.neighbor.requests):
            raise ScriptError("this neighbor list belongs to an earlier run: request it again in init_run")
        return self.neighbor.build_occasional(nlist, self.system.particles, self.system.box, self.run_state.step)

    # ---- bonds -------------------------------------------------------------------------------------
    def bond_single(self, bond_type, rsq):
        """(F/r, energy) of one bond of ``bond_type`` at r^2 = ``rsq`` under the current run's bond
        styles ((0, 0) for a type none computes, or before a run)."""
        integrator = self.run_state.integrator
        forces = getattr(integrator, "bond_forces", None)
        return (0.0, 0.0) if forces is None else forces.single(int(bond_type), float(rsq))

    def interaction_energy(self):
        """In a run: the pair and bond energy where the particles stand now, f recomputed (Verlet's)."""
        if self.run_state.integrator is None:
            raise SimulationError("interaction_energy() is for styles inside a run")
        return self.run_state.integrator.interaction_energy()

    def bonds(self):
        """This rank's bonds as rows (i, j, type): i an owned row, j the nearest copy of its partner,
        turned-off bonds (type < 0) included, broken ones (type 0) not."""
        return self.system.topology.stored_bonds(self)

    @property
    def nbondtypes(self):
        """The box's number of bond types (0 without bonds)."""
        return self.system.topology.nbondtypes

    def fix_with(self, capability):
        """The first fix (in definition order) that has ``capability`` (a Protocol of
        pdps_core.api, e.g. HeatTransport), or None."""
        return next((fix for fix in self.fixes.values() if isinstance(fix, capability)), None)

    def create_bonds(self, pairs, bond_type):
        """New bonds of ``bond_type`` between the id pairs ``pairs`` ((k, 2), the same rows on every
        rank; fix bond/create), the special lists made again; a fix doing this mid-run also sets
        ``next_reneighbor`` to this step, so the neighbor lists see the new exclusions."""
        self.system.topology.create_bonds(self, pairs, int(bond_type))

    def break_bonds(self, pairs):
        """Delete the bonds between the id pairs ``pairs`` ((k, 2), the same rows on every rank; fix
        bond/break), the special lists made again (set ``next_reneighbor`` as for create_bonds)."""
        self.system.topology.break_bonds(self, pairs)

    # ---- running -----------------------------------------------------------------------------------
    def run_steps(self, nsteps, ramp_bounds=None):
        """Run ``nsteps`` timesteps (pdps_core/run/driver.py)."""
        driver.run_steps(self, nsteps, ramp_bounds)

    def minimize(self, etol, ftol, maxiter, maxeval):
        """LAMMPS's minimize (pdps_core/run/minimize.py); returns its result."""
        return driver.minimize(self, etol, ftol, maxiter, maxeval)

    def clear(self):
        """LAMMPS's clear: a new simulation, keeping the variables, the log, the screen, the dialect
        and where the script is."""
        self.output.forget_styles()
        self._new_state()

    def close(self):
        self.output.close()


for _part, _names in READ_THROUGH.items():
    for _name in _names:
        setattr(Simulation, _name, property(attrgetter(f"{_part}.{_name}"), doc=f"``{_part}.{_name}``"))


def _word(value):
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float) and math.isfinite(value):
        return repr(value)
    return str(value)
