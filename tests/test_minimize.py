"""``minimize`` (LAMMPS's cg, sd and fire) on an overlapping Lennard-Jones start: the same start energy as
LAMMPS, and a final energy LAMMPS's own run reaches (tests/data/lammps/minimize.txt, recorded by
benchmarks/lammps_references/minimize.py)."""

import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_prints_as_lammps, script_error

DATA = Path(__file__).parent / "data" / "lammps"
REFERENCE = {row.split("\t")[0]: row.split("\t")[1:] for row in (DATA / "minimize.txt").read_text().splitlines()
             if not row.startswith("#")}
MINIMIZE = (DATA / "minimize.txt").read_text().splitlines()[0].split(";")[0].lstrip("# ")


def minimized(tmp_path, monkeypatch, style, extra=""):
    shutil.copy(DATA / "min_start.data", tmp_path / "min_start.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style atomic\nread_data min_start.data\nmass 1 1.0\npair_style lj/cut 2.5\n"
                "pair_coeff 1 1 1.0 1.0 2.5\nneighbor 0.3 bin\nneigh_modify every 1 delay 0 check yes\n"
                f"min_style {style}\nthermo 0\n{extra}{MINIMIZE}")
    return sim


@pytest.mark.parametrize("style", sorted(REFERENCE))
def test_minimize_reaches_the_energy_lammps_reaches(tmp_path, monkeypatch, style):
    initial, final, iterations, _, criterion = REFERENCE[style]
    sim = minimized(tmp_path, monkeypatch, style)
    result = sim.run_state.minimize_result
    assert result["initial"] == pytest.approx(float(initial), rel=1e-12)
    # a few hundred iterations of floating-point paths apart: the same basin, the same minimum
    assert result["final"] == pytest.approx(float(final), rel=1e-6), (result, final, iterations, criterion)
    assert result["final"] < result["initial"]
    assert sim.step == result["iterations"]


def test_cg_lowers_the_energy_every_iteration_and_ends_near_zero_force(tmp_path, monkeypatch):
    sim = minimized(tmp_path, monkeypatch, "cg")
    result = sim.run_state.minimize_result
    energies = np.array(result["energies"])
    assert len(energies) == result["iterations"] + 1
    assert np.all(np.diff(energies) <= 1e-12)                 # each line search only goes down
    assert result["fnorm"] / np.sqrt(sim.nlocal) < 1e-3       # per-atom force near zero at the end


@pytest.mark.parametrize("line, message", [
    ("minimize 1e-4 1e-6 100", "expected 4 argument(s), got 3; usage: minimize ETOL FTOL MAXITER MAXEVAL"),
    ("minimize -1 1e-6 100 1000", "etol must be >= 0 (got -1)"),
    ("minimize 0 0 0 1000", "maxiter must be >= 1 (got 0)"),
    ("min_style hftn", "min_style must be one of cg, sd, fire (got hftn)"),
    ("min_modify dmax 0", "dmax must be > 0 (got 0)"),
])
def test_minimize_errors(line, message):
    assert script_error("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1", line).message == message


# A 2-d LJ slab on a hex lattice, its lower rows held by fix setforce (LAMMPS's examples/indent's
# first minimization, on a smaller slab: this file's own script).
SLAB = """
dimension     2
boundary      p s p
atom_style    atomic
neighbor      0.3 bin
neigh_modify  delay 5
lattice       hex 0.9
region        box block 0 12 0 8 -0.25 0.25
create_box    2 box
create_atoms  1 box
mass          * 1.0
pair_style    lj/cut 2.5
pair_coeff    * * 1.0 1.0 2.5
region        1 block INF INF INF 1.25 INF INF
group         lower region 1
group         mobile subtract all lower
set           group lower type 2
{fixes}
fix           5 all enforce2d
thermo        10
minimize      1.0e-6 1.0e-6 1000 1000
"""
# LAMMPS 22 Jul 2025 on SLAB: final energy, iterations, force evaluations. Fixes take part through
# their min_post_force (setforce, addforce); fix gravity has none, so it changes nothing. pdps ignored
# setforce (it reached -3.16549934, near the slab without it) and used the script's delay 5 between
# line-search steps, which LAMMPS overrides with a warning.
SLAB_LAMMPS = {
    "": (-3.165516616055, 15, 30),
    "fix 2 lower setforce 0.0 0.0 0.0": (-3.16338532820689, 31, 62),
    "fix 2 lower setforce 0.0 0.0 0.0\nfix 3 mobile addforce 0.0 -0.05 0.0": (-3.16337707714086, 21, 77),
    "fix 2 lower setforce 0.0 0.0 0.0\nfix 3 mobile gravity 1.0 vector 0 -1 0": (-3.16338532820689, 31, 62),
}


