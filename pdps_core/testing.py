"""The test kit for style authors: small systems, and the checks every style should pass.

Use it from a plugin's tests (the fixtures come with pdps-core through its pytest plugin, so no
conftest is needed)::

    from pdps_core.testing import build, energy_gradient, forces_by_tag

    def test_force_is_minus_gradient(tmp_path):
        sim = build(tmp_path, [[5, 5, 5], [6.1, 5.2, 5.0]], setup="pair_style lj/cut 2.5\\n"
                    "pair_coeff * * 1.0 1.0")
        analytic, numeric = energy_gradient(sim)
        assert numeric == pytest.approx(analytic, rel=1e-6, abs=1e-9)

What is here:

- ``write_data``, ``build``: a Simulation holding given particles (through a LAMMPS data file, so
  the path a user's read_data takes), ``fluid``: random positions at a density, without overlaps;
  ``bench_data``: the benchmark scenes' data files (dpd_water, dpd_gw, gran_box, lj_fcc), as LAMMPS reads them.
- ``lj_fcc``: the opening lines of LAMMPS's Lennard-Jones melt scene (an fcc crystal in a box of
  N unit cells a side), which many LAMMPS-dialect tests and recorders start from.
- ``liggghts_material``: the ``fix mN all property/global ...`` lines of a LIGGGHTS granular
  material (Young's modulus, Poisson's ratio, restitution, friction and any other property);
  ``liggghts_one_particle``: a LIGGGHTS script's opening with one particle in a box.
- ``sphere_bed``: a data file of polydisperse spheres on a jittered lattice with random velocities
  (the granular styles' scene for same-answers-on-any-number-of-ranks tests).
- ``make_box``: a silent Simulation with an empty block box, then the script lines given
  (create_particle, pair_style, fixes...).
- ``sphere_mass``: the mass create_particle gives a sphere of a diameter and density;
  ``unwrapped``: positions with their periodic images undone, in id order.
- test styles, so a plugin's tests need no other plugin: fix ``test/nve_sphere`` (``SphereVerlet``,
  velocity Verlet for x, v and the spin of spheres), ``test/force`` (``ConstantForce``),
  ``test/record`` (``Record``, the particles' state after every step) and pair style
  ``test/no_force`` (``NoForcePair``: neighbor lists and no forces); ``register_styles`` makes these,
  or a test's own styles, usable in scripts.
- ``forces_by_tag``, ``energy_gradient``: forces in id order; forces against central differences
  of the total potential energy; ``two_type_cluster`` and ``assert_force_is_minus_gradient``: every
  pair style's scene and check of that (four particles of two types at different separations).
- ``total_force``, ``total_momentum``: Newton's third law and momentum conservation.
- ``run_ranks``: a script run with ``mpiexec -n N`` (thermo lines back), for same-answers-on-any-
  number-of-ranks tests; ``thermo_rows`` reads thermo tables from a log or screen text,
  ``thermo_csv`` the full-precision CSV a run writes next to its log; ``logged_thermo``: the thermo
  rows a script run from a file prints to its log.
- ``lammps_thermo``, ``assert_thermo_as_lammps``: a LAMMPS-dialect script run in a folder with the
  files it reads, its thermo rows at full precision; those rows against LAMMPS's, recorded as
  tab-separated ``case step value...`` lines (every plugin's "thermo as LAMMPS prints it" test).
- ``recorded_case``: a LAMMPS reference case (script, data file with spins) run with a test/record
  fix; ``sphere_spins``: the spins of a sphere data file's Velocities section.
- ``restart_round_trip``: run N+M steps in one go, and N, write_restart, read_restart, M; both
  final states are returned for comparison.
- ``script_error``: the one-line error a script line is refused with (every style's "bad input is
  named" test); ``assert_refused``: a ``pdps run`` refused with its one ``ERROR: in.test:LINE: ...`` line.
- fixtures ``make_sim`` (a silent Simulation in a temporary folder) and ``pdps_cli`` (``pdps run``
  in-process, returning exit code, stdout and stderr).
"""

import math
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from .errors import ScriptError
from .simulation import Simulation
from .state import observables
from .styles import Fix, Pair, StyleArgs, keyword, registry

DEFAULT_SEED = 12345


