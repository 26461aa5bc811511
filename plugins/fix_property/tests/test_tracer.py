"""fix property/atom/tracer and compute nparticles/tracer/region (LIGGGHTS's numbers:
plugins/fix_property/tests/data/liggghts.cases.json, case tracer): what they need, one line each."""

import pytest

from pdps_core.api import ScriptError, Simulation

SETUP = """
atom_style granular
units si
region box block 0 1 0 1 0 1 units box
create_box 1 box
region inlet block 0 0.5 0 1 0 1 units box
"""


@pytest.mark.parametrize("line, message", [
    ("fix t all property/atom/tracer mark_step 10", "fix property/atom/tracer needs region_mark RID"),
    ("fix t all property/atom/tracer region_mark inlet", "fix property/atom/tracer needs mark_step N"),
    ("fix t all property/atom/tracer region_mark nowhere mark_step 0", "region nowhere"),
    ("fix t all property/atom/tracer region_mark inlet mark_step 0 marker_style box",
     "marker_style must be one of 'dirac', 'heaviside' or 'none' (got box)"),
    ("compute n all nparticles/tracer/region region_count inlet tracer m1",
     "compute n (nparticles/tracer/region): fix m1 is not a fix property/atom/tracer"),
    ("compute n all nparticles/tracer/region tracer t", "needs region_count RID and tracer FIX_ID"),
])
def test_what_they_need_is_one_line(line, message):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SETUP + "fix m1 all property/global youngsModulus peratomtype 5.e6\n"
                        "fix t0 all property/atom/tracer region_mark inlet mark_step 0\n")
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert message in error.value.message
