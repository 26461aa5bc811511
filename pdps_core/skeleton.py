"""``pdps new-plugin NAME --kind KIND [--style STYLE]``: write a working, tested plugin to start from.

Each kind gets a complete distribution: ``pyproject.toml`` with the entry point, a package whose
``__init__.py`` declares the style API range it supports (``PDPS_API``), one module holding the
style (a docstring with the physics, the syntax and an example; ``Args`` declared with ``param``
and the kind of quantity of each parameter) and tests that pass as written:

- fix: adds a velocity increment to a group each step (the example of docs/plugin-guide.md);
- compute: the kinetic energy of each particle, and its sum over ranks;
- region: a sphere (``inside``, ``bounds``);
- dump: positions in the xyz format;
- pair: a soft harmonic repulsion as a force law in the core's pair loop (per-type tables,
  energy, mixing), tested against finite differences of its energy.

NAME names the distribution (``pdps-KIND-NAME``) and the package (``pdps_KIND_NAME``); STYLE (default
NAME) is the name scripts use and may contain ``/`` (``lj/cut``: module ``lj_cut.py``).
"""

import re
from pathlib import Path
from string import Template

from .errors import ScriptError
from .styles import API_VERSION

KINDS = ("pair", "fix", "compute", "region", "dump")
API_RANGE = f">={API_VERSION},<{int(API_VERSION.split('.')[0]) + 1}"

PYPROJECT = '''[build-system]
requires = ["setuptools>=61"]
build-backend = "setuptools.build_meta"

[project]
name = "$dist"
version = "0.1.0"
description = "pdps $kind style $style"
requires-python = ">=3.11"
dependencies = ["pdps-core"]

[project.entry-points."pdps.$kind"]
"$style" = "$package.$module:$cls"

[tool.setuptools.packages.find]
include = ["$package*"]
'''

INIT = '''"""pdps plugin $dist: $kind style ``$style`` (see $module.py for the physics and the syntax)."""

PDPS_API = "$api_range"      # the versions of pdps_core.api this plugin is written for (PEP 440)
'''

# ---- fix ----------------------------------------------------------------------------------------
FIX = r'''r"""Fix ``$style``: adds a constant velocity increment to every particle of a group each step.

.. math::

    \mathbf{v}_i \leftarrow \mathbf{v}_i + \Delta\mathbf{v} \quad \text{at the end of each step}

Parameters: ``DVX DVY DVZ``, the increment (velocity units).

Syntax::

    fix ID GROUP $style DVX DVY DVZ

Example::

    fix kick all $style 0.0 0.0 0.1
"""

from numba import njit

from pdps_core.api import Fix, StyleArgs, param


@njit(cache=True)
def add_velocity(v, mask, groupbit, nlocal, dvx, dvy, dvz):
    for i in range(nlocal):
        if mask[i] & groupbit:
            v[i, 0] += dvx
            v[i, 1] += dvy
            v[i, 2] += dvz


class $cls(Fix):
    name = "$style"
    usage = "fix ID GROUP $style DVX DVY DVZ"

    class Args(StyleArgs):
        dvx: float = param(unit="velocity")
        dvy: float = param(unit="velocity")
        dvz: float = param(unit="velocity")

    def end_of_step(self, sim):
        p = sim.particles
        add_velocity(p.v, p.mask, sim.groups.bit(self.group), p.nlocal,
                     self.args.dvx, self.args.dvy, self.args.dvz)
'''

FIX_TEST = r'''"""Fix $style: the velocity grows by the increment each step, only in the fix's group."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, registry
from $package.$module import $cls

SCRIPT = """
region box block 0 4 0 4 0 4
create_box 2 box
mass * 1
create_particle 1 single 1 1 1
create_particle 2 single 3 3 3
group moving type 1
velocity all set 0 0 0
fix kick moving $style 0.0 0.0 0.1
"""


@pytest.fixture
def sim():
    registry.register("fix", "$style", $cls)     # works before the plugin is installed too
    return Simulation(screen=False, log=None)


def test_increment_accumulates_in_the_group_only(sim):
    sim.command(SCRIPT + "run 5")
    np.testing.assert_allclose(sim.v[0], [0.0, 0.0, 0.5])
    np.testing.assert_allclose(sim.v[1], [0.0, 0.0, 0.0])


def test_bad_increment_is_a_one_line_error(sim):
    with pytest.raises(ScriptError, match=r"dvz must be a finite number \(got fast\)"):
        sim.command(SCRIPT.replace("0.0 0.0 0.1", "0.0 0.0 fast"))
'''

