"""compute slice (LIGGGHTS's numbers for one vector: plugins/compute_basic/tests/data/liggghts.cases.json,
case slice): several inputs give one column each (LIGGGHTS 3.8.0's array output reads wrong
elements, so this is checked against the inputs themselves); bad words are one line."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import make_box

SETUP = """
    mass 1 1.0
    create_particle 1 single 1 2 3
    create_particle 1 single 4 5 6
    create_particle 1 single 7 8 9.5
    compute s all reduce sum x y z vx vy vz
    compute m all reduce max x y z
"""


def test_several_inputs_give_a_column_each():
    sim = make_box(SETUP + "compute two all slice 1 3 1 c_s c_m\ncompute one all slice 2 6 3 c_s")
    np.testing.assert_array_equal(sim.computes["two"].array(sim), [[12.0, 7.0], [15.0, 8.0]])
    np.testing.assert_array_equal(sim.computes["one"].vector(sim), [15.0])


@pytest.mark.parametrize("line, message", [
    ("compute b all slice 3 2 1 c_s", "nstop 2 is before nstart 3"),
    ("compute b all slice 1 2 3 c_s", "compute b slice: 1 2 3 picks no element"),
    ("compute b all slice 1 3 1 x", "compute b slice: x is not c_ID, c_ID[N], f_ID or f_ID[N]"),
    ("compute b all slice 1 3 1 c_nothing", "compute b slice: compute nothing is not defined (c_nothing)"),
])
def test_bad_words_are_one_line(line, message):
    sim = make_box(SETUP)
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert message in error.value.message


def test_an_input_shorter_than_nstop_is_refused_when_read():
    sim = make_box(SETUP + "compute b all slice 1 7 1 c_m")
    with pytest.raises(ScriptError, match="compute b slice: c_m has 3 elements, fewer than nstop 7"):
        sim.computes["b"].vector(sim)
