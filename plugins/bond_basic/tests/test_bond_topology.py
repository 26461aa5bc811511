"""fix bond/break and fix bond/create: their rules on scenes small enough to work out by hand (the
longest or closest partner each particle picks, one bond a check, maxbond and the new types), prob's
fraction against the binomial law, the room they make for bonds, and their refusals. Their thermo
against LAMMPS's (chains breaking, monomers bonding, both at once; 2 ranks for some) is checked by
tests/test_recorded_thermo.py from data/bond_topology.cases.json (benchmarks/lammps_references/bond_topology.py)."""

import re
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

DATA = Path(__file__).parent / "data"

HEAD = """{title}

{n} atoms
3 atom types
{nbonds} bonds
2 bond types
{extra} extra bond per atom

0 10 xlo xhi
0 10 ylo yhi
0 10 zlo zhi

Masses

1 1.0
2 1.0
3 1.0

Atoms # bond

"""


def scene(tmp_path, atoms, bonds=(), lines="", extra=1):
    """Particles (type, x) held still under pair_style zero, with ``bonds`` (type, i, j) and ``lines``."""
    text = HEAD.format(title="by hand", n=len(atoms), nbonds=len(bonds), extra=extra)
    text += "\n".join(f"{k + 1} 1 {t} {x} 5.0 5.0" for k, (t, x) in enumerate(atoms)) + "\n"
    if bonds:
        text += "\nBonds\n\n" + "\n".join(f"{k + 1} {t} {i} {j}" for k, (t, i, j) in enumerate(bonds)) + "\n"
    (tmp_path / "scene.data").write_text(text)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"atom_style bond\nread_data {tmp_path / 'scene.data'}\npair_style zero 4.0\npair_coeff * *\n"
                f"bond_style harmonic\nbond_coeff * 10.0 1.0\n{lines}")
    return sim


def bonds_of(sim):
    p = sim.particles
    return sorted((int(p.tag[i]), int(p.bond_atom[i, b]), int(p.bond_type[i, b]))
                  for i in range(p.nlocal) for b in range(int(p.num_bond[i])))


def special_of(sim, tag):
    p = sim.particles
    row = p.index_of_tag(tag)
    return sorted(p.special[row, :p.nspecial[row, 2]].tolist())


def test_bond_break_breaks_each_particle_s_longest_bond_one_at_a_time(tmp_path):
    # 1 -1.3- 2 -1.5- 3 -0.9- 4 (type 1 bonds, Rmax 1.2): particle 2 picks 2-3, its longest, so 1-2
    # waits a check; 3-4 is not stretched
    sim = scene(tmp_path, [(1, 1.0), (1, 2.3), (1, 3.8), (1, 4.7)], [(1, 1, 2), (1, 2, 3), (1, 3, 4)],
                "fix b all bond/break 1 1 1.2")
    sim.command("run 1")
    assert bonds_of(sim) == [(1, 2, 1), (3, 4, 1)]
    assert special_of(sim, 2) == [1] and special_of(sim, 3) == [4]
    assert sim.fixes["b"].vector(sim).tolist() == [1, 1]
    sim.command("run 1")
    assert bonds_of(sim) == [(3, 4, 1)]
    assert special_of(sim, 1) == [] and special_of(sim, 2) == []
    assert sim.fixes["b"].vector(sim).tolist() == [1, 2]


def test_bond_break_takes_its_type_and_group_only(tmp_path):
    sim = scene(tmp_path, [(1, 1.0), (1, 2.5), (1, 4.0), (1, 5.5)], [(2, 1, 2), (1, 3, 4)],
                "group front id 3 4\nfix b front bond/break 1 1 1.2\nfix c all bond/break 1 1 1.2")
    sim.command("unfix c\nrun 1")
    assert bonds_of(sim) == [(1, 2, 2)]


def test_bond_create_bonds_mutual_closest_pairs_and_changes_types_at_maxbond(tmp_path):
    # type 1 at 5.0; type 2 at 5.9 and 4.2: particle 1 picks 3 (0.8 away), which picks 1; 2 is left.
    # iparam 1 3: particle 1 has its one bond and becomes type 3, so 2 never bonds to it
    sim = scene(tmp_path, [(1, 5.0), (2, 5.9), (2, 4.2)], lines="fix c all bond/create 1 1 2 1.0 1 iparam 1 3")
    sim.command("run 3")
    assert bonds_of(sim) == [(1, 3, 1)]
    assert sim.particles.type[sim.particles.index_of_tag(1)] == 3
    assert sim.fixes["c"].vector(sim).tolist() == [0, 1]
    assert special_of(sim, 1) == [3] and special_of(sim, 3) == [1]