# ---- compute ------------------------------------------------------------------------------------
COMPUTE = r'''r"""Compute ``$style``: the kinetic energy of each particle of a group, and their sum.

.. math::

    e_i = \tfrac12 m_i \lvert \mathbf{v}_i - \mathbf{u} \rvert^2, \qquad E = \sum_{i \in G} e_i

in energy units (``mvv2e`` of the unit system turns mass * velocity^2 into energy; 1 in lj units),
with :math:`\mathbf{u}` the velocity of the frame the energy is measured in (default 0). Particles
outside the group count 0. ``peratom`` gives the values of this rank's particles (``dump custom ...
c_ID``, ``compute reduce``); ``scalar`` sums them over all ranks (thermo ``c_ID``).

Parameters: ``frame UX UY UZ`` (optional keyword): the frame's velocity (velocity units).

Syntax::

    compute ID GROUP $style [frame UX UY UZ]

Example::

    compute ke all $style
    compute drift all $style frame 0.5 0 0
    thermo_style custom step c_ke
    dump 1 all custom 100 ke.dump id c_ke
"""

import numpy as np

from pdps_core.api import Compute, StyleArgs, keyword, observables


class $cls(Compute):
    name = "$style"
    usage = "compute ID GROUP $style [frame UX UY UZ]"

    class Args(StyleArgs):
        frame: tuple[float, float, float] = keyword((0.0, 0.0, 0.0), unit="velocity")

    def peratom(self, sim):
        p = sim.particles
        relative = p.v[: p.nlocal] - np.asarray(self.args.frame)
        energy = 0.5 * observables.masses(sim) * np.einsum("ij,ij->i", relative, relative) * sim.units.mvv2e
        return np.where(sim.groups.select(sim, self.group), energy, 0.0)

    def scalar(self, sim):
        return sim.comm.sum(float(self.peratom(sim).sum()))
'''

COMPUTE_TEST = r'''"""Compute $style: 1/2 m v^2 per particle (per-type and per-particle masses), 0 outside the
group, and the sum over the group."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, registry
from pdps_core.testing import build, by_tag
from $package.$module import $cls

X = [[1.0, 1.0, 1.0], [2.0, 3.0, 1.5], [4.0, 2.0, 6.0], [7.0, 7.0, 7.0]]
V = [[0.5, -1.0, 2.0], [0.0, 0.3, 0.0], [-1.5, 0.25, 0.75], [1.0, 1.0, 1.0]]
TYPES = [1, 2, 2, 1]
MASSES = {1: 1.0, 2: 3.5}


@pytest.fixture(autouse=True)
def style():
    registry.register("compute", "$style", $cls)     # works before the plugin is installed too


def expected(frame=(0.0, 0.0, 0.0), members=(True, True, True, True)):
    m = np.array([MASSES[t] for t in TYPES])
    relative = np.array(V) - np.array(frame)
    return np.where(members, 0.5 * m * (relative ** 2).sum(axis=1), 0.0)


def test_kinetic_energy_of_each_particle_and_the_sum(tmp_path):
    sim = build(tmp_path, X, v=V, types=TYPES, masses=MASSES, setup="compute ke all $style\nrun 0")
    compute = sim.computes["ke"]
    np.testing.assert_allclose(by_tag(sim, compute.peratom(sim)), expected(), rtol=1e-14)
    assert compute.scalar(sim) == pytest.approx(expected().sum(), rel=1e-14)


def test_group_and_frame(tmp_path):
    sim = build(tmp_path, X, v=V, types=TYPES, masses=MASSES,
                setup="group heavy type 2\ncompute ke heavy $style frame 0.5 0 -1\nrun 0")
    heavy = [t == 2 for t in TYPES]
    values = expected(frame=(0.5, 0.0, -1.0), members=heavy)
    np.testing.assert_allclose(by_tag(sim, sim.computes["ke"].peratom(sim)), values, rtol=1e-14)
    assert sim.computes["ke"].scalar(sim) == pytest.approx(values.sum(), rel=1e-14)


def test_bad_frame_is_a_one_line_error(tmp_path):
    with pytest.raises(ScriptError, match=r"keyword frame needs 3 value\(s\) \(got 2\)"):
        build(tmp_path, X, setup="compute ke all $style frame 1 2")
'''