@pytest.mark.parametrize("fixes", sorted(SLAB_LAMMPS))
def test_fixes_take_part_in_minimization_as_lammps(fixes):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SLAB.format(fixes=fixes))
    final, iterations, evaluations = SLAB_LAMMPS[fixes]
    result = sim.run_state.minimize_result
    assert result["final"] == pytest.approx(final, rel=1e-12)
    assert (result["iterations"], result["evaluations"]) == (iterations, evaluations)
    assert sim.warnings == ["Using 'neigh_modify every 1 delay 0 check yes' setting during minimization"]
    # the run's own settings come back after the minimization
    assert (sim.neighbor.every, sim.neighbor.delay, sim.neighbor.check) == (1, 5, True)


def test_a_force_fix_that_cannot_take_part_is_refused_at_the_minimize_line(pdps_cli):
    from pdps_core.testing import ConstantForce
    from pdps_core.testing import register_styles
    register_styles(ConstantForce)
    result = pdps_cli(SLAB.format(fixes="fix 2 lower test/force 0.0 0.1 0.0"), name="in.slab")
    assert result.returncode == 1
    assert result.stderr.strip().splitlines()[-1] == (
        "ERROR: in.slab:21: minimize: fix 2 (test/force) changes forces in a run but cannot take part in a "
        "minimization (it has no min_post_force); unfix it before minimize")