def test_bond_create_needs_both_types_and_leaves_bonded_pairs(tmp_path):
    # 1 (type 1) and 2 (type 2), 0.5 apart, are bonded already and, with special_bonds 1 1 1, in
    # the neighbor lists: 2 takes 4 (type 1, 0.9 away) instead; 3 (type 2) is out of reach, and
    # 1 and 4 are both type 1
    sim = scene(tmp_path, [(1, 5.0), (2, 5.5), (2, 8.0), (1, 4.6)], [(1, 1, 2)],
                "special_bonds lj 1 1 1\nfix c all bond/create 1 1 2 1.0 1")
    sim.command("run 3")
    assert bonds_of(sim) == [(1, 2, 1), (2, 4, 1)]
    assert sim.fixes["c"].vector(sim).tolist() == [0, 1]


def test_bond_create_makes_room_past_extra_bond_per_atom(tmp_path):
    # a star: particle 1 (type 1) bonds one type-2 particle a check, 5 in all, in a data file with
    # room for 2 (LAMMPS stops: "New bond exceeded bonds per atom")
    atoms = [(1, 5.0)] + [(2, 5.0 + d) for d in (0.5, -0.55, 0.6, -0.65, 0.7)]
    sim = scene(tmp_path, atoms, lines="fix c all bond/create 1 1 2 1.0 1", extra=0)
    sim.command("run 6")
    assert bonds_of(sim) == [(1, k, 1) for k in range(2, 7)]
    assert sim.particles.bond_type.shape[1] >= 5
    assert special_of(sim, 2) == [1, 3, 4, 5, 6]


def _broken_at_first_check(tmp_path, prob, seed):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"atom_style bond\nread_data {DATA / 'chains.data'}\npair_style zero 2.5\npair_coeff * *\n"
                f"bond_style harmonic\nbond_coeff * 100.0 1.0\n"
                f"fix b all bond/break 1 1 0.0{'' if prob is None else f' prob {prob} {seed}'}\nrun 1")
    return int(sim.fixes["b"].vector(sim)[0])


def test_bond_break_prob_breaks_the_binomial_fraction(tmp_path):
    # every type-1 bond is stretched past 0: the first check's eligible bonds are the same whatever
    # prob says, and prob f breaks each with probability f: over 12 seeds Binomial(12 n, f)
    eligible = _broken_at_first_check(tmp_path, None, 0)
    assert eligible > 30
    f, seeds = 0.3, range(1001, 1013)
    broken = sum(_broken_at_first_check(tmp_path, f, seed) for seed in seeds)
    trials = eligible * len(seeds)
    sigma = np.sqrt(trials * f * (1 - f))
    assert abs(broken - f * trials) < 4 * sigma, (broken, f * trials, sigma)
    assert _broken_at_first_check(tmp_path, 0.0, 1001) == 0


@pytest.mark.parametrize("line, message", [
    ("fix b all bond/break 1 3 1.0", "fix b (bond/break): bond type 3 is more than the 2 bond types of the box"),
    ("fix b all bond/break 1 1 1.0 prob 1.5 123", "fix b (bond/break): prob's fraction must be from 0 to 1 (got 1.5)"),
    ("fix b all bond/break 1 1 1.0 prob 0.5 0", "fix b (bond/break): prob's seed must be a positive integer (got 0)"),
    ("fix c all bond/create 1 1 4 1.0 1", "fix c (bond/create): jtype 4 is more than the 3 particle types"),
    ("fix c all bond/create 1 1 1 1.0 1 iparam 2 2", "fix c (bond/create): iparam and jparam differ while itype = jtype"),
    ("fix c all bond/create 1 1 2 1.0 1 jparam 2 7", "fix c (bond/create): jparam's newtype 7 is not a particle type (1-3)"),
])
def test_refusals(tmp_path, line, message):
    sim = scene(tmp_path, [(1, 1.0), (1, 2.0)], [(1, 1, 2)])
    with pytest.raises(ScriptError, match=re.escape(message) + "$"):
        sim.command(line)


def test_without_bonds_they_are_refused(tmp_path):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("region b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 single 1 1 1\nmass 1 1.0")
    with pytest.raises(ScriptError, match=re.escape("fix b (bond/break) needs bonds (a particle_style with bonds, "
                                                    "a data file's Bonds)") + "$"):
        sim.command("fix b all bond/break 1 1 1.0")