# ---- region -------------------------------------------------------------------------------------
REGION = r'''r"""Region ``$style``: a sphere, :math:`\lvert \mathbf{x} - \mathbf{c} \rvert \le R`.

Points on the surface are inside. The box that holds it (``create_box N ID``, lattice filling) is
:math:`\mathbf{c} \pm R` on each axis.

Parameters: ``XC YC ZC`` the centre (distance units), ``RADIUS`` the radius R (distance units, > 0).

Syntax::

    region ID $style XC YC ZC RADIUS

Example::

    region ball $style 10 10 10 4.5
    create_particle 1 region ball
"""

import numpy as np

from pdps_core.api import Region, StyleArgs, param


class $cls(Region):
    name = "$style"
    usage = "region ID $style XC YC ZC RADIUS"

    class Args(StyleArgs):
        xc: float = param(unit="distance")
        yc: float = param(unit="distance")
        zc: float = param(unit="distance")
        radius: float = param(gt=0, unit="distance")

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        self.centre = np.array([args.xc, args.yc, args.zc])

    def inside(self, x):
        delta = np.asarray(x, dtype=np.float64).reshape(-1, 3) - self.centre
        return np.einsum("ij,ij->i", delta, delta) <= self.args.radius ** 2

    def bounds(self):
        return self.centre - self.args.radius, self.centre + self.args.radius
'''

REGION_TEST = r'''"""Region $style: points inside and outside, the box it makes, and a lattice filling it at the
density of the lattice (its count against the sphere's volume)."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, observables, registry
from $package.$module import $cls


@pytest.fixture
def sim():
    registry.register("region", "$style", $cls)     # works before the plugin is installed too
    return Simulation(screen=False, log=None)


def test_inside_on_chosen_points(sim):
    sim.command("region ball $style 1 2 3 2")
    ball = sim.region("ball")
    points = [[1, 2, 3], [3, 2, 3], [1, 2, 1], [1, 2 - 1.999, 3], [3.001, 2, 3],
              [1 + 1.2, 2 + 1.2, 3], [1 + 1.1, 2 + 1.1, 3 + 1.1]]
    # centre, on the surface (x, z), just inside (y), just outside (x), |d| = 1.697 and 1.905 (inside)
    # and the corner of the box the sphere fits in (outside)
    assert list(ball.inside(np.array(points, dtype=float))) == [True, True, True, True, False, True, True]
    assert not ball.inside(np.array([[3.0, 4.0, 5.0]]))[0]


def test_the_box_it_makes_and_a_lattice_filling_it(sim):
    radius = 8.0
    sim.command(f"""
        region ball $style 10 10 10 {radius}
        create_box 1 ball
        mass 1 1
        lattice spacing x 1 y 1 z 1
        create_particle 1 region ball
    """)
    np.testing.assert_allclose(sim.box.lo, [10 - radius] * 3)
    np.testing.assert_allclose(sim.box.hi, [10 + radius] * 3)
    volume = 4.0 / 3.0 * math.pi * radius ** 3      # one lattice point per unit volume
    # the count differs from the volume by a surface term, a few points per unit area at most
    assert abs(observables.count(sim) - volume) < 0.02 * volume


def test_radius_must_be_positive(sim):
    with pytest.raises(ScriptError, match=r"radius must be > 0 \(got -1\)"):
        sim.command("region ball $style 0 0 0 -1")
'''