# A 2-d LJ slab relaxing on a fixed layer, periodic in x and shrink-wrapped in y: particles cross
# the periodic face during line searches. LAMMPS 22 Jul 2025 printed WRAPPING_SLAB_LAMMPS on this
# machine. Before 12-08 pdps left the line search's origin unwrapped when a rebuild wrapped a
# particle, read the wrap as a move past the skin at the next evaluation and rebuilt there: the
# box followed other positions and the runs parted at iteration 6.
WRAPPING_SLAB = """dimension 2
boundary p s p
atom_style atomic
neighbor 0.3 bin
lattice hex 0.95
region box block 0 16 0 12 -0.25 0.25
create_box 2 box
create_atoms 1 box
mass * 1.0
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0 2.5
region 1 block INF INF INF 1.25 INF INF
group lower region 1
set group lower type 2
fix 2 lower setforce 0.0 0.0 0.0
fix 5 all enforce2d
thermo 1
thermo_style custom step pe press vol yhi
thermo_modify format float %.15g
minimize 1.0e-6 1.0e-6 1000 1000
"""
WRAPPING_SLAB_LAMMPS = [
    [0, -3.2096659383804, 1.24125922152716, 404.291368421053, 22.9170220278717],
    [1, -3.20968987463532, 1.19162339405534, 404.291368421053, 22.9170220278717],
    [2, -3.2102506932775, 1.19075673468458, 404.291368421053, 22.9170220278717],
    [3, -3.21041291356768, 1.19007631491497, 404.291368421053, 22.9170220278717],
    [4, -3.2106767137087, 1.15900217255726, 404.291368421053, 22.9170220278717],
    [5, -3.21094508255627, 1.10504077756103, 404.291368421053, 22.9170220278717],
    [6, -3.21149434584775, 1.03756179953883, 406.953398993558, 23.0679327769154],
    [7, -3.21163019914974, 1.00962941173966, 406.953398993558, 23.0679327769154],
    [8, -3.21192333029727, 0.977937921273294, 406.953398993558, 23.0679327769154],
    [9, -3.2123172549335, 0.966138545418323, 406.953398993558, 23.0679327769154],
    [10, -3.21261699331725, 0.954993137606481, 406.953398993558, 23.0679327769154],
    [11, -3.21284178523812, 0.939781908938768, 406.953398993558, 23.0679327769154],
    [12, -3.21311719614726, 0.920290642265349, 406.953398993558, 23.0679327769154],
    [13, -3.21337539475138, 0.902241231486511, 406.953398993558, 23.0679327769154],
    [14, -3.21362923090878, 0.89064256297338, 406.953398993558, 23.0679327769154],
    [15, -3.21375450980256, 0.884125165677706, 406.953398993558, 23.0679327769154],
    [16, -3.21391571881118, 0.873138825853798, 406.953398993558, 23.0679327769154],
    [17, -3.21416069847022, 0.853988605450335, 406.953398993558, 23.0679327769154],
    [18, -3.21437193047745, 0.8395540148285, 406.953398993558, 23.0679327769154],
    [19, -3.21456523863886, 0.82765876816656, 406.953398993558, 23.0679327769154],
    [20, -3.21475924477161, 0.821773618647251, 407.272281683622, 23.0860102648719],
    [21, -3.21501205146796, 0.812440904472726, 407.272281683622, 23.0860102648719],
    [22, -3.21535675823167, 0.783571452123216, 407.272281683622, 23.0860102648719],
    [23, -3.21566955200973, 0.758227165589271, 407.272281683622, 23.0860102648719],
    [24, -3.21579497907213, 0.7477795342537, 407.272281683622, 23.0860102648719],
    [25, -3.21589345903003, 0.73933867455783, 407.272281683622, 23.0860102648719],
    [26, -3.21600283721645, 0.723801087357031, 407.272281683622, 23.0860102648719],
    [27, -3.21606143944508, 0.709021229612269, 407.272281683622, 23.0860102648719],
    [28, -3.21615313881913, 0.697963438687414, 407.272281683622, 23.0860102648719],
    [29, -3.21621139540488, 0.689382787290252, 407.272281683622, 23.0860102648719],
    [30, -3.21623813361973, 0.681896197756019, 407.272281683622, 23.0860102648719],
    [31, -3.21627503723598, 0.671396166798412, 407.272281683622, 23.0860102648719],
    [32, -3.21634933503229, 0.664014509900504, 407.272281683622, 23.0860102648719],
    [33, -3.21640483112516, 0.655662092757062, 407.272281683622, 23.0860102648719],
    [34, -3.21643974725974, 0.647793370518173, 407.272281683622, 23.0860102648719],
    [35, -3.21647684776639, 0.634906751087662, 407.272281683622, 23.0860102648719],
    [36, -3.21652051752371, 0.624629147530206, 407.272281683622, 23.0860102648719],
    [37, -3.21653968311134, 0.618941199911472, 407.272281683622, 23.0860102648719],
    [38, -3.21655199359885, 0.612091062931862, 409.97276101808, 23.2391006776377],
    [39, -3.21655883108458, 0.610236535510698, 409.97276101808, 23.2391006776377],
    [40, -3.21657341843444, 0.605773964267825, 409.97276101808, 23.2391006776377],
    [41, -3.21659138163728, 0.600465882393178, 409.97276101808, 23.2391006776377],
    [42, -3.21660638126212, 0.595596286992082, 409.97276101808, 23.2391006776377],
    [43, -3.21663020557792, 0.589529739591247, 409.97276101808, 23.2391006776377],
    [44, -3.2166582595708, 0.578678039377373, 409.97276101808, 23.2391006776377],
    [45, -3.21669490059229, 0.566490215059037, 409.97276101808, 23.2391006776377],
    [46, -3.21671134073518, 0.559998824234342, 409.97276101808, 23.2391006776377],
    [47, -3.21673175354454, 0.556448219049533, 409.97276101808, 23.2391006776377],
    [48, -3.21675476041391, 0.554546858548203, 409.97276101808, 23.2391006776377],
    [49, -3.21677160816014, 0.553396897973391, 409.97276101808, 23.2391006776377],
    [50, -3.2167774623167, 0.551749885650495, 409.97276101808, 23.2391006776377],
    [51, -3.21678113109933, 0.549953306471263, 409.97276101808, 23.2391006776377],
    [52, -3.21678432324697, 0.547416308597331, 409.97276101808, 23.2391006776377],
]


def test_line_search_origins_follow_particles_wrapped_at_a_rebuild(tmp_path):
    assert_prints_as_lammps(tmp_path, WRAPPING_SLAB, WRAPPING_SLAB_LAMMPS, rel=1e-11, abs=1e-12)
