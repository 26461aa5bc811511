"""What one style offers another is declared once, in the api (pdps_core/capabilities.py), and
the styles that offer it are the ones expected; no plugin tests another plugin's style by its name.
"""

import re
from pathlib import Path

import pytest

from pdps_core.api import (ContactConduction, ContactTable, ContactTimes, HeatTransport, MeshSurface, MoleculeBodies,
                           SurfaceValues, registry)
from pdps_core.styles import IN_PROCESS

ROOT = Path(__file__).parents[1]

METHOD_CAPABILITIES = {
    ContactTable: {("pair", "gran"), ("pair", "bubble"), ("pair", "gran_bubble"), ("pair", "granular"),
                   ("pair", "dem/lsd"), ("pair", "dem/hertz")},
    # pair granular answers that its contacts carry no heat (its heat models are not built)
    ContactConduction: {("pair", "gran"), ("pair", "bubble"), ("pair", "gran_bubble"), ("pair", "granular")},
    ContactTimes: {("pair", "gran"), ("pair", "bubble"), ("pair", "gran_bubble"), ("pair", "granular"),
                   ("pair", "gran/hooke"), ("pair", "gran/hooke/history"),
                   ("pair", "gran/hertz/history"), ("pair", "dem/lsd"), ("pair", "dem/hertz")},
    HeatTransport: {("fix", "heat/gran"), ("fix", "heat/gran/conduction")},
    MeshSurface: {("fix", "mesh/surface"), ("fix", "mesh/surface/stress"), ("fix", "mesh/surface/planar")},
    SurfaceValues: {("fix", "mesh/surface/stress")},
    # the thermostatted and barostatted variants inherit the method and refuse the mol keyword
    MoleculeBodies: {("fix", name) for name in ("rigid/small", "rigid/nve/small", "rigid/nvt/small", "rigid/nph/small",
                                                 "rigid/npt/small")},
}


@pytest.mark.parametrize("capability", METHOD_CAPABILITIES, ids=lambda c: c.__name__)
def test_the_styles_offering_a_capability_are_those_expected(capability):
    offering = set()
    # the installed styles: test modules register styles of their own in this process
    for entry in registry.entries():
        if entry.kind in ("pair", "fix", "compute") and entry.dist != IN_PROCESS and not entry.disabled:
            kind, name, cls = entry.kind, entry.name, registry.load(entry)
            # a protocol with data members is checked on instances; its methods tell here
            methods = [m for m in capability.__dict__ if not m.startswith("_") and callable(capability.__dict__[m])]
            if all(callable(getattr(cls, m, None)) for m in methods):
                offering.add((kind, name))
    assert offering == METHOD_CAPABILITIES[capability]


def test_a_fix_holding_particles_and_computes_a_thermostat_reads_say_so():
    installed = [e for e in registry.entries() if e.dist != IN_PROCESS and not e.disabled]
    flagged = {flag: [e.name for e in installed if getattr(registry.load(e), flag, False)]
               for flag in ("holds_at_rest", "gives_temperature", "gives_pressure")}
    assert flagged["holds_at_rest"] == ["freeze"]
    temperature, pressure = flagged["gives_temperature"], flagged["gives_pressure"]
    assert (temperature, pressure) == (["temp", "temp/partial", "temp/ramp", "temp/region", "temp/sphere"], ["pressure"])


# another distribution's style tested by its name: what the capabilities replace
NAMED = re.compile(r"\b(?!self\b)\w+\.name\s*(==|!=|in)\s*[\"'(]")


def test_no_plugin_tests_another_distributions_style_by_its_name():
    offenders = []
    for path in sorted(ROOT.glob("plugins/*/pdps_*/**/*.py")):
        if "build" in path.parts:
            continue
        # the distribution's own pyproject, above the package and any sub-package
        own = next(parent / "pyproject.toml" for parent in path.parents if (parent / "pyproject.toml").exists()).read_text()
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = NAMED.search(line)
            if match is None or ".dialect.name" in line or ".units.name" in line or ".variable.name" in line:
                continue
            names = re.findall(r"[\"']([a-z][a-z0-9/]+)[\"']", line[match.end() - 1:])
            if any(f'"{name}" =' not in own for name in names):
                offenders.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()}")
    assert not offenders, "\n".join(offenders)


@pytest.mark.parametrize("name, integrates", [
    ("nve", True), ("nve/sphere", True), ("nve/limit", True), ("nvt", True), ("npt", True), ("nph", True),
    ("rigid", True), ("rigid/small", True), ("rigid/nvt", True), ("rigid/nph/small", True), ("mvv/dpd", True),
    ("langevin", False), ("shardlow", False), ("move/mesh", False), ("freeze", False), ("addforce", False),
])
def test_the_integrators_say_so(name, integrates):
    """LAMMPS's time_integrate: what a fix wrapping an integrator's steps (langevin gjf) looks for."""
    assert registry.lookup("fix", name).time_integrate is integrates