# ---- systems ------------------------------------------------------------------------------------
def write_data(path, lo, hi, x, *, types=None, tags=None, velocities=None, masses=None):
    """A LAMMPS data file (atomic style) with the particles ``x`` (n x 3), their types (default 1),
    ids (default 1..n), velocities and masses per type (default 1.0), to full precision."""
    x = np.atleast_2d(np.asarray(x, dtype=float))
    n = len(x)
    types = np.ones(n, dtype=int) if types is None else np.asarray(types, dtype=int)
    tags = np.arange(1, n + 1) if tags is None else np.asarray(tags, dtype=int)
    ntypes = int(types.max()) if n else 1
    masses = masses or {t: 1.0 for t in range(1, ntypes + 1)}
    lines = ["written by pdps_core.testing", "", f"{n} atoms", f"{ntypes} atom types", ""]
    lines += [f"{lo[d]:.17g} {hi[d]:.17g} {a}lo {a}hi" for d, a in enumerate("xyz")]
    lines += ["", "Masses", ""] + [f"{t} {m:.17g}" for t, m in masses.items()]
    lines += ["", "Atoms # atomic", ""]
    lines += [f"{tags[i]} {types[i]} {x[i, 0]:.17g} {x[i, 1]:.17g} {x[i, 2]:.17g}" for i in range(n)]
    if velocities is not None:
        velocities = np.asarray(velocities, dtype=float)
        lines += ["", "Velocities", ""]
        lines += [f"{tags[i]} {velocities[i, 0]:.17g} {velocities[i, 1]:.17g} {velocities[i, 2]:.17g}"
                  for i in range(n)]
    Path(path).write_text("\n".join(lines) + "\n")
    return path


def build(tmp_path, x, *, setup="", types=None, tags=None, v=None, masses=None,
          lo=(0.0, 0.0, 0.0), hi=(10.0, 10.0, 10.0), boundary="p p p", units="lj", name="data.test",
          log=None):
    """A silent Simulation holding the particles ``x`` (read from a data file in ``tmp_path``), with
    the script lines ``setup`` (pair_style, pair_coeff, fixes...) run after read_data. ``log``: a
    log file path (its thermo CSV is ``LOG.csv``; see ``thermo_csv``)."""
    path = write_data(Path(tmp_path) / name, lo, hi, x, types=types, tags=tags, velocities=v,
                      masses=masses)
    sim = Simulation(screen=False, log=None if log is None else str(log))
    sim.command(f"units {units}\nboundary {boundary}\nread_data {path}")
    if setup:
        sim.command(textwrap.dedent(setup))
    return sim


def make_box(setup="", *, box="0 10 0 10 0 10", boundary="p p p", ntypes=1, particle_style=None,
             dimension=None, units="lj", screen=False):
    """A Simulation with the block ``box`` (``region box block BOX``, ``create_box NTYPES box``)
    and no particles, then the script lines ``setup`` run. ``particle_style`` and ``dimension`` are
    set only when given; ``screen`` as Simulation's (an io.StringIO keeps what the run prints)."""
    sim = Simulation(screen=screen, log=None)
    lines = [f"units {units}"]
    if dimension is not None:
        lines.append(f"dimension {dimension}")
    lines.append(f"boundary {boundary}")
    if particle_style is not None:
        lines.append(f"particle_style {particle_style}")
    lines += [f"region box block {box}", f"create_box {ntypes} box"]
    sim.command("\n".join(lines))
    if setup:
        sim.command(textwrap.dedent(setup))
    return sim


def lj_fcc(cells, ntypes=1, *, density=0.8442, atom_style="atomic"):
    """The opening of LAMMPS's melt example (bench/in.lj) as script lines: units lj, atom_style atomic,
    an fcc lattice of reduced density 0.8442 filling a box of ``cells`` unit cells a side, created
    with ``ntypes`` particle types and a particle of type 1 on every site (no masses yet). Another
    ``density`` or ``atom_style`` (molecular) changes those lines."""
    return (f"units lj\natom_style {atom_style}\nlattice fcc {density}\n"
            f"region box block 0 {cells} 0 {cells} 0 {cells}\ncreate_box {ntypes} box\ncreate_atoms 1 box\n")


def liggghts_one_particle(ntypes=1):
    """A LIGGGHTS script's opening in five lines: atom_style granular, SI units, a box from -1 to 1 m
    of ``ntypes`` particle types and one particle of type 1 at its centre (the scene of the
    bad-line tests of the granular styles)."""
    return (f"atom_style granular\nunits si\nregion reg block -1 1 -1 1 -1 1 units box\ncreate_box {ntypes} reg\n"
            "create_atoms 1 single 0 0 0 units box\n")


_TYPE_PAIR_PROPERTIES = {"coefficientRestitution", "coefficientFriction", "coefficientRollingFriction",
                         "cohesionEnergyDensity", "coefficientRollingViscousDamping"}


def liggghts_material(young, poisson, restitution, friction, **more):
    """The LIGGGHTS material as script lines, ``fix m1 all property/global youngsModulus ...``, then
    m2 poissonsRatio, m3 coefficientRestitution, m4 coefficientFriction and m5... for ``more``, in the
    order given, by their LIGGGHTS names (characteristicVelocity=1.0, thermalConductivity=(5, 5),
    cohesionEnergyDensity=3e4...). A per-type property takes a value or one per type; a type-pair
    table (restitution, friction, rolling friction, cohesion energy density) a value for one type
    or the ntypes x ntypes table row by row; characteristicVelocity is a scalar."""
    properties = {"youngsModulus": young, "poissonsRatio": poisson, "coefficientRestitution": restitution,
                  "coefficientFriction": friction, **more}
    lines = []
    for number, (name, values) in enumerate(properties.items(), start=1):
        if name == "characteristicVelocity":
            lines.append(f"fix m{number} all property/global {name} scalar {values}")
            continue
        values = list(values) if isinstance(values, (list, tuple)) else [values]
        if name in _TYPE_PAIR_PROPERTIES:
            ntypes = math.isqrt(len(values))
            lines.append(f"fix m{number} all property/global {name} peratomtypepair {ntypes} "
                         + " ".join(map(str, values)))
        else:
            lines.append(f"fix m{number} all property/global {name} peratomtype " + " ".join(map(str, values)))
    return "\n".join(lines) + "\n"


