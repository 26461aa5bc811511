"""compute property/local: the pairs within the pair cutoff (patom/ptype) and those the neighbor
lists hold (natom/ntype), each pair once; bad input gets one line. LIGGGHTS 3.8.0's numbers for an
LJ-units fluid are in data/liggghts.cases.json (property_local, also on 2 ranks)."""

import pytest

from pdps_core.api import ScriptError, Simulation

SCENE = """units lj
atom_style atomic
boundary p p p
region box block 0 10 0 10 0 10
create_box 2 box
mass * 1.0
create_atoms 1 single 1.0 1.0 1.0
create_atoms 2 single 2.0 1.0 1.0
create_atoms 1 single 1.0 2.1 1.0
create_atoms 2 single 9.6 1.0 1.0
create_atoms 1 single 5.0 5.0 5.0
pair_style soft 1.05
pair_coeff * * 1.0
neighbor 0.3 bin
"""


def simulation(lines):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCENE + lines)
    return sim


def test_pairs_within_the_cutoff_and_within_the_lists():
    """1-2 at 1.0 and 1-4 across the periodic face at 1.4: within 1.05 only 1-2; within the lists'
    1.35 also 1-3 (1.1); 1-4 (1.4) in neither."""
    sim = simulation("compute p all property/local patom1 patom2 ptype1 ptype2\n"
                     "compute n all property/local natom1 natom2\nrun 0")
    pairs = sim.computes["p"].local(sim)
    assert [sorted(row[:2]) for row in pairs.tolist()] == [[1.0, 2.0]]
    assert sorted(pairs[0, 2:].tolist()) == [1.0, 2.0]
    listed = sorted(sorted(row) for row in sim.computes["n"].local(sim).tolist())
    assert listed == [[1.0, 2.0], [1.0, 3.0]]


def test_one_value_is_a_vector_and_groups_choose_both_particles():
    sim = simulation("group odd id 1 3\ncompute n odd property/local natom2\nrun 0")
    assert sim.computes["n"].local(sim).tolist() in ([3.0], [1.0])


@pytest.mark.parametrize("words, message", [
    ("batom1 batom2", "batom1: pdps has no bonds, angles, dihedrals or impropers; the pair values are natom1 natom2 "
                      "ntype1 ntype2 patom1 patom2 ptype1 ptype2"),
    ("natom1 patom2", "the neighbor values (natom1 ... ntype2) and the pair values (patom1 ... ptype2) cannot be "
                      "used together (LAMMPS's rule)"),
    ("patom3", "must be one of"),
])
def test_bad_values(words, message):
    sim = simulation("")
    with pytest.raises(ScriptError) as caught:
        sim.command(f"compute p all property/local {words}")
    assert message in caught.value.message


def test_read_before_a_run():
    sim = simulation("compute p all property/local patom1")
    with pytest.raises(ScriptError) as caught:
        sim.computes["p"].local(sim)
    assert caught.value.message == "compute p (property/local) is read before any run: run 0 first"
