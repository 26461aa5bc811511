"""Simulation: the one object a script or a Python user drives.

    from pdps_core.api import Simulation
    sim = Simulation(log=None)
    sim.file("in.water")            # a whole script
    sim.command("run 100")          # one or more lines of script
    sim.run(100)                    # the same, as a typed call
    sim.x, sim.v, sim.f             # numpy views of the owned particles

Script lines and typed calls go through one path: ``execute(words)``, which looks the command up in
``pdps_core.commands.COMMANDS``. Errors raise ``ScriptError`` naming the file, line and command.
"""

import math
import os
import time

import numpy as np

from .comm import world
from .commands import COMMANDS
from .commands.preflight import preflight, unknown_command
from .errors import ScriptError
from .neighbor.neighbor import Neighbor
from .output.output import Output
from .run.minimize import MinSettings
from .run.timers import Timers
from .script.context import FormulaContext
from .script.dialect import DIALECTS, detect, dialect_named
from .script.lexer import logical_lines, read_text, split_words, strip_comment, substitute
from .script.variables import Variables
from .state import limits
from .state.groups import Groups
from .state.particles import Particles, substyles
from .state.units import UNITS
from .styles import VariableRef


class ScriptFlow:
    """Where a script is: its lines, the next one, a jump asked for by the line just run, the state
    (variables, step, particle count) each backward jump last left from (a loop that comes back to
    the same state can never end), and whether the next jump is skipped (an exhausted ``next``, as
    LAMMPS)."""

    def __init__(self, source, lines, path=None):
        self.source, self.lines, self.at = source, lines, 0
        self.path = path            # the file read (None for commands typed from Python)
        self.jump = None
        self.seen = {}
        self.skip_jump = False


