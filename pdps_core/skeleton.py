"""``pdps new-plugin NAME``: write a working, tested plugin skeleton (a fix) to start a style from.

The skeleton is the example of docs/plugin-guide.md: a fix that adds a velocity increment each step,
with its numba kernel, pydantic arguments, entry point and a physics test.
"""

import re
from pathlib import Path

from .errors import ScriptError

PYPROJECT = '''[build-system]
requires = ["setuptools>=68"]
build-backend = "setuptools.build_meta"

[project]
name = "pdps-fix-{dash}"
version = "0.1.0"
description = "pdps fix {name}"
requires-python = ">=3.11"
dependencies = ["pdps-core"]

[project.entry-points."pdps.fix"]
{name} = "{package}.{module}:{cls}"

[tool.setuptools.packages.find]
include = ["{package}*"]
'''

MODULE = '''r"""Fix ``{name}``: adds a constant velocity increment to every particle of a group each step.

.. math::

    \\mathbf{{v}}_i \\leftarrow \\mathbf{{v}}_i + \\Delta\\mathbf{{v}} \\quad \\text{{at the end of each step}}

Parameters: ``DVX DVY DVZ``, the increment (velocity units).

Syntax::

    fix ID GROUP {name} DVX DVY DVZ

Example::

    fix kick all {name} 0.0 0.0 0.1
"""

from numba import njit

from pdps_core.api import Fix, StyleArgs


@njit(cache=True)
def add_velocity(v, mask, groupbit, nlocal, dvx, dvy, dvz):
    for i in range(nlocal):
        if mask[i] & groupbit:
            v[i, 0] += dvx
            v[i, 1] += dvy
            v[i, 2] += dvz


class {cls}(Fix):
    name = "{name}"
    usage = "fix ID GROUP {name} DVX DVY DVZ"

    class Args(StyleArgs):
        dvx: float
        dvy: float
        dvz: float

    def end_of_step(self, sim):
        p = sim.particles
        add_velocity(p.v, p.mask, sim.groups.bit(self.group), p.nlocal,
                     self.args.dvx, self.args.dvy, self.args.dvz)
'''

TEST = '''"""Fix {name}: the velocity grows by the increment each step, only in the fix's group."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, registry
from {package}.{module} import {cls}

SCRIPT = """
region box block 0 4 0 4 0 4
create_box 2 box
mass * 1
create_particle 1 single 1 1 1
create_particle 2 single 3 3 3
group moving type 1
velocity all set 0 0 0
fix kick moving {name} 0.0 0.0 0.1
"""


@pytest.fixture
def sim():
    registry.register("fix", "{name}", {cls})     # works before the plugin is installed too
    return Simulation(screen=False, log=None)


def test_increment_accumulates_in_the_group_only(sim):
    sim.command(SCRIPT + "run 5")
    np.testing.assert_allclose(sim.v[0], [0.0, 0.0, 0.5])
    np.testing.assert_allclose(sim.v[1], [0.0, 0.0, 0.0])


def test_bad_increment_is_a_one_line_error(sim):
    with pytest.raises(ScriptError, match=r"dvz must be a finite number \\(got fast\\)"):
        sim.command(SCRIPT.replace("0.0 0.0 0.1", "0.0 0.0 fast"))
'''


def new_plugin(name, directory="plugins"):
    if not re.fullmatch(r"[a-z][a-z0-9_]*", name):
        raise ScriptError(f"plugin name must be lower-case letters, digits and _ (got {name})")
    root = Path(directory) / f"fix_{name}"
    if root.exists():
        raise ScriptError(f"{root} already exists")
    package, module = f"pdps_fix_{name}", name
    cls = "Fix" + "".join(part.capitalize() for part in name.split("_"))
    values = dict(name=name, dash=name.replace("_", "-"), package=package, module=module, cls=cls)
    (root / package).mkdir(parents=True)
    (root / "tests").mkdir()
    (root / "pyproject.toml").write_text(PYPROJECT.format(**values))
    (root / package / "__init__.py").write_text(f'"""pdps plugin: fix {name}."""\n')
    (root / package / f"{module}.py").write_text(MODULE.format(**values))
    (root / "tests" / f"test_{module}.py").write_text(TEST.format(**values))
    return root
