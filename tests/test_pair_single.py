"""Pair.single (LAMMPS's Pair::single): for every pair style written as a force law, generated
formulas and hybrid included, the force and energy of a chosen pair equal what the style's own
loop gives that pair in a run; beyond the cutoff both are 0; a style without it says so."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

TWO = """units lj
atom_style atomic
region box block -5 5 -5 5 -5 5
create_box 2 box
create_atoms 1 single 0 0 0
create_atoms 2 single {x} 0.5 -0.3
mass * 1.0
{pair}
thermo_style custom step pe
run 0
"""


def lj_table(path):
    """An LJ section, 1000 points from r 0.5 to 2.5 (LAMMPS's table format)."""
    r = np.linspace(0.5, 2.5, 1000)
    e = 4 * (r ** -12 - r ** -6)
    f = 24 * (2 * r ** -13 - r ** -7)
    rows = "\n".join(f"{k + 1} {r[k]:.17g} {e[k]:.17g} {f[k]:.17g}" for k in range(len(r)))
    path.write_text(f"LJ\nN 1000 R 0.5 2.5\n\n{rows}\n")


STYLES = {
    "lj/cut": "pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0",
    "lj/cut mixed": "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2 2.0",
    "soft": "pair_style soft 1.0\npair_coeff * * 10.0",
    "yukawa": "pair_style yukawa 2.0 2.5\npair_coeff * * 1.0",
    "morse": "pair_style morse 2.5\npair_coeff * * 1.0 2.0 1.2",
    "zero": "pair_style zero 2.5\npair_coeff * *",
    # T = 0: no noise, and particles at rest feel no friction: the loop's force is the conservative one
    "dpd": "pair_style dpd 0.0 1.0 1234\npair_coeff * * 25.0 4.5",
    "table": "pair_style table linear 1000\npair_coeff * * lj.table LJ 2.5",
    "formula": 'pair_style formula 2.5\npair_coeff * * "4*eps*((sig/r)^12 - (sig/r)^6) + A*exp(-r/rho)" '
               "eps 1.0 sig 1.0 A 3.0 rho 0.4",
    "hybrid": "pair_style hybrid lj/cut 2.5 soft 1.0\npair_coeff * * lj/cut 1.0 1.0\npair_coeff 1 2 soft 10.0",
    "hybrid/overlay": "pair_style hybrid/overlay lj/cut 2.5 soft 1.0\npair_coeff * * lj/cut 1.0 1.0\n"
                      "pair_coeff * * soft 10.0",
}


def two_particles(tmp_path, monkeypatch, pair, x=0.7):
    monkeypatch.chdir(tmp_path)
    lj_table(tmp_path / "lj.table")
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(TWO.format(pair=pair, x=x))
    p = sim.particles
    i, j = p.index_of_tag(1), p.index_of_tag(2)
    return sim, i, j, p.x[i] - p.x[j]


@pytest.mark.parametrize("style", STYLES)
def test_single_gives_the_force_and_energy_the_run_gave(tmp_path, monkeypatch, style):
    sim, i, j, delta = two_particles(tmp_path, monkeypatch, STYLES[style])
    fpair, energy = sim.pair.single(sim, [i], [j], [delta])
    assert fpair.shape == energy.shape == (1,)
    np.testing.assert_allclose(fpair[0] * delta, sim.particles.f[i], rtol=1e-12, atol=1e-14)
    assert energy[0] == pytest.approx(sim.pe, rel=1e-12, abs=1e-14)
    if style != "zero":
        assert abs(energy[0]) > 1e-3 and np.abs(sim.particles.f[i]).max() > 1e-3


def test_single_of_lj_is_the_formula(tmp_path, monkeypatch):
    sim, i, j, delta = two_particles(tmp_path, monkeypatch, STYLES["lj/cut"])
    r = math.sqrt(0.7 ** 2 + 0.5 ** 2 + 0.3 ** 2)
    fpair, energy = sim.pair.single(sim, [i, j], [j, i], [delta, -delta])
    np.testing.assert_allclose(energy, 4 * (r ** -12 - r ** -6), rtol=1e-13)
    np.testing.assert_allclose(fpair, 24 * (2 * r ** -14 - r ** -8), rtol=1e-13)


@pytest.mark.parametrize("style", ["lj/cut", "dpd", "formula", "hybrid"])
def test_pairs_beyond_the_cutoff_give_nothing(tmp_path, monkeypatch, style):
    sim, i, j, delta = two_particles(tmp_path, monkeypatch, STYLES[style])
    far = delta / np.linalg.norm(delta) * 2.5 * (1 + 1e-12)     # just beyond: 2.5 itself rounds either way
    fpair, energy = sim.pair.single(sim, [i, i], [j, j], [far, far * 1.5])
    assert fpair.tolist() == [0.0, 0.0] and energy.tolist() == [0.0, 0.0]


def test_a_style_without_single_says_so(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("""atom_style sphere
region box block -5 5 -5 5 -5 5
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.9 0 0
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
run 0""")
    with pytest.raises(ScriptError, match=r"pair style gran/hooke cannot evaluate chosen pairs \(it has no single\(\)\)"):
        sim.pair.single(sim, [0], [1], [[0.9, 0.0, 0.0]])


def test_extract_gives_a_coefficient_per_type_pair_and_the_global_values(tmp_path, monkeypatch):
    sim, *_ = two_particles(tmp_path, monkeypatch, STYLES["lj/cut mixed"])
    epsilon = sim.pair.extract("epsilon")
    assert epsilon.shape == (3, 3) and math.isnan(epsilon[0, 0])
    assert epsilon[1, 1] == 1.0 and epsilon[2, 2] == 0.5 and epsilon[1, 2] == epsilon[2, 1] == math.sqrt(0.5)
    cutoff = sim.pair.extract("cutoff")
    assert cutoff[1, 1] == 2.5 and cutoff[2, 2] == 2.0 and cutoff[1, 2] == pytest.approx(math.sqrt(5.0))
    with pytest.raises(ScriptError, match=r"pair style lj/cut has no value eps \(it has: cutoff, epsilon, sigma\)"):
        sim.pair.extract("eps")