# ---- dump ---------------------------------------------------------------------------------------
DUMP = r'''r"""Dump ``$style``: positions in the xyz format, one frame every N steps.

Each frame is the number of particles, a comment line with the step, and one line ``type x y z``
per particle of the group, sorted by id (positions in distance units, 17 significant digits, so
they read back to the same numbers). VMD, OVITO and ASE read it. In a parallel run rank 0 writes
every rank's particles.

Parameters: ``N`` the interval (timesteps, >= 1), ``FILE`` the file name.

Syntax::

    dump ID GROUP $style N FILE

Example::

    dump movie all $style 100 movie.xyz
"""

import numpy as np

from pdps_core.api import Dump, ScriptError, StyleArgs, param


class $cls(Dump):
    name = "$style"
    usage = "dump ID GROUP $style N FILE"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.handle = None
        if sim.comm.is_root:
            try:
                self.handle = open(args.file, "w")
            except OSError as exc:
                raise ScriptError(f"cannot open dump file {args.file}: {exc.strerror}") from None

    def write(self, sim):
        p = sim.particles
        chosen = np.flatnonzero(sim.groups.select(sim, self.group))
        rows = np.column_stack([p.tag[chosen], p.type[chosen], p.x[chosen]]).astype(np.float64)
        table = sim.comm.gather_rows(rows.reshape(len(chosen), 5))
        if not sim.comm.is_root:
            return
        table = table[np.argsort(table[:, 0], kind="stable")]
        lines = [f"{len(table)}\n", f"Timestep: {sim.step}\n"]
        lines += [f"{int(t)} {x:.17g} {y:.17g} {z:.17g}\n" for _, t, x, y, z in table.tolist()]
        self.handle.write("".join(lines))
        self.handle.flush()

    def close(self):
        if self.handle is not None and not self.handle.closed:
            self.handle.close()
'''

DUMP_TEST = r'''"""Dump $style: frames every N steps that read back to the particles' types and positions."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, registry
from pdps_core.testing import build, by_tag
from $package.$module import $cls

X = [[1.0, 1.0, 1.0], [2.5, 3.0, 1.5], [4.0, 2.0, 6.0]]
V = [[0.1, 0.0, 0.0], [0.0, -0.2, 0.0], [0.0, 0.0, 0.3]]


@pytest.fixture(autouse=True)
def style():
    registry.register("dump", "$style", $cls)     # works before the plugin is installed too


def read_frames(path):
    lines = path.read_text().splitlines()
    frames = []
    while lines:
        n = int(lines[0])
        step = int(lines[1].split(":")[1])
        rows = np.array([[float(w) for w in line.split()] for line in lines[2:2 + n]])
        frames.append((step, rows))
        lines = lines[2 + n:]
    return frames


def test_frames_read_back(tmp_path):
    sim = build(tmp_path, X, v=V, types=[2, 1, 2], masses={1: 1.0, 2: 1.0},
                setup=f"fix 1 all nve\ndump d all $style 2 {tmp_path / 'out.xyz'}\nrun 5")
    frames = read_frames(tmp_path / "out.xyz")
    assert [step for step, _ in frames] == [0, 2, 4]
    step, rows = frames[-1]
    assert rows[:, 0].tolist() == [2, 1, 2]
    # no forces: x + 4 dt v after 4 steps of dt 0.005 (lj units)
    np.testing.assert_allclose(rows[:, 1:], np.array(X) + 4 * 0.005 * np.array(V), rtol=0, atol=1e-15)
    sim.command("run 1")
    step, rows = read_frames(tmp_path / "out.xyz")[-1]
    assert step == 6
    np.testing.assert_array_equal(rows[:, 1:], by_tag(sim, sim.x))     # 17 digits read back exactly


def test_interval_must_be_positive(tmp_path):
    with pytest.raises(ScriptError, match=r"N must be >= 1 \(got 0\)"):
        build(tmp_path, X, setup=f"dump d all $style 0 {tmp_path / 'out.xyz'}")
'''