class Simulation:
    def __init__(self, *, screen=None, log="log.pdps", variables=None, comm=None, dialect=None):
        """``screen``: a text stream (default stdout) or False for silence; ``log``: a path or None;
        ``variables``: {name: value} defined as index variables, as ``-var NAME VALUE`` does;
        ``dialect``: "lammps" or "pdps" for every script this simulation reads, or None (the default):
        the first script file's own lines decide (pdps_core.script.dialect), commands typed from
        Python are read as PDPS until then."""
        self.dialect = DIALECTS["pdps"] if dialect is None else dialect_named(dialect, "dialect")
        self.dialect_fixed = dialect is not None   # given, or settled by the first script
        self.unit_system = UNITS["lj"]
        self.dimension = 3
        self.periodicity = ("p", "p", "p")
        self.box = None
        self.ntypes = 0
        self.type_mass = np.zeros(1)
        self.particle_style = "atomic"
        self.lattice = None
        self.particles = Particles()
        self.neighbors = Neighbor(skin=0.3)
        self.comm = comm if comm is not None else world()
        self.processors = None
        self.groups = Groups()
        self.regions = {}
        self.pair = None
        self.pair_list = None
        self.fixes = {}
        self.computes = {}
        self.analyzes = {}
        self.variables = Variables(lambda per_atom=False, vector=False: FormulaContext(self, per_atom, vector))
        for name, value in (variables or {}).items():
            values = [str(v) for v in value] if isinstance(value, (list, tuple)) else [str(value)]
            self.variables.define([name, "index", *values], from_command_line=True)
        self.output = Output(self, screen=screen, log=log)
        self.timers = Timers()
        self.ghost_velocity = False
        self.step = 0
        self.run_first_step = 0
        self.dt = self.unit_system.dt
        self.time = 0.0
        self.run_last_step = 0
        self.ramp_bounds = (0, 0)       # the run's first and last step, or run start/stop's
        self.random_epoch = 0           # reset_timestep backwards so far (random_key)
        self.highest_step = 0
        self.pe = 0.0
        self.evdwl = 0.0                # the pair style's share of pe (thermo evdwl)
        self.virial = np.zeros(6)
        self.eflag = False              # energy is computed on the current step (read by fixes)
        self.vflag = False              # virial is computed on the current step
        self.energy_step = None
        self.virial_step = None
        self.setup_done_step = None
        self.source = None
        self.line = None
        self.warnings = []
        self.in_setup = False         # True while a run computes its setup forces
        self.in_init = False          # True while styles' init_run is called (neighbor requests)
        self.error_location = None
        self._integrator = None
        self.restart_output = None     # the `restart N FILE` schedule (state/restart.py)
        self.min_settings = MinSettings()
        self.minimize_result = None
        self.restored_states = {}      # (kind, id) -> (style, state, instance) from read_restart
        self.box_changed = False       # change_box since the last neighbor decision (Verlet rebuilds)

    # ---- names a style reads ----------------------------------------------------------------------
    @property
    def units(self):
        return self.unit_system

    @property
    def mass(self):
        """Mass per type (index 0 unused); NaN where not yet set."""
        return self.type_mass

    @property
    def neighbor(self):
        return self.neighbors

    @property
    def particle_styles(self):
        """The particle styles in effect: (particle_style,), or the sub-styles of hybrid, so that
        ``"sphere" in sim.particle_styles`` holds for ``hybrid sphere molecular`` too."""
        return substyles(self.particle_style)

    # ---- numpy views of the owned particles -------------------------------------------------------
    @property
    def nlocal(self):
        return self.particles.nlocal

    def _owned(self, name):
        return self.particles.arrays[name][: self.particles.nlocal]

    x = property(lambda self: self._owned("x"), doc="positions of owned particles (n x 3 view)")
    v = property(lambda self: self._owned("v"), doc="velocities of owned particles (n x 3 view)")
    f = property(lambda self: self._owned("f"), doc="forces on owned particles (n x 3 view)")
    tag = property(lambda self: self._owned("tag"), doc="global ids of owned particles")
    type = property(lambda self: self._owned("type"), doc="types of owned particles")

    # ---- scripts ----------------------------------------------------------------------------------
    def file(self, path):
        """Run a whole script file."""
        shown = os.path.basename(path) if self.source is None else path
        self.include_depth = getattr(self, "include_depth", 0) + 1
        try:
            if self.include_depth > limits.MAX_INCLUDE_DEPTH:
                raise ScriptError(f"scripts include each other more than {limits.MAX_INCLUDE_DEPTH} deep "
                                  f"({path} includes itself?)")
            text = read_text(path, "input script", shown, top=self.source is None)
            here = os.path.dirname(os.path.abspath(path))
            if self.source is None:
                self._settle_dialect(text, shown, here)
                preflight(self, text, shown)
            self._script(text, shown, here, path)
        finally:
            self.include_depth -= 1
        return self

    def _settle_dialect(self, text, shown, directory):
        """The top script's dialect: given, or read off its lines and those of the files it includes;
        named on the first output line."""
        found, reason = detect(text, shown, directory)
        if self.dialect_fixed:
            if reason.startswith("dialect on line") and found is not self.dialect:
                raise ScriptError(f"dialect {found.name} ({reason}) contradicts the dialect given "
                                  f"({self.dialect.name})", source=shown)
            reason = "as asked"
        else:
            self.dialect, self.dialect_fixed = found, True
        self.output.message(f"read as {self.dialect.label}: {reason}")

    def dialect_index(self, index, what):
        """A script's index (c_ID[i], f_ID[i], a per-atom column) as a 0-based one."""
        base = self.dialect.index_base
        if index < base:
            raise ScriptError(f"{what}: indices count from {base} in the {self.dialect.label} dialect "
                              f"(got {index})")
        return index - base

    def command(self, text):
        """Run one or more lines of script text."""
        self._script(text, "<command>", os.getcwd())
        return self

    def _script(self, text, source, directory, path=None):
        outer = self.source, self.line, getattr(self, "directory", None), getattr(self, "_flow", None)
        self.source, self.directory = source, directory
        self._flow = flow = ScriptFlow(source, list(logical_lines(text)), path)
        try:
            while flow.at < len(flow.lines):
                number, raw = flow.lines[flow.at]
                flow.at += 1
                self._line(number, raw, source)
                if flow.jump is not None:
                    source, directory = self._take_jump(flow, source, directory)
        finally:
            self.source, self.line, self.directory, self._flow = outer

    def _line(self, number, raw, source):
        """Run one logical line of a script (substituted, echoed), located in errors."""
        self.line = number
        first = raw.split(maxsplit=1)
        name = first[0] if first else None      # known even if the line cannot be read
        try:
            line = substitute(strip_comment(raw), self.variables.text)
            words = split_words(line)
            if not words:
                return
            self.output.echo(line.strip())
            self.execute(words)
        except ScriptError as exc:
            raise exc.locate(source, number, name)
        except MemoryError as exc:
            # a valid scene too large for this machine is the user's to resize, not a bug
            message = str(exc).split(" for an array")[0].rstrip(".") or "an allocation failed"
            raise ScriptError(f"out of memory ({message}): the scene needs more memory "
                              "than this machine gives").locate(source, number, name) from None
        except Exception:
            # the innermost place a bug surfaced, for the one-line internal error
            if self.error_location is None:
                self.error_location = (source, number)
            raise

    def _take_jump(self, flow, source, directory):
        line = self.line
        try:
            return self._jump_to(flow, source, directory)
        except ScriptError as exc:
            raise exc.locate(source, line, "jump") from None

    def _jump_to(self, flow, source, directory):
        """Carry out ``jump FILE [LABEL]``: this script from its label, or another file in its place
        (LAMMPS's jump); a backward jump with nothing changed since the last one is an endless loop.
        Jumping to the script's own file by name is jumping to SELF: the same loop, the same check."""
        target, label = flow.jump
        flow.jump = None
        path = None if target == "SELF" else self.resolve(target)
        same_file = target == "SELF" or (flow.path is not None and _same_file(path, flow.path))
        if not same_file:
            text = read_text(path, "input script", path)
            source, directory = path, os.path.dirname(os.path.abspath(path))
            self.source, self.directory = source, directory
            flow.source, flow.lines, flow.at, flow.path = source, list(logical_lines(text)), 0, path
            flow.seen = {}
        if label is None:
            start = 0
        else:
            start = next((k + 1 for k, (_, raw) in enumerate(flow.lines)
                          if raw.split()[:2] == ["label", label]), None)
            if start is None:
                raise ScriptError(f"label {label} is not in {source}", source=source, line=self.line,
                                  command="jump")
        backward = same_file and start <= flow.at
        if backward:
            state = (self.variables.signature(), self.step, self.particles.nlocal)
            if flow.seen.get(start) == state:
                raise ScriptError(f"jump {target} {label or ''}: an endless loop (variables, step and particles "
                                  "are as they were at the last jump back)".replace("  ", " "),
                                  source=source, line=self.line, command="jump")
            flow.seen[start] = state
        flow.at = start
        return source, directory

    def execute(self, words):
        """Run one command given as words: the single path scripts and typed calls share."""
        name, args = words[0], list(words[1:])
        entry = COMMANDS.get(name)
        if entry is None:
            raise ScriptError(unknown_command(name), command=name)
        try:
            # numpy's floating-point warnings never reach the screen raw: the checks that matter
            # (non-finite positions and forces, lost particles) report in the core's own words
            with np.errstate(all="ignore"):
                entry(self, args)
        except ScriptError as exc:
            if exc.command is None:
                exc.command = name
            raise

    def resolve(self, path):
        """A file path named in a script, relative to the directory of that script."""
        if os.path.isabs(path) or getattr(self, "directory", None) is None:
            return path
        candidate = os.path.join(self.directory, path)
        return candidate if os.path.exists(candidate) or not os.path.exists(path) else path

    # ---- typed calls for the common commands (the same path as script lines) ----------------------
    def _call(self, name, *args):
        self.execute([name, *(_word(a) for a in args)])
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
        if not self.in_init:
            raise ScriptError("neighbor lists are requested in a style's init_run(sim), at the start of a run")
        if cutoff is None:
            raise ScriptError("a neighbor list request needs a cutoff")
        return self.neighbors.request(kind, cutoff, ntypes=self.ntypes, occasional=occasional,
                                      groupbit=self.groups.bit(group))

    def build_neighbor_list(self, nlist):
        """Build an occasional list from the current positions (once per step; call it whenever the
        style needs the list, e.g. when a compute is read)."""
        if not any(nlist is r for r in self.neighbors.requests):
            raise ScriptError("this neighbor list belongs to an earlier run: request it again in init_run")
        return self.neighbors.build_occasional(nlist, self.particles, self.box, self.step)

    # ---- a box that changes during a run -----------------------------------------------------------
    def change_box(self, lo, hi, remap=None):
        """Give the box new bounds ``lo``, ``hi`` (3 each) now, as LAMMPS's ``set_global_box``.
        ``remap``: a group name whose owned particles keep their fractional position in the box
        (LAMMPS's x2lamda / lamda2x: x' = lo' + (hi' - lo') (x - lo) / (hi - lo)); None moves none.
        The next neighbor decision rebuilds the lists (wrap, migrate, ghosts with the new image
        shifts), so every step the box changes is a rebuild step. Collective under MPI: every rank
        passes the same bounds."""
        box = self.box
        if remap is None:
            box.set_bounds(lo, hi)
        else:
            chosen = self.groups.select(self, remap)
            x = self.particles.x[: self.particles.nlocal]
            lamda = (x[chosen] - box.lo) * (1.0 / box.length)
            box.set_bounds(lo, hi)
            x[chosen] = box.length * lamda + box.lo
        self.box_changed = True

    # ---- particles inserted and deleted by styles ------------------------------------------------
    def add_particles(self, x, type, v=None, **per_atom):
        """Insert owned particles at positions ``x`` (n x 3) of ``type`` (one or n), velocities ``v``
        and other per-atom values (``radius=...``, ``rmass=...``, ``mask=...``); returns their row
        indices. Collective under MPI: every rank calls it (with n = 0 where it inserts nothing);
        ids continue after the largest id on any rank, rank by rank, so they stay globally unique.
        Call it from ``pre_exchange`` on a step the fix asked a rebuild for (``next_reneighbor``):
        the particles are then wrapped, migrated to their owners and listed on that very step."""
        x = np.atleast_2d(np.asarray(x, dtype=np.float64)).reshape(-1, 3)
        counts = self.comm.allgather_rows(np.array([[len(x)]], dtype=np.int64)).ravel()
        p = self.particles
        largest = int(self.comm.max(int(p.tag[: p.nlocal].max()) if p.nlocal else 0))
        first = largest + 1 + int(counts[: self.comm.rank].sum())
        tags = np.arange(first, first + len(x), dtype=np.int64)
        if v is not None:
            per_atom["v"] = v
        rows = p.add(x, type, tags=tags, **per_atom)
        p.next_tag = max(p.next_tag, largest + 1 + int(counts.sum()))
        return rows

    def delete_particles(self, rows):
        """Remove the owned particles at ``rows`` (indices or a boolean mask over owned particles),
        from ``pre_exchange`` on a rebuild step as for insertion. Ids are not reused."""
        p = self.particles
        keep = np.ones(p.nlocal, dtype=bool)
        keep[rows] = False
        p.keep(np.flatnonzero(keep))

    # ---- random numbers ----------------------------------------------------------------------------
    def random_key(self, seed):
        """The key a style's random numbers use for its ``seed``: the seed itself until
        reset_timestep sends the step back to steps already run, then a new key for each such
        reset, so a production run after ``reset_timestep 0`` does not replay the noise of the
        equilibration (LAMMPS's generators never rewind either)."""
        if self.random_epoch == 0:
            return seed
        return (seed + self.random_epoch * 0x9E3779B97F4A7C15) % (2 ** 63 - 1) + 1

    def reset_step(self, step):
        """reset_timestep: a step below one already reached starts a new random epoch."""
        self.highest_step = max(self.highest_step, self.step)
        if step < self.highest_step:
            self.random_epoch += 1
            self.highest_step = step
        self.step = step

    def clear(self):
        """LAMMPS's clear: a new simulation, keeping the variables, the log, the screen, the dialect
        and where the script is."""
        for dump in self.output.dumps.values():
            close = getattr(dump, "close", None)
            if callable(close):
                close()
        keep = {name: getattr(self, name) for name in ("variables", "output", "comm", "dialect",
                                                       "dialect_fixed", "source", "line", "directory",
                                                       "include_depth", "_flow") if hasattr(self, name)}
        self.__init__(screen=False, log=None, comm=self.comm)
        self.__dict__.update(keep)
        from .output.thermo import Thermo
        self.output.dumps = {}
        self.output.thermo = Thermo(self)

    # ---- run information ---------------------------------------------------------------------------
    def ramp(self, start, stop):
        """start + (stop - start) * (step - first step) / (last step - first step) of the current run
        (of ``run N start S stop E``'s S and E when given): LAMMPS's ramp(x, y), what a thermostat
        ramping T_START to T_STOP reads each step."""
        first, last = self.ramp_bounds
        if last <= first:
            return start
        return start + (stop - start) * (self.step - first) / (last - first)

    def evaluate(self, value):
        """A style argument's value now: a number as it is, ``v_NAME`` (a ``VariableRef``) evaluated."""
        if isinstance(value, VariableRef):
            name = value.name
            if name not in self.variables:
                raise ScriptError(f"variable {name} is not defined (argument v_{name})")
            return float(self.variables.value(name))
        return value

    # ---- state helpers used by commands and styles -----------------------------------------------
    def substitute(self, text):
        """``text`` with ``$x``, ``${name}`` and ``$(formula)`` replaced now, as a script line is."""
        return substitute(text, self.variables.text)

    def info(self, message):
        """A line on screen and in the log (a style's summary or notice)."""
        self.output.message(message)

    def warn(self, message):
        """A warning on screen and in the log, kept in ``sim.warnings``; the run goes on."""
        self.warnings.append(message)
        self.output.message(f"WARNING: {message}")

    def require_box(self, what):
        if self.box is None:
            raise ScriptError(f"{what} before the simulation box exists (use create_box or read_data first)")

    def region(self, id, style=None, *args):
        """``region(id)`` looks a region up; ``region(id, style, *args)`` defines one."""
        if style is not None:
            return self._call("region", id, style, *args)
        try:
            return self.regions[id]
        except KeyError:
            raise ScriptError(f"region {id} is not defined (defined: {', '.join(self.regions) or 'none'})") from None

    def require_group(self, name):
        self.groups.bit(name)
        return name

    def find_compute(self, ident):
        """The compute of that ID: the script's, else one of thermo's own that every LAMMPS run
        defines (thermo_temp, thermo_press, thermo_pe), else None."""
        from .output.thermo import THERMO_COMPUTES
        return self.computes.get(ident) or THERMO_COMPUTES.get(ident)

    def compute_value(self, ident, indices=()):
        """``c_ID``, ``c_ID[i]``, ``c_ID[i][j]``: a compute's scalar, vector element or array element."""
        compute = self.find_compute(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined")
        return self._style_value("c", compute, ident, indices)

    def fix_value(self, ident, indices=()):
        """``f_ID[...]``: what a fix or analyze style offers through scalar/vector/array, as LAMMPS's
        f_ references (analyze styles share the prefix: their IDs are in the same script namespace)."""
        style = self.fixes.get(ident) or self.analyzes.get(ident)
        if style is None:
            raise ScriptError(f"fix {ident} is not defined")
        return self._style_value("f", style, ident, indices)

    def _style_value(self, prefix, style, ident, indices):
        reader = {0: "scalar", 1: "vector"}.get(len(indices), "array")
        method = getattr(style, reader, None)
        if method is None:
            raise ScriptError(f"{prefix}_{ident}: {style.kind} {ident} ({style.name}) has no {reader} value")
        if len(indices) == 0:
            return float(method(self))
        values = method(self)
        shown = f"{prefix}_{ident}{''.join(f'[{i}]' for i in indices)}"
        position = tuple(self.dialect_index(i, shown) for i in indices)
        try:
            return float(values[position])
        except IndexError:
            raise ScriptError(f"{shown} is out of range ({style.kind} {ident} has shape {np.shape(values)}; "
                              f"indices count from {self.dialect.index_base})") from None

    def compute_needs(self, ident):
        compute = self.find_compute(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined")
        return ({"energy"} if compute.needs_energy else set()) | ({"virial"} if compute.needs_virial else set())

    def require_energy(self):
        if self.energy_step != self.step:
            raise ScriptError(f"potential energy was not computed on step {self.step}: "
                              "read it on a thermo step, or run 0 first")

    def require_virial(self):
        if self.virial_step != self.step:
            raise ScriptError(f"virial was not computed on step {self.step}: "
                              "read it on a thermo step, or run 0 first")

    # ---- running -----------------------------------------------------------------------------------
    def run_steps(self, nsteps, ramp_bounds=None):
        from .run.verlet import Verlet
        self.require_box("run")
        self._check_masses()
        self.ramp_bounds = (self.step, self.step + nsteps) if ramp_bounds is None else tuple(ramp_bounds)
        t_start = time.perf_counter()
        self.run_first_step = self.step
        last = self.step + nsteps
        self.run_last_step = last
        self.run_wall_start = None      # thermo's cpu counts from the loop's start, 0 before
        self.output.thermo.last_clock = None
        integrator = Verlet(self)
        self._integrator = integrator
        if self.restored_states:
            from .state.restart import hand_over_states
            hand_over_states(self)
        try:
            integrator.setup()
            self.output.setup(self.step, last)
            self.timers.reset()
            t_loop = time.perf_counter()
            self.run_wall_start = t_loop
            integrator.run(nsteps)
            loop = time.perf_counter() - t_loop
        finally:
            self.output.flush()
        # between runs ramp() reads its start value, as LAMMPS's (its run's first and last steps collapse)
        self.ramp_bounds = (self.step, self.step)
        self._report(nsteps, loop, time.perf_counter() - t_start)
        self.output.flush()

    def minimize(self, etol, ftol, maxiter, maxeval):
        """LAMMPS's minimize (pdps_core/run/minimize.py); the result is kept in ``minimize_result``."""
        from .run.minimize import Minimizer
        self.require_box("minimize")
        self._check_masses()
        self.run_first_step, self.run_last_step = self.step, self.step + maxiter
        self.ramp_bounds = (self.step, self.step + maxiter)
        self.run_wall_start = None
        self.output.thermo.last_clock = None
        minimizer = Minimizer(self, self.min_settings)
        self._integrator = minimizer
        try:
            self.minimize_result = minimizer.minimize(etol, ftol, maxiter, maxeval)
        finally:
            self.output.flush()
        self.run_last_step = self.step
        return self.minimize_result

    def _check_masses(self):
        p = self.particles
        if p.has("rmass") or p.nlocal == 0:
            return
        used = np.unique(p.type[: p.nlocal])
        unset = [int(t) for t in used if not (self.type_mass[t] > 0)]
        if unset:
            raise ScriptError(f"mass is not set for type {unset[0]} (use the mass command)")

    def _report(self, nsteps, loop, total):
        n = int(self.comm.sum(self.particles.nlocal))
        loop = float(self.comm.max(loop))
        message = self.output.message
        message(f"Loop time of {loop:.6g} on {self.comm.nprocs} procs for {nsteps} steps with {n} particles")
        if loop > 0 and nsteps:
            message(f"Performance: {nsteps / loop:.4g} timesteps/s, {n * nsteps / loop / 1e6:.4g} M particle-steps/s")
        for line in self.timers.report(loop):
            message(line)
        neighbor = self.neighbors
        if neighbor.requests:
            message(f"Neighbor list builds = {neighbor.builds}, dangerous builds = {neighbor.dangerous}")
        message("")

    def close(self):
        self.output.close()


def _same_file(a, b):
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _word(value):
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float) and math.isfinite(value):
        return repr(value)
    return str(value)