def sphere_bed(path, cells, offset, lo, hi, *, ntypes, seed):
    """A LAMMPS data file (atom_style sphere) at ``path``: spheres of diameter 0.8-1.2 and density 6/pi
    (mass d^3) on a lattice of spacing 1.3, ``cells`` (nx, ny, nz) sites from ``offset``, each moved by
    up to 0.05, with Gaussian velocities of scale 0.5, all of type 1 in a box ``lo``-``hi`` of
    ``ntypes`` types; draws from numpy's generator of ``seed``."""
    rng = np.random.default_rng(seed)
    sites = np.mgrid[0:cells[0], 0:cells[1], 0:cells[2]].reshape(3, -1).T
    x = sites * 1.3 + np.asarray(offset) + rng.uniform(-0.05, 0.05, size=(len(sites), 3))
    d = rng.uniform(0.8, 1.2, size=len(x))
    v = rng.normal(scale=0.5, size=x.shape)
    lines = ["bed", "", f"{len(x)} atoms", f"{ntypes} atom types", ""]
    lines += [f"{lo[k]:g} {hi[k]:g} {a}lo {a}hi" for k, a in enumerate("xyz")]
    lines += ["", "Atoms # sphere", ""]
    lines += [f"{k} 1 {float(d[k - 1])!r} 1.9098593171027440 {float(p[0])!r} {float(p[1])!r} {float(p[2])!r}"
              for k, p in enumerate(x, 1)]
    lines += ["", "Velocities", ""]
    lines += [f"{k} {float(u[0])!r} {float(u[1])!r} {float(u[2])!r} 0 0 0" for k, u in enumerate(v, 1)]
    Path(path).write_text("\n".join(lines) + "\n")


def sphere_mass(diameter, density):
    """The mass of a solid sphere, density * pi d^3 / 6 (create_particle ... diameter D density RHO
    in 3-d)."""
    return density * math.pi * diameter ** 3 / 6.0


def fluid(n, density, *, seed=DEFAULT_SEED, min_distance=0.0, dimension=3):
    """``n`` random positions in a cube (a square in 2-d) of the given number density, no two closer
    than ``min_distance`` (periodic distances). Returns (x, L)."""
    length = (n / density) ** (1.0 / dimension)
    rng = np.random.default_rng(seed)
    x = np.zeros((n, 3))
    placed = 0
    for _ in range(1000 * n):
        if placed == n:
            break
        trial = rng.uniform(0.0, length, size=3)
        if dimension == 2:
            trial[2] = 0.0
        if min_distance > 0 and placed:
            delta = x[:placed] - trial
            delta -= length * np.round(delta / length)
            if dimension == 2:
                delta[:, 2] = 0.0
            if (np.einsum("ij,ij->i", delta, delta) < min_distance ** 2).any():
                continue
        x[placed] = trial
        placed += 1
    if placed < n:
        raise ValueError(f"could not place {n} particles {min_distance} apart at density {density}")
    return x, length



