"""What fixes contribute to thermo: energy to pe (fix_modify energy yes), virial to press
(fix_modify virial yes), arguments read from variables each step."""

import math

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, SimulationError, observables, registry
from pdps_core.testing import build, forces_by_tag, thermo_csv

EPS, RC, L, KT, N = 50.0, 1.0, 10.0, 1.0, 1000
WALLS = " ".join(f"{face} EDGE {EPS} 1.0 {RC}" for face in ("xlo", "xhi", "ylo", "yhi", "zlo", "zhi"))


# ---- energy: fix addforce in a constant field -----------------------------------------------------
def test_addforce_energy_joins_pe_only_after_fix_modify(tmp_path):
    """A constant field F: the fix's energy is -F . x summed over unwrapped positions (LAMMPS)."""
    x = np.array([[1.0, 2.0, 3.0], [4.0, 5.0, 6.5], [7.5, 1.5, 2.5]])
    sim = build(tmp_path, x, setup="pair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\n"
                                   "variable fx equal 0.5\nfix push all addforce v_fx -1.0 2.0\nrun 0")
    pair_only = sim.pe
    sim.command("fix_modify push energy yes\nrun 0")
    field = np.array([0.5, -1.0, 2.0])
    assert sim.pe - pair_only == pytest.approx(-(x @ field).sum(), rel=1e-14)
    sim.command("fix_modify push energy no\nrun 0")
    assert sim.pe == pair_only


def test_addforce_counts_image_flags_in_its_energy(tmp_path):
    sim = build(tmp_path, [[9.5, 5.0, 5.0]], v=[[2.0, 0.0, 0.0]],
                setup="fix 1 all nve\nfix push all addforce 1.0 0.0 0.0\nfix_modify push energy yes\n"
                      "timestep 0.1\nrun 10")
    # the particle crossed the periodic face: its unwrapped x is image * L + x
    unwrapped = sim.x[0, 0] + sim.particles.image[0, 0] * 10.0
    assert sim.particles.image[0, 0] == 1
    assert sim.pe == pytest.approx(-unwrapped, rel=1e-12)


def test_addforce_variable_components_are_read_every_step(tmp_path):
    """F_x = 0.01 * step: the impulse over 10 steps of dt 0.1 is 0.1 * 0.01 * (1 + ... + 10) (the
    force of step n acts in the second half-kick of step n and the first of n+1)."""
    sim = build(tmp_path, [[5.0, 5.0, 5.0]], setup="variable ramp equal 0.01*step\n"
                "fix 1 all nve\nfix push all addforce v_ramp 0.0 0.0\ntimestep 0.1\nrun 10")
    half_kicks = 0.5 * 0.1 * 0.01 * (0 + 2 * sum(range(1, 10)) + 10)
    assert sim.v[0, 0] == pytest.approx(half_kicks, rel=1e-12)
    assert forces_by_tag(sim)[0, 0] == pytest.approx(0.1, rel=1e-12)


@pytest.mark.parametrize("line, message", [
    ("fix_modify 9 energy yes", "fix_modify: fix 9 is not defined"),
    ("fix_modify n energy yes", "fix_modify: fix n (nve) has no energy to contribute"),
    ("fix_modify n virial maybe", "fix_modify: virial must be one of yes, no (got maybe)"),
    ("fix_modify n temp t", "fix_modify: unknown keyword temp; expected: fix_modify ID [energy yes|no] [virial yes|no]"),
    ("fix_modify push energy", "fix_modify: expected: fix_modify ID [energy yes|no] [virial yes|no]"),
])
def test_fix_modify_errors(tmp_path, line, message):
    sim = build(tmp_path, [[5.0, 5.0, 5.0]], setup="fix n all nve\nfix push all addforce 1 0 0")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value) == f"<command>:1: {message}"


def test_addforce_with_an_undefined_variable_is_a_one_line_error(tmp_path):
    sim = build(tmp_path, [[5.0, 5.0, 5.0]], setup="fix push all addforce v_nope 0 0")
    with pytest.raises(ScriptError, match=r"variable nope is not defined \(argument v_nope\)"):
        sim.command("run 0")


# ---- virial: an ideal gas held by walls ------------------------------------------------------------
def excluded_length():
    """The length one harmonic wall takes from the gas: int_0^rc (1 - exp(-eps (rc-d)^2 / kT)) dd."""
    return RC - 0.5 * math.sqrt(math.pi * KT / EPS) * math.erf(RC * math.sqrt(EPS / KT))