# ---- pair ---------------------------------------------------------------------------------------
PAIR = r'''r"""Pair style ``$style``: a soft harmonic repulsion between particles closer than a cutoff.

.. math::

    E(r) = \frac{\epsilon}{2}\left(1 - \frac{r}{r_c}\right)^2, \qquad
    \mathbf{F}_i = -\frac{dE}{dr}\,\hat{\mathbf{r}}_{ij}
                 = \frac{\epsilon}{r_c}\left(1 - \frac{r}{r_c}\right)\hat{\mathbf{r}}_{ij}
    \qquad (r < r_c)

and nothing beyond :math:`r_c`; :math:`\mathbf{r}_{ij} = \mathbf{r}_i - \mathbf{r}_j`. The force
stays finite as r -> 0 (overlapping particles push apart gently), as the conservative force of
DPD, which is this law with :math:`a = \epsilon / r_c`.

Parameters:

- ``pair_style $style RC``: ``RC`` the cutoff of pairs that give none (distance units, > 0).
- ``pair_coeff I J EPSILON [RC]``: ``EPSILON`` the strength (energy units, >= 0), ``RC`` the cutoff
  of this type pair (distance units, > 0; default the pair_style one).

Type pairs not given are mixed from the I I and J J coefficients: :math:`\epsilon_{ij} =
\sqrt{\epsilon_i \epsilon_j}` and :math:`r_{c,ij} = \sqrt{r_{c,i} r_{c,j}}` (geometric, the default)
or :math:`(r_{c,i} + r_{c,j})/2` (``pair_modify mix arithmetic``).

Syntax::

    pair_style $style RC
    pair_coeff I J EPSILON [RC]

Example::

    pair_style $style 1.0
    pair_coeff * * 25.0
    pair_coeff 1 2 40.0 0.8
"""

import math

from numba import njit

from pdps_core.api import PairLaw, StyleArgs, param


@njit(cache=True)
def harmonic_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """The force law (docstring); coeff = (epsilon, rc). Returns F/r and the pair's energy."""
    epsilon, rc = coeff[0], coeff[1]
    r = math.sqrt(rsq)
    w = 1.0 - r / rc
    return epsilon * w / (rc * r), 0.5 * epsilon * w * w


class $cls(PairLaw):
    name = "$style"
    usage = "pair_style $style RC"
    coeff_usage = "EPSILON [RC]"
    params = ("epsilon", "rc")
    law = staticmethod(harmonic_law)
    mix_default = "geometric"

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")

    class Coeff(StyleArgs):
        epsilon: float = param(ge=0, unit="energy")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def rc(self, c):
        return c.cutoff if c.cutoff is not None else self.args.cutoff

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        return self.rc(c), (c.epsilon, self.rc(c))

    def mix_coeff(self, ci, cj, rule):
        rc_i, rc_j = self.rc(ci), self.rc(cj)
        rc = math.sqrt(rc_i * rc_j) if rule == "geometric" else 0.5 * (rc_i + rc_j)
        return self.Coeff(epsilon=math.sqrt(ci.epsilon * cj.epsilon), cutoff=rc)
'''

PAIR_TEST = r'''"""Pair $style: energy and force against the formula, force against a central difference of
the energy, mixing, Newton's third law and momentum conservation."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, registry
from pdps_core.testing import build, energy_gradient, fluid, total_energy, total_force, total_momentum
from $package.$module import $cls

TWO = "pair_style $style 1.5\npair_coeff * * 2.0"


@pytest.fixture(autouse=True)
def style():
    registry.register("pair", "$style", $cls)     # works before the plugin is installed too


@pytest.mark.parametrize("r", [0.1, 0.7, 1.2, 1.49])
def test_energy_and_force_of_one_pair(tmp_path, r):
    d = np.array([0.6, -0.48, 0.64])         # a unit vector
    sim = build(tmp_path, [[5, 5, 5], 5 + r * d], setup=TWO + "\nrun 0")
    w = 1.0 - r / 1.5
    assert total_energy(sim) == pytest.approx(0.5 * 2.0 * w * w, rel=1e-12)
    force = 2.0 / 1.5 * w                    # -dE/dr, along r_i - r_j: pushes the two apart
    np.testing.assert_allclose(sim.f[np.argsort(sim.tag)], [-force * d, force * d], rtol=1e-12, atol=1e-15)


def test_force_is_minus_the_gradient_of_the_energy(tmp_path):
    sim = build(tmp_path, [[5, 5, 5], [5.8, 5.5, 4.9]], setup=TWO)
    analytic, numeric = energy_gradient(sim, h=1e-6)
    np.testing.assert_allclose(numeric, analytic, rtol=1e-6, atol=1e-9)


def test_nothing_beyond_the_cutoff(tmp_path):
    sim = build(tmp_path, [[5, 5, 5], [6.51, 5, 5]], setup=TWO + "\nrun 0")
    assert total_energy(sim) == 0.0
    assert not sim.f.any()


@pytest.mark.parametrize("rule, rc", [("geometric", math.sqrt(1.0 * 1.6)), ("arithmetic", 1.3)])
def test_unset_pairs_are_mixed(tmp_path, rule, rc):
    setup = f"pair_style $style 1.0\npair_coeff 1 1 4.0\npair_coeff 2 2 9.0 1.6\npair_modify mix {rule}\nrun 0"
    sim = build(tmp_path, [[5, 5, 5], [5.9, 5, 5]], types=[1, 2], setup=setup)
    epsilon = math.sqrt(4.0 * 9.0)
    assert total_energy(sim) == pytest.approx(0.5 * epsilon * (1 - 0.9 / rc) ** 2, rel=1e-12)


def test_newton_third_law_and_momentum_in_a_fluid(tmp_path):
    x, length = fluid(200, 3.0, seed=7)
    v = np.random.default_rng(8).normal(size=(200, 3))
    sim = build(tmp_path, x, v=v, types=[1 + k % 2 for k in range(200)], masses={1: 1.0, 2: 2.0},
                hi=(length, length, length),
                setup="pair_style $style 1.0\npair_coeff 1 1 25\npair_coeff 2 2 30 0.9\n"
                      "timestep 0.01\nfix 1 all nve\nrun 0")
    assert np.abs(total_force(sim)).max() < 1e-10
    before = total_momentum(sim)
    sim.command("run 100")
    np.testing.assert_allclose(total_momentum(sim), before, rtol=0, atol=1e-10)


def test_negative_strength_is_a_one_line_error(tmp_path):
    with pytest.raises(ScriptError, match=r"epsilon must be >= 0 \(got -1\)"):
        build(tmp_path, [[5, 5, 5]], setup="pair_style $style 1.0\npair_coeff * * -1")
'''