def bench_data(kind, path):
    """The data file of a benchmark scene, byte for byte as the benchmark kit's ``make_data.py``
    writes it for LAMMPS (so both engines read the same particles); returns ``path``.

    - ``dpd_water``: the PDPS manual's water example, 20 x 20 x 10 lattice sites of spacing
      0.5, 0.5, 1 in a cube of side 10 (4,000 particles).
    - ``dpd_gw``: Groot-Warren fluid, uniform random positions at rho = 3 in a cube of side 22
      (31,944 particles, seed 7).
    - ``gran_box``: 4,000 spheres of diameter 1 and mass 1 (sphere style) on a 20 x 20 x 10 lattice of
      spacing 1.1, jittered by +-0.04 (seed 3), above the floor of a 22.2 x 22.2 x 40 box.
    - ``lj_fcc``: LAMMPS's in.lj benchmark, fcc at reduced density 0.8442, 20^3 cells (32,000
      atoms), Gaussian velocities with zero total momentum scaled to T = 1.44 (seed 87287).
    - ``settle`` (pdps's own, for benchmarks/scenes/liggghts/in.settle; si units): 20,000 glass
      beads, diameters uniform in 3.0-3.6 mm, density 2500 kg/m^3, on a 50 x 50 x 8 lattice of
      spacing 3.7 mm jittered by +-0.04 mm (no two touch), the lowest layer's centres 1.95 mm above
      the floor of a 0.185 x 0.185 x 0.1 m box, with velocity components uniform in +-0.1 m/s
      (seed 11) so that they collide from the start.
    """
    if kind == "dpd_water":
        x = _bench_lattice(20, 20, 10, 1.0) * np.array([0.5, 0.5, 1.0])
        _bench_atomic(path, [0, 0, 0], [10, 10, 10], x)
    elif kind == "dpd_gw":
        rng = np.random.default_rng(7)
        length = 22.0
        x = rng.uniform(0, length, size=(int(round(3 * length ** 3)), 3))
        _bench_atomic(path, [0, 0, 0], [length] * 3, x)
    elif kind == "gran_box":
        x = _bench_lattice(20, 20, 10, 1.1) + np.array([0.6, 0.6, 1.0])
        x += np.random.default_rng(3).uniform(-0.04, 0.04, size=x.shape)
        _bench_sphere(path, [0, 0, 0], [22.2, 22.2, 40.0], x, diameter=1.0, density=1.9098593)
    elif kind == "lj_fcc":
        a = (4 / 0.8442) ** (1 / 3)
        basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
        x = ((_bench_lattice(20, 20, 20, 1.0)[:, None, :] + basis[None]) * a).reshape(-1, 3)
        v = np.random.default_rng(87287).normal(size=x.shape)
        v -= v.mean(axis=0)
        v *= np.sqrt(3 * 1.44 / (v ** 2).sum(axis=1).mean())
        _bench_atomic(path, [0, 0, 0], [20 * a] * 3, x, velocities=v)
    elif kind == "settle":
        rng = np.random.default_rng(11)
        x = _bench_lattice(50, 50, 8, 0.0037) + np.array([0.00185, 0.00185, 0.00195])
        x += rng.uniform(-0.00004, 0.00004, size=x.shape)
        diameter = rng.uniform(0.003, 0.0036, size=len(x))
        v = rng.uniform(-0.1, 0.1, size=x.shape)
        _bench_sphere(path, [0, 0, 0], [0.185, 0.185, 0.1], x, diameter=diameter, density=2500.0, velocities=v)
    else:
        raise ValueError(f"unknown benchmark scene {kind!r} (dpd_water, dpd_gw, gran_box, lj_fcc, settle)")
    return path


def _bench_lattice(nx, ny, nz, spacing):
    cells = np.mgrid[0:nx, 0:ny, 0:nz].reshape(3, -1).T.astype(float)
    return cells * spacing


def _bench_header(n, lo, hi):
    lines = ["generated for benchmarking", "", f"{n} atoms", "1 atom types", ""]
    return lines + [f"{lo[d]} {hi[d]} {a}lo {a}hi" for d, a in enumerate("xyz")]


def _bench_atomic(path, lo, hi, x, velocities=None):
    lines = _bench_header(len(x), lo, hi) + ["", "Masses", "", "1 1.0", "", "Atoms # atomic", ""]
    lines += [f"{i} 1 {p[0]:.10f} {p[1]:.10f} {p[2]:.10f}" for i, p in enumerate(x, 1)]
    if velocities is not None:
        lines += ["", "Velocities", ""]
        lines += [f"{i} {v[0]:.10f} {v[1]:.10f} {v[2]:.10f}" for i, v in enumerate(velocities, 1)]
    Path(path).write_text("\n".join(lines) + "\n")


def _bench_sphere(path, lo, hi, x, *, diameter, density, velocities=None):
    lines = _bench_header(len(x), lo, hi) + ["", "Atoms # sphere", ""]
    if np.ndim(diameter) == 0:
        lines += [f"{i} 1 {diameter} {density} {p[0]:.10f} {p[1]:.10f} {p[2]:.10f}" for i, p in enumerate(x, 1)]
    else:
        lines += [f"{i} 1 {d:.10f} {density} {p[0]:.10f} {p[1]:.10f} {p[2]:.10f}"
                  for i, (d, p) in enumerate(zip(diameter, x), 1)]
    if velocities is not None:
        lines += ["", "Velocities", ""]
        lines += [f"{i} {v[0]:.10f} {v[1]:.10f} {v[2]:.10f} 0 0 0" for i, v in enumerate(velocities, 1)]
    Path(path).write_text("\n".join(lines) + "\n")

# ---- checks -------------------------------------------------------------------------------------
def by_tag(sim, values):
    """Rows of an owned per-atom array, in id order."""
    return np.asarray(values)[np.argsort(sim.tag)]


def unwrapped(sim):
    """Owned positions with their periodic images undone, x + image * L, in id order."""
    return by_tag(sim, sim.x + sim.particles.image[: sim.nlocal] * sim.box.length)


def forces_by_tag(sim):
    return by_tag(sim, sim.f).copy()


