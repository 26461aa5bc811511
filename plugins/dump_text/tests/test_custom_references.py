"""Dump custom columns that read other styles: ``c_ID``/``c_ID[k]`` of per-atom computes,
``f_ID``/``f_ID[k]`` of fixes with per-atom values, ``v_NAME`` of a variable; k counts from 0.

The styles here are defined in the test, with values known from the particle state: a compute
whose per-atom values are (tag^2, 10 tag + type) and one with 1/2 m v^2 for particles in its group;
a fix whose per-atom value is the number of steps it has seen times the tag.
"""

import numpy as np
import pytest

from pdps_core.api import Compute, Fix, ScriptError
from pdps_core.testing import make_box, register_styles


class TagColumns(Compute):
    name = "test/tag_columns"

    def peratom(self, sim):
        tag, type_ = sim.tag.astype(float), sim.type.astype(float)
        return np.column_stack([tag ** 2, 10 * tag + type_])


class HalfMV2(Compute):
    name = "test/half_mv2"

    def peratom(self, sim):
        chosen = sim.groups.select(sim, self.group)
        return np.where(chosen, 0.5 * sim.mass[sim.type] * (sim.v ** 2).sum(axis=1), 0.0)


class StepCounter(Fix):
    name = "test/step_counter"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.steps = 0

    def end_of_step(self, sim):
        self.steps += 1

    def peratom(self, sim):
        return self.steps * sim.tag.astype(float)


register_styles(TagColumns, HalfMV2, StepCounter)


def read_frames(path):
    """(step, columns, rows as floats) of every frame of a LAMMPS text dump."""
    lines, frames, i = path.read_text().splitlines(), [], 0
    while i < len(lines):
        step, n = int(lines[i + 1]), int(lines[i + 3])
        columns = lines[i + 8].split()[2:]
        table = np.array([[float(w) for w in line.split()] for line in lines[i + 9:i + 9 + n]])
        frames.append((step, columns, table.reshape(n, len(columns))))
        i += 9 + n
    return frames


def make(tmp_path, columns, extra=""):
    sim = make_box(f"""
        mass 1 1.0
        mass 2 2.5
        lattice spacing x 2 y 2 z 2
        create_particle 1 box
        group heavy type 2
        compute tc all test/tag_columns
        compute ke heavy test/half_mv2
        fix count all test/step_counter
        variable twice equal step*2
        {extra}
    """, box="0 6 0 6 0 6", ntypes=2)
    sim.type[::4] = 2
    sim.v[:] = np.random.default_rng(2).normal(size=sim.v.shape)
    sim.command(f"dump d all custom 5 {tmp_path / 'd.txt'} {columns}\nfix 1 all nve\ntimestep 0.001\nrun 10")
    return sim


def test_compute_fix_and_variable_columns_hold_the_values_of_each_particle(tmp_path):
    sim = make(tmp_path, "id type c_tc[0] c_tc[1] c_ke f_count v_twice")
    frames = read_frames(tmp_path / "d.txt")
    assert [f[0] for f in frames] == [0, 5, 10]
    step, columns, table = frames[-1]
    assert columns == ["id", "type", "c_tc[0]", "c_tc[1]", "c_ke", "f_count", "v_twice"]
    tag, type_ = table[:, 0], table[:, 1]
    np.testing.assert_array_equal(table[:, 2], tag ** 2)
    np.testing.assert_array_equal(table[:, 3], 10 * tag + type_)
    order = np.argsort(sim.tag)
    mass = np.where(sim.type == 2, 2.5, 1.0)
    expected = np.where(sim.type == 2, 0.5 * mass * (sim.v ** 2).sum(axis=1), 0.0)[order]
    np.testing.assert_allclose(table[:, 4], expected, rtol=1e-9)
    assert (table[:, 4][type_ == 1] == 0).all() and (table[:, 4][type_ == 2] > 0).all()
    np.testing.assert_array_equal(table[:, 5], 10 * tag)
    assert (table[:, 6] == 20).all()
    # the step-5 frame read the fix after 5 steps
    np.testing.assert_array_equal(frames[1][2][:, 5], 5 * frames[1][2][:, 0])


def test_a_dump_with_a_variable_asks_for_energy_on_its_steps(tmp_path):
    sim = make(tmp_path, "id v_twice")
    assert sim.output.dumps["d"].needs == {"energy", "virial"}
    sim.command(f"dump e all custom 5 {tmp_path / 'e.txt'} id c_ke")
    assert sim.output.dumps["e"].needs == set()


@pytest.mark.parametrize("columns, words", [
    ("id c_nope", ("compute nope is not defined",)),
    ("id f_nope[0]", ("fix nope is not defined",)),
    ("id v_nope", ("variable nope is not defined",)),
    ("id v_twice[0]", ("a variable has one value",)),
    ("id c_plain", ("compute plain (test/plain) has no per-atom values",)),
    ("id f_1", ("fix 1 (nve) has no per-atom values",)),
    ("id c_tc", ("2 values per particle", "[k]")),
    ("id c_ke[0]", ("one value per particle", "drop the [k]")),
    ("id c_tc[2]", ("column 2 is out of range", "from 0")),
    ("id q_x", ("unknown dump column q_x",)),
])
def test_bad_reference_columns_give_one_line_errors(tmp_path, columns, words):
    register_styles(type("Plain", (Compute,), {"name": "test/plain"}))
    sim = make_box(f"""
        mass 1 1
        create_particle 1 single 1 1 1
        compute tc all test/tag_columns
        compute ke all test/half_mv2
        compute plain all test/plain
        variable twice equal 2
        fix 1 all nve
    """, box="0 4 0 4 0 4")
    with pytest.raises(ScriptError) as error:
        sim.command(f"dump d all custom 1 {tmp_path / 'd.txt'} {columns}\nrun 0")
    assert "\n" not in str(error.value)
    for word in words:
        assert word in str(error.value)
