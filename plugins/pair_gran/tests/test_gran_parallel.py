"""A settling bed of frictional spheres (gran/hooke/history on a wall/gran floor) gives the same
kinetic energies on 1 and 2 ranks: springs of contacts across the rank boundary are kept by both
sides and merged back on their owners (as LAMMPS's reverse communication of history)."""

import numpy as np
import pytest

from pdps_core.testing import contacts_held_on_ranks, run_ranks, sphere_bed, thermo_on_ranks, thermo_rows


def bed(path):
    """Polydisperse spheres (d 0.8-1.2) on a loose lattice over a floor, with random velocities."""
    sphere_bed(path, (12, 6, 4), (0.7, 0.7, 0.7), (0, 0, 0), (15.6, 7.8, 12), ntypes=1, seed=11)


def kinetic_energies(tmp_path, ranks):
    bed(tmp_path / "bed.data")
    done = run_ranks("""\
        units lj
        atom_style sphere
        boundary p p f
        comm_modify vel yes
        read_data bed.data
        pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 1
        pair_coeff * *
        timestep 0.0001
        fix 1 all nve/sphere
        fix 2 all gravity 10.0 vector 0 0 -1
        fix 3 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 NULL
        thermo_style custom step ke
        thermo_modify format float %.15g
        thermo 500
        run 4000
        """, ranks, tmp_path)
    return np.array(thermo_rows(done.stdout))


def test_same_settling_on_1_and_2_ranks(tmp_path):
    one = kinetic_energies(tmp_path, 1)
    two = kinetic_energies(tmp_path, 2)
    assert one[:, 0].tolist() == list(range(0, 4001, 500))
    # free fall would add (g t)^2 / 2 = 8 per sphere by t = 0.4: the floor and the contacts took some
    assert one[-1, 1] < one[0, 1] + 0.6 * 8.0
    assert two == pytest.approx(one, rel=1e-9)


def test_liggghts_model_with_rolling_spring_and_cohesion_on_1_and_2_ranks(tmp_path):
    """pair gran with epsd (a rolling spring torque in each contact's history besides the
    tangential spring: six values merged back on their owners) and sjkr cohesion: the same
    kinetic energies on 1 and 2 ranks."""
    bed(tmp_path / "bed.data")
    script = """\
        units lj
        atom_style granular
        boundary p p f
        read_data bed.data
        fix m1 all property/global youngsModulus peratomtype 1.e5 1.e5
        fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
        fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
        fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
        fix m5 all property/global coefficientRollingFriction peratomtypepair 2 0.2 0.2 0.2 0.2
        fix m6 all property/global coefficientRollingViscousDamping peratomtypepair 2 0.3 0.3 0.3 0.3
        fix m7 all property/global cohesionEnergyDensity peratomtypepair 2 500 500 500 500
        pair_style gran model hertz tangential history rolling_friction epsd cohesion sjkr
        pair_coeff * *
        timestep 0.0005
        fix 1 all nve/sphere
        fix 2 all gravity 10.0 vector 0 0 -1
        fix 3 all wall/gran model hertz tangential history primitive type 2 zplane 0.0
        thermo_style custom step ke
        thermo_modify format float %.15g
        thermo 500
        run 3000
        """
    # the data file has one type: a second (the floor's material) is made room for
    (tmp_path / "bed.data").write_text((tmp_path / "bed.data").read_text().replace("1 atom types", "2 atom types"))
    one, two = thermo_on_ranks(script, tmp_path)
    assert one[:, 0].tolist() == list(range(0, 3001, 500))
    assert not np.allclose(one[-1, 1], one[0, 1])
    assert two == pytest.approx(one, rel=1e-9)


LIGGGHTS_EPSD_PAIR = "gran model hertz tangential history rolling_friction epsd cohesion sjkr"
LIGGGHTS_EPSD_MATERIAL = """\
    fix m1 all property/global youngsModulus peratomtype 5.e7
    fix m2 all property/global poissonsRatio peratomtype 0.45
    fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
    fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
    fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.1
    fix m6 all property/global coefficientRollingViscousDamping peratomtypepair 1 0.3
    fix m7 all property/global cohesionEnergyDensity peratomtypepair 1 1000.0
"""


def hot_gas(path, seed=6):
    """100 spheres (d 1, m 1) near the sites of a lattice of spacing 1.2 in a periodic box 6 wide
    (a data file), and Gaussian velocities of deviation 8 for them."""
    rng = np.random.default_rng(seed)
    sites = (np.stack(np.meshgrid(*[np.arange(5)] * 3, indexing="ij"), -1).reshape(-1, 3)[:100] * 1.2
             + 0.6 + rng.uniform(-0.02, 0.02, (100, 3)))
    lines = ["gas", "", "100 atoms", "1 atom types", "", "0 6 xlo xhi", "0 6 ylo yhi", "0 6 zlo zhi", "",
             "Atoms # sphere", ""]
    lines += [f"{k} 1 1.0 1.9098593171027440 {p[0]!r} {p[1]!r} {p[2]!r}" for k, p in enumerate(sites.tolist(), 1)]
    path.write_text("\n".join(lines) + "\n")
    return rng.normal(0.0, 8.0, (100, 3))


HOOKE_STIFF = "gran/hooke/history 2000000.0 NULL 50.0 NULL 0.5 1"


@pytest.mark.parametrize("pair, material, grid", [(HOOKE_STIFF, "", "2 1 1"),
                                                  (LIGGGHTS_EPSD_PAIR, LIGGGHTS_EPSD_MATERIAL, "2 1 1"),
                                                  (HOOKE_STIFF, "", "2 2 1")],
                         ids=["gran/hooke/history", "gran model", "gran/hooke/history on 4 ranks"])
def test_contact_slots_hold_exactly_the_contacts_of_each_step_on_several_ranks(tmp_path, pair, material, grid):
    """On several ranks a contact across a cut keeps its spring on both sides and the mirror written
    into a ghost goes back to its owner; between list builds only the rows that held a contact, those
    this step's contacts touched and those the mirrors came back to are swept. In a hot gas cut
    across x (and y on four ranks, where a rank has ghosts from three others), at every step the
    owned spheres' slots, over all ranks, hold exactly the pairs that touch (gran model: those and
    the pairs that came apart since the last list build, LIGGGHTS's rule). The springs are stiff
    (a contact lasts a few steps, builds come every seven), so that contacts end between builds:
    with soft ones every contact outlives a build and a row left unswept would not show."""
    velocities = hot_gas(tmp_path / "gas.data")
    script = """\
        units lj
        atom_style sphere
        boundary p p p
        comm_modify vel yes
        processors {grid}
        read_data gas.data
        """.format(grid=grid) + material + f"""\
        pair_style {pair}
        pair_coeff * *
        timestep 0.0004
        neighbor 0.1 bin
        neigh_modify delay 0 every 1 check yes
        fix 1 all nve/sphere
        """
    ranks = int(np.prod([int(n) for n in grid.split()]))
    exact, builds, contacts, until_build, inexact = contacts_held_on_ranks(script, velocities, 400, ranks,
                                                                          tmp_path)
    print(f"builds {builds}, touching pairs summed over the steps {contacts}, steps holding pairs apart "
          f"{inexact}")
    assert builds > 20 and contacts > 400
    if pair == HOOKE_STIFF:
        assert exact
    else:
        assert until_build and inexact > 20