def energy_gradient(sim, h=1e-6, particles=None):
    """(analytic, numeric): the forces of a ``run 0``, and minus the central difference of the total
    potential energy moving each coordinate by +-h, both (n, 3) in id order (only the ``particles``
    ids given, by default all). Serial runs only."""
    sim.command("run 0")
    analytic = forces_by_tag(sim)
    tags = np.sort(sim.tag) if particles is None else np.asarray(particles)
    numeric = np.zeros((len(tags), 3))
    for row, tag in enumerate(tags):
        i = sim.particles.index_of_tag(int(tag))
        for d in range(3):
            saved = sim.x[i, d]
            energies = []
            for sign in (1.0, -1.0):
                sim.x[i, d] = saved + sign * h
                sim.command("run 0")
                energies.append(total_energy(sim))
                i = sim.particles.index_of_tag(int(tag))
            sim.x[i, d] = saved
            numeric[row, d] = -(energies[0] - energies[1]) / (2.0 * h)
    sim.command("run 0")
    order = np.searchsorted(np.sort(sim.tag), tags)
    return analytic[order], numeric


def two_type_cluster(tmp_path, setup):
    """Four particles of types 1, 1, 2, 2 at separations from 1.1 to 2.1 (every type pair present),
    then ``setup``: the scene of the pair styles' force-against-energy checks."""
    x = [[5.0, 5.0, 5.0], [6.05, 5.3, 4.8], [4.4, 5.9, 5.6], [5.5, 4.1, 5.9]]
    return build(tmp_path, x, types=[1, 1, 2, 2], setup=setup)


def assert_force_is_minus_gradient(sim, *, rel, abs, largest):
    """The forces equal minus the central-difference gradient of the energy (h = 1e-6) to ``rel``
    and ``abs``, and the largest force component exceeds ``largest`` (so the check is not 0 = 0)."""
    analytic, numeric = energy_gradient(sim, h=1e-6)
    assert np.abs(analytic).max() > largest
    assert numeric == pytest.approx(analytic, rel=rel, abs=abs)


def total_energy(sim):
    """The potential energy of the whole system (pair and fixes that contribute), not per particle."""
    from .state import observables
    return observables.potential_energy(sim)


def total_force(sim):
    """Sum of the forces on all particles (zero for pair forces: Newton's third law)."""
    return np.asarray(sim.comm.sum(sim.f.sum(axis=0)))


def total_momentum(sim):
    from .state import observables
    m = observables.masses(sim)
    return np.asarray(sim.comm.sum((m[:, None] * sim.v).sum(axis=0)))


# ---- parallel runs and restarts -----------------------------------------------------------------
def mpiexec():
    """The mpiexec beside this Python (the mpich wheel installs it into the venv)."""
    candidate = Path(sys.executable).parent / "mpiexec"
    return str(candidate) if candidate.exists() else shutil.which("mpiexec")


def run_ranks(script, nprocs, cwd, *, name="in.test", timeout=600, log="none", dialect=None):
    """Run ``script`` (text) with ``mpiexec -n nprocs pdps run`` (its log to ``log``: a thermo CSV
    beside it); returns the CompletedProcess. Fails the test with the stderr when the run fails."""
    cwd = Path(cwd)
    (cwd / name).write_text(textwrap.dedent(script))
    command = [mpiexec(), "-n", str(nprocs), sys.executable, "-m", "pdps_core.cli", "run", name,
               "-log", log, "--no-progress"] + (["--dialect", dialect] if dialect else [])
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    if done.returncode != 0:
        pytest.fail(f"mpiexec -n {nprocs} pdps run {name} failed: {done.stderr.strip()}")
    return done


def thermo_on_ranks(script, cwd, ranks=(1, 2)):
    """The thermo rows (an array each) that ``script`` prints run with ``mpiexec -n`` each of ``ranks``:
    what a style prints must not depend on how many ranks run it."""
    return [np.array(thermo_rows(run_ranks(script, n, cwd).stdout)) for n in ranks]


def thermo_csv(path):
    """The thermo CSV a run wrote next to its log: {column name: array over thermo lines}."""
    lines = Path(path).read_text().splitlines()
    names = lines[0].split(",")
    values = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    return {name: values[:, k] for k, name in enumerate(names)}


def thermo_rows(text):
    """Every thermo line of a screen or log text as a list of floats (header lines skipped)."""
    rows, inside = [], False
    for line in text.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            inside = True
            continue
        if inside:
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                inside = False
            if not words:
                inside = False
    return rows


def assert_prints_as_lammps(tmp_path, script, lammps, *, rel=2e-8, abs=1e-12):
    """Run ``script`` in LAMMPS's dialect with its log in ``tmp_path``: its thermo rows are ``lammps``
    (the rows LAMMPS printed for it), as many and each to LAMMPS's printed digits. The log's text."""
    log = Path(tmp_path) / "log.case"
    sim = Simulation(screen=False, log=str(log), dialect="lammps")
    sim.command(script)
    sim.close()
    text = log.read_text()
    rows = thermo_rows(text)
    assert len(rows) == len(lammps)
    for got, want in zip(rows, lammps):
        assert got == pytest.approx(want, rel=rel, abs=abs), want[0]
    return text