@pytest.mark.parametrize("virial", ["yes", "no"])
def test_ideal_gas_between_walls_reads_the_pressure_it_exerts_on_them(tmp_path, virial):
    """N ideal-gas particles at temperature T (Langevin) in a cube of side L with a harmonic wall on
    each face. The gas fills the accessible volume h^3, h = L - 2 x (excluded length), at density
    n0 = N / h^3; the force on one wall is n0 k T h^2 (the other walls keep the gas off the wall's
    edges), so the pressure on the walls, force over wall area, is N k T / (h L^2). With the walls'
    virial (fix_modify virial yes) press is that; without it (LAMMPS's default) press is the
    kinetic part N k T / L^3 alone."""
    rng = np.random.default_rng(17)
    x = rng.uniform(1.5, L - 1.5, size=(N, 3))
    sim = build(tmp_path, x, hi=(L, L, L), boundary="f f f", log=tmp_path / "log.gas", setup=f"""
        velocity all create {KT} 5512 dist gaussian
        fix 1 all nve
        fix t all langevin {KT} {KT} 1.0 7331
        fix w all wall/harmonic {WALLS}
        fix_modify w virial {virial}
        timestep 0.005
        run 4000
        thermo 10
        thermo_style custom step press
        run 40000
    """)
    sim.close()
    press = thermo_csv(tmp_path / "log.gas.2.csv")["Press"][1:]
    blocks = press.reshape(20, -1).mean(axis=1)       # 10 time units each, 20 damping times
    mean, error = blocks.mean(), blocks.std(ddof=1) / math.sqrt(len(blocks))
    h = L - 2 * excluded_length()
    expected = N * KT / (h * L * L) if virial == "yes" else N * KT / L ** 3
    assert abs(mean - expected) < 2.0 * error, (mean, expected, error)
    assert error < 0.05 * abs(N * KT / (h * L * L) - N * KT / L ** 3)   # the test tells the two apart


# ---- a virial complete only after final_integrate (fix rigid's constraint forces) -----------------
class LateVirial(Fix):
    """Sets its virial in setup and final_integrate: w = 3 (step + 1) on each diagonal component."""
    name = "test/latevirial"
    can_virial = True
    virial_default = True
    virial_after = "final_integrate"

    def setup(self, sim):
        self.w = 3.0

    def final_integrate(self, sim):
        self.w = 3.0 * (sim.step + 1)

    def compute_virial(self, sim):
        return (self.w, self.w, self.w, 0.0, 0.0, 0.0)


def test_a_virial_after_final_integrate_enters_the_pressure_of_its_own_step(tmp_path):
    """Particles at rest, no pair style: press = w / V, w the value final_integrate set this step
    (read after post_force it would be the step before's)."""
    registry.register("fix", LateVirial.name, LateVirial)
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [5.0, 5.0, 5.0]], setup="fix late all test/latevirial\nrun 0")
    assert observables.pressure(sim) == pytest.approx(3.0 / 1000.0, rel=1e-14)
    sim.command("thermo 1\nrun 4")
    assert observables.pressure(sim) == pytest.approx(3.0 * 5 / 1000.0, rel=1e-14)
    sim.command("fix_modify late virial no\nrun 2")
    assert observables.pressure(sim) == 0.0


# ---- degrees of freedom a fix removes -------------------------------------------------------------
class Constrain(Fix):
    """Removes ``removed`` degrees of freedom from every group (a stand-in for constraints)."""
    name = "test/constrain"
    removed = 0

    def dof_removed(self, sim, group):
        return self.removed


@pytest.mark.parametrize("removed, dof", [(0, 3), (3, 0)])
def test_degrees_of_freedom_are_dn_less_d_less_what_fixes_remove(tmp_path, removed, dof):
    registry.register("fix", Constrain.name, Constrain)
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [5.0, 5.0, 5.0]], setup="fix c all test/constrain")
    sim.fixes["c"].removed = removed
    assert observables.degrees_of_freedom(sim) == dof


def test_fewer_than_zero_degrees_of_freedom_is_an_error_as_in_lammps(tmp_path):
    """LAMMPS's compute temp stops with "Temperature compute degrees of freedom < 0" (a rigid dimer
    of spheres: 6 - 3 - 6 = -3); an empty group has none and no error."""
    registry.register("fix", Constrain.name, Constrain)
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [5.0, 5.0, 5.0]],
                setup="fix c all test/constrain\ngroup nobody id 99\nthermo_style custom step temp")
    sim.fixes["c"].removed = 6
    with pytest.raises(SimulationError) as caught:
        sim.command("run 0")
    assert str(caught.value) == ("<command>:1: run: temperature of group all: degrees of freedom < 0 (3 x 2 particles "
                                 "- 3 - 6 removed by fix c (test/constrain) 6 = -3)")
    assert observables.degrees_of_freedom(sim, "nobody") == 0
