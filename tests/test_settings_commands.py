"""dielectric, box and partition: what they set, which commands partition runs with pdps's one
partition, and their errors, one line each (LIGGGHTS 3.8.0's thermo with them: the recorded case
settings, tests/data/liggghts.cases.json)."""

import pytest

from pdps_core.api import ScriptError, Simulation

BOX = "region box block 0 1 0 1 0 1 units box\ncreate_box 1 box\n"


def sim_of(dialect="liggghts"):
    return Simulation(screen=False, log=None, dialect=dialect)


def test_dielectric_is_kept():
    sim = sim_of("lammps")
    sim.command("dielectric 2.5")
    assert sim.system.dielectric == 2.5


@pytest.mark.parametrize("spec, runs", [("1", True), ("*", True), ("*3", True), ("1*2", True), ("2", False),
                                        ("2*", False), ("2*4", False)])
def test_partition_runs_its_command_in_partition_1_only_where_named(spec, runs):
    sim = sim_of()
    sim.command(f'variable hit equal 0\npartition yes {spec} variable hit equal 1\n'
                f'variable miss equal 0\npartition no {spec} variable miss equal 1')
    assert sim.variables.value("hit") == (1.0 if runs else 0.0)
    assert sim.variables.value("miss") == (0.0 if runs else 1.0)


@pytest.mark.parametrize("lines, message", [
    ("partition maybe 1 print hi", "partition: partition style must be one of yes, no (got maybe)"),
    ("partition yes 0 print hi", "partition: partition N must name partitions from 1 (got 0)"),
    ("partition yes x print hi", "partition: partition N must be a number or an asterisk range such as *, *2, 2*, "
                                 "1*3 (got x)"),
    ("partition yes 1", "partition: usage: partition yes|no N COMMAND ..."),
    ("box tilt huge", "box: box tilt must be one of small, large (got huge)"),
    ("box tilt", "box: usage: box tilt small|large (got tilt)"),
    (BOX + "box tilt large", "box: box must come before the simulation box is created (as LIGGGHTS)"),
    ("dielectric soft", "dielectric: dielectric must be a number (got soft)"),
])
def test_bad_lines(lines, message):
    sim = sim_of()
    with pytest.raises(ScriptError) as error:
        sim.command(lines)
    assert str(error.value).split(": ", 1)[1] == message


def test_box_is_liggghts_s_only():
    with pytest.raises(ScriptError) as error:
        sim_of("lammps").command("box tilt large")
    assert str(error.value) == ("<command>:1: box: box is a LAMMPS command pdps does not support; instead: nothing: "
                                "the command is obsolete in LAMMPS too (docs/lammps.md)")