def logged_thermo(folder, script):
    """The thermo rows (an array, as printed) that ``script``, written to ``folder``/in.case and run
    from there as ``pdps run`` does, prints to its log."""
    path, log = Path(folder) / "in.case", Path(folder) / "log.pdps"
    path.write_text(script)
    sim = Simulation(screen=False, log=str(log))
    sim.file(str(path))
    sim.close()
    return np.array(thermo_rows(log.read_text()))


def lammps_thermo(folder, monkeypatch, script, files=(), source=None, screen=False, dialect="lammps"):
    """Run ``script`` (LAMMPS's dialect unless ``dialect`` says another) in ``folder`` (the ``files``
    copied there from the folder ``source``) with its log at log.case; returns (the Simulation, its
    thermo rows as strings from the CSV beside the log: full precision, header dropped)."""
    for name in files:
        shutil.copy(Path(source) / name, Path(folder) / name)
    monkeypatch.chdir(folder)
    sim = Simulation(screen=screen, log="log.case", dialect=dialect)
    sim.command(script)
    sim.close()
    rows = [line.split(",") for line in (Path(folder) / "log.case.csv").read_text().splitlines()[1:]]
    return sim, rows


def lammps_rows(path, case=None):
    """LAMMPS's thermo rows recorded in ``path`` (tab-separated; with ``case``: the lines that
    begin with it, that word dropped)."""
    rows = [line.split("\t") for line in Path(path).read_text().splitlines()]
    return rows if case is None else [row[1:] for row in rows if row[0] == case]


def assert_thermo_as_lammps(mine, reference, what="", steps=(0, 25, 50, 75, 100), rtol=1e-9, atol=1e-12):
    """pdps's thermo rows (step first) against LAMMPS's, step for step, to ``rtol``/``atol``."""
    assert [int(r[0]) for r in mine] == [int(r[0]) for r in reference] == list(steps)
    for got, want in zip(mine, reference):
        np.testing.assert_allclose([float(v) for v in got[1:]], [float(v) for v in want[1:]], rtol=rtol,
                                   atol=atol, err_msg=f"{what} step {got[0]}")


def sphere_spins(data_text):
    """{tag: (wx, wy, wz)} from the Velocities section of a sphere data file (pdps reads only vx vy vz
    there, so a test sets the spins itself)."""
    spins, inside = {}, False
    for line in data_text.splitlines():
        words = line.split()
        if words[:1] == ["Velocities"]:
            inside = True
        elif inside and len(words) == 7:
            spins[int(words[0])] = tuple(float(w) for w in words[4:7])
    return spins


def recorded_case(folder, name, tmp_path, replace=()):
    """A LAMMPS reference case (folder/NAME.in reading NAME.data, its last line the run) run in pdps
    with the spins of the data file and a test/record fix; returns the Record (x, v, omega... after
    every step, in id order). ``replace``: (old, new) pairs applied to the script first (other
    plugins' styles swapped for the kit's test styles)."""
    script = (folder / f"{name}.in").read_text()
    for old, new in replace:
        script = script.replace(old, new)
    data = (folder / f"{name}.data").read_text()
    (tmp_path / f"{name}.data").write_text(data)
    lines = script.rstrip().splitlines()
    register_styles(Record)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("\n".join(lines[:-1]).replace(f"read_data {name}.data", f"read_data {tmp_path / name}.data"))
    for tag, spin in sphere_spins(data).items():
        sim.particles.omega[sim.particles.index_of_tag(tag)] = spin
    sim.command(f"fix record all test/record\n{lines[-1]}")
    return sim.fixes["record"]


def restart_round_trip(tmp_path, setup, first, second, *, split=False, again=""):
    """(straight, resumed): a Simulation that ran ``setup`` then ``run first+second`` (with
    ``split``: ``run first`` and ``run second``, for styles whose run set-up acts, as LAMMPS's
    barostats kick their strain rate), and one that ran ``setup``, ``run first``, wrote a restart
    file, and a fresh one that read it, gave the lines ``again`` a restart file does not hold (as
    LAMMPS scripts do: ``neigh_modify exclude ...``) and ran ``second``: both should hold the same
    particles for deterministic styles."""
    path = Path(tmp_path) / "round_trip.restart"
    straight = Simulation(screen=False, log=None)
    runs = f"run {first}\nrun {second}" if split else f"run {first + second}"
    straight.command(textwrap.dedent(setup) + f"\n{runs}")
    before = Simulation(screen=False, log=None)
    before.command(textwrap.dedent(setup) + f"\nrun {first}\nwrite_restart {path}")
    resumed = Simulation(screen=False, log=None)
    resumed.command(f"read_restart {path}\n{again}\nrun {second}")
    return straight, resumed


# what a LAMMPS or LIGGGHTS restart file holds (their read_restart pages): a script that reads one does
# not give these again
RESTART_HOLDS = frozenset({
    "units", "atom_style", "atom_modify", "dimension", "boundary", "lattice", "create_box", "create_atoms",
    "read_data", "mass", "velocity", "set", "displace_atoms", "delete_atoms", "group", "pair_style", "pair_coeff",
    "pair_modify", "bond_style", "bond_coeff", "special_bonds", "newton", "comm_modify", "communicate", "run"})