TEMPLATES = {"fix": (FIX, FIX_TEST, "Fix"), "compute": (COMPUTE, COMPUTE_TEST, "Compute"),
             "region": (REGION, REGION_TEST, "Region"), "dump": (DUMP, DUMP_TEST, "Dump"),
             "pair": (PAIR, PAIR_TEST, "Pair")}

EXAMPLES = {"fix": "fix ID GROUP {style} DVX DVY DVZ", "compute": "compute ID GROUP {style}",
            "region": "region ID {style} XC YC ZC RADIUS", "dump": "dump ID GROUP {style} N FILE",
            "pair": "pair_style {style} RC"}

NAME = re.compile(r"[a-z][a-z0-9_]*(/[a-z0-9_]+)*")
# a style name as scripts spell it: LIGGGHTS's have capitals (dump mesh/gran/VTK)
STYLE = re.compile(r"[A-Za-z][A-Za-z0-9_]*(/[A-Za-z0-9_]+)*")


def new_plugin(name, directory="plugins", kind="fix", style=None):
    """Write the plugin; returns (its folder, the script line that uses its style)."""
    if kind not in TEMPLATES:
        raise ScriptError(f"kind must be one of {', '.join(KINDS)} (got {kind})")
    if not NAME.fullmatch(name):
        raise ScriptError(f"plugin name must be lower-case letters, digits, _ and / (got {name})")
    style = style or name
    if not STYLE.fullmatch(style):
        raise ScriptError(f"style name must be letters, digits, _ and / (got {style})")
    ident = name.replace("/", "_")
    root = Path(directory) / f"{kind}_{ident}"
    if root.exists():
        raise ScriptError(f"{root} already exists")
    module_text, test_text, prefix = TEMPLATES[kind]
    module = style.replace("/", "_").lower()
    values = dict(kind=kind, style=style, module=module, package=f"pdps_{kind}_{ident}",
                  dist=f"pdps-{kind}-{ident.replace('_', '-')}", api_range=API_RANGE,
                  cls=prefix + "".join(part.capitalize() for part in module.split("_")))
    package = root / values["package"]
    package.mkdir(parents=True)
    (root / "tests").mkdir()
    (root / "pyproject.toml").write_text(Template(PYPROJECT).substitute(values))
    (package / "__init__.py").write_text(Template(INIT).substitute(values))
    (package / f"{module}.py").write_text(Template(module_text).substitute(values))
    (root / "tests" / f"test_{module}.py").write_text(Template(test_text).substitute(values))
    return root, EXAMPLES[kind].format(style=style)
