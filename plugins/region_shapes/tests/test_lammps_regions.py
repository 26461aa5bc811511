"""LAMMPS's region styles in pdps select the lattice sites LAMMPS selects (counts recorded with LAMMPS by
benchmarks/lammps_references/regions.py into data/lammps_regions.txt): sphere, cylinder, cone, plane,
prism, union, intersect, with side out, units box and lattice, INF and EDGE."""

from pathlib import Path

import pytest

from pdps_core.api import ScriptError, Simulation

ROWS = [line.split("\t") for line in (Path(__file__).parent / "data" / "lammps_regions.txt").read_text().splitlines()]


@pytest.fixture(scope="module")
def sim():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style atomic\nlattice sc 1.0\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                "create_atoms 1 box\nmass 1 1")
    for region, _ in ROWS:
        name = region.split()[1]
        sim.command(f"{region}\ngroup g{name} region {name}")
    return sim


@pytest.mark.parametrize("region, count", ROWS, ids=[row[0].split()[1] for row in ROWS])
def test_regions_select_the_sites_lammps_selects(sim, region, count):
    assert sim.variables.evaluate(f"count(g{region.split()[1]})") == int(count)


@pytest.mark.parametrize("line, message", [
    ("region r sphere 0 0 0 -1", "radius must be >= 0 (got -1)"),
    ("region r cylinder w 0 0 1 0 1", "dim must be x, y or z (got w)"),
    ("region r cone z 0 0 1 1 INF 3", "lo of a cone must be a number or EDGE (got INF)"),
    ("region r plane 0 0 0 0 0 0", "the plane's normal must not be zero"),
    ("region r union 3 box", "N is 3 but 1 region IDs follow"),
    ("region r union 2 box nowhere", "region nowhere is not defined"),
    ("region r prism 0 1 0 1 0 1 0 0 0 side up", "side must be one of"),
])
def test_bad_regions(line, message):
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 10 0 10 0 10\ncreate_box 1 box")
    with pytest.raises(ScriptError, match=message.replace("(", r"\(").replace(")", r"\)")):
        sim.command(line)