def given_again(script):
    """The lines of a LAMMPS or LIGGGHTS ``script`` that a script reading its restart file gives again:
    all but those the file holds (RESTART_HOLDS) and the runs; its fixes, computes, regions, thermo
    and neighbor settings."""
    kept = [line for line in textwrap.dedent(script).splitlines()
            if line.split()[:1] and line.split()[0] not in RESTART_HOLDS]
    return "\n".join(kept) + "\n"


def script_error(setup, line):
    """The ScriptError that ``line`` raises in a silent Simulation that first ran ``setup``."""
    sim = Simulation(screen=False, log=None)
    sim.command(setup)
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    return caught.value


# ---- test styles --------------------------------------------------------------------------------
def assert_refused(done, line, message):
    """``pdps run`` (the ``pdps_cli`` fixture's result) refused its script with one line: exit code 1
    and ``ERROR: in.test:LINE: message``."""
    assert done.returncode == 1
    assert done.stderr.strip() == f"ERROR: in.test:{line}: {message}"


def register_styles(*styles):
    """Make style classes usable in scripts under their ``name`` in this process: the test styles
    below, or a test's own (``register_styles(SphereVerlet, MyProbe)``)."""
    for style in styles:
        registry.register(style.kind, style.name, style)


class SphereVerlet(Fix):
    """``fix ID GROUP test/nve_sphere [rotate yes|no] [translate yes|no]``: velocity Verlet for x, v
    and the spin omega of solid spheres, I = 2/5 m r^2 (LAMMPS's fix nve/sphere), for the particles
    of the group. ``rotate no`` leaves omega alone (and serves point particles), ``translate no``
    leaves x and v alone. Masses are per particle when present, else per type."""
    name = "test/nve_sphere"

    class Args(StyleArgs):
        rotate: bool = keyword(True)
        translate: bool = keyword(True)

    def initial_integrate(self, sim):
        self.kick(sim)
        if self.args.translate:
            p = sim.particles
            chosen = sim.groups.select(sim, self.group)
            p.x[: p.nlocal][chosen] += sim.dt * p.v[: p.nlocal][chosen]

    def final_integrate(self, sim):
        self.kick(sim)

    def kick(self, sim):
        p, n = sim.particles, sim.particles.nlocal
        chosen = sim.groups.select(sim, self.group)
        half = 0.5 * sim.dt
        mass = observables.masses(sim, chosen)
        if self.args.translate:
            p.v[:n][chosen] += half * p.f[:n][chosen] / mass[:, None]
        if self.args.rotate:
            inertia = 0.4 * mass * p.radius[:n][chosen] ** 2
            p.omega[:n][chosen] += half * p.torque[:n][chosen] / inertia[:, None]


class NoForcePair(Pair):
    """``pair_style test/no_force`` with ``pair_coeff * *``: no forces and no energy, but the core
    builds its neighbor lists (and re-sorts particles) as for any pair style; a base for test pair
    styles."""
    name = "test/no_force"

    class Coeff(StyleArgs):
        pass

    def init_one(self, i, j):
        return 1.0

    def compute(self, sim, nlist, eflag, vflag):
        self.energy = 0.0


class ConstantForce(Fix):
    """``fix ID GROUP test/force FX FY FZ``: the force (FX, FY, FZ) on every particle of the group,
    also at setup so the first half-kick sees it (as LAMMPS's fix addforce)."""
    name = "test/force"

    class Args(StyleArgs):
        fx: float
        fy: float
        fz: float

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        chosen = sim.groups.select(sim, self.group)
        sim.f[chosen] += [self.args.fx, self.args.fy, self.args.fz]


class Record(Fix):
    """``fix ID GROUP test/record``: after every step (end_of_step), the time in ``t`` and the owned
    particles' ``x``, ``v``, ``f`` and, where the particles have them, ``omega`` and ``torque``, each
    a list of arrays in id order; ``series(key, particle)`` is one particle's history (0: the lowest
    id) as an array."""
    name = "test/record"
    KEYS = ("x", "v", "f", "omega", "torque")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.t = []
        for key in self.KEYS:
            setattr(self, key, [])

    def end_of_step(self, sim):
        p = sim.particles
        order = np.argsort(p.tag[: p.nlocal])
        self.t.append(sim.time)
        for key in self.KEYS:
            if p.has(key):
                getattr(self, key).append(p.arrays[key][: p.nlocal][order].copy())

    def series(self, key, particle=0):
        return np.array([row[particle] for row in getattr(self, key)])


class ContactsHeld(Fix):
    """``fix ID all test/contacts_held``, for a granular pair style in a periodic cube of edge
    ``EDGE``, on any number of ranks: at the end of every step, whether the owned particles' contact
    slots hold exactly the pairs of spheres that touch (found afresh by minimum image over every
    rank's spheres, each pair on both spheres), in ``exact``; whether they hold LIGGGHTS's pairs
    instead, in ``until_build``: those that touch and those that came apart since the last list
    build, exactly those that touch at a build; and how many pairs touch, in ``contacts`` (the same
    on every rank)."""
    name = "test/contacts_held"
    EDGE = 6.0

    def init_run(self, sim):
        self.exact, self.until_build, self.contacts = [], [], []
        self._last = set()

    def end_of_step(self, sim):
        p = sim.particles
        n, comm = p.nlocal, sim.comm
        owned = comm.allgather_rows(np.column_stack([p.tag[:n], p.radius[:n], p.x[:n]]))
        tag, radius, x = owned[:, 0].astype(np.int64), owned[:, 1], owned[:, 2:]
        delta = x[:, None, :] - x[None, :, :]
        delta -= self.EDGE * np.round(delta / self.EDGE)
        np.fill_diagonal(delta[..., 0], 2.0 * self.EDGE)
        i, j = np.nonzero((delta ** 2).sum(axis=2) < (radius[:, None] + radius[None, :]) ** 2)
        touching = set(zip(tag[i].tolist(), tag[j].tolist()))
        partner = sim.pair.history.partner[:n]
        rows, slots = np.nonzero(partner >= 0)
        pairs = comm.allgather_rows(np.column_stack([p.tag[:n][rows], partner[rows, slots]]).reshape(-1, 2))
        held = set(map(tuple, pairs.astype(np.int64).tolist()))
        once = len(pairs) == len(held)
        self.exact.append(held == touching and once)
        apart_since_build = held - touching <= self._last and sim.neighbor.ago > 0
        self.until_build.append(once and touching <= held and (held == touching or apart_since_build))
        self._last = held
        self.contacts.append(len(touching) // 2)


_CONTACTS_HELD_DRIVER = """
import sys
import numpy as np
from pdps_core.simulation import Simulation
from pdps_core.testing import ContactsHeld, register_styles
register_styles(ContactsHeld)
sim = Simulation(screen=False, log=None, dialect=sys.argv[1])
sim.file("in.setup")
p = sim.particles
velocities = np.load("velocities.npy")
p.v[: p.nlocal] = velocities[p.tag[: p.nlocal] - 1]
sim.command("fix contacts_held all test/contacts_held")
sim.command("run " + sys.argv[2])
check = sim.fixes["contacts_held"]
if sim.comm.is_root:
    np.save("held.npy", np.array([all(check.exact), sim.neighbor.builds, sum(check.contacts),
                                  all(check.until_build), len(check.exact) - sum(check.exact)]))
"""


def contacts_held_on_ranks(script, velocities, steps, nprocs, cwd, dialect="lammps"):
    """Run ``script`` (text: the spheres and their pair style, no run), the particles given
    ``velocities`` (by tag), for ``steps`` steps on ``nprocs`` ranks with fix test/contacts_held
    (``ContactsHeld``, a periodic cube of edge 6); returns (whether the slots held exactly the
    touching pairs at every step, list builds, touching pairs summed over the steps, whether they
    held LIGGGHTS's pairs at every step (ContactsHeld.until_build), steps they did not hold exactly
    the touching pairs)."""
    cwd = Path(cwd)
    (cwd / "in.setup").write_text(textwrap.dedent(script))
    (cwd / "driver.py").write_text(_CONTACTS_HELD_DRIVER)
    np.save(cwd / "velocities.npy", np.asarray(velocities, dtype=np.float64))
    done = subprocess.run([mpiexec(), "-n", str(nprocs), sys.executable, "driver.py", dialect, str(steps)],
                          cwd=cwd, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        pytest.fail(f"mpiexec -n {nprocs} driver.py failed: {done.stderr.strip()}")
    exact, builds, contacts, until_build, inexact = np.load(cwd / "held.npy")
    return bool(exact), int(builds), int(contacts), bool(until_build), int(inexact)


# ---- fixtures (registered as a pytest plugin by pdps-core) -------------------------------------
@pytest.fixture
def make_sim(tmp_path, monkeypatch):
    """A silent Simulation working in a temporary folder: ``make_sim()`` or with Simulation's
    keywords."""
    monkeypatch.chdir(tmp_path)

    def make(**kwargs):
        kwargs.setdefault("screen", False)
        kwargs.setdefault("log", None)
        return Simulation(**kwargs)
    return make


@pytest.fixture
def pdps_cli(tmp_path, monkeypatch, capsys):
    """``pdps run`` in-process in a temporary folder: writes the script, runs it and returns a
    CompletedProcess (exit code, stdout, stderr)."""
    from . import cli
    monkeypatch.chdir(tmp_path)

    def run(script, *extra, name="in.test"):
        (tmp_path / name).write_text(textwrap.dedent(script))
        argv = ["run", name, *extra]
        capsys.readouterr()
        code = cli.main(argv)
        out, err = capsys.readouterr()
        return subprocess.CompletedProcess(argv, code, out, err)
    return run

