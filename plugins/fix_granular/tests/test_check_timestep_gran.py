"""fix check/timestep/gran: warns with the three ratios when dt passes a set fraction of the
Rayleigh or Hertz (or contact) time or a step's motion passes the skin, stays silent when fine,
checks every NEVERY steps, says once when the pair style gives no limits, stops with error yes."""

import pytest

from pdps_core.api import ScriptError, SimulationError
from pdps_core.testing import liggghts_material


def scene(spheres, limits, fix="check/timestep/gran 100 0.1 0.1", dt=0.001):
    return spheres(f"""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 1 single 3 0 0 diameter 1.0
        pair_style {limits}
        pair_coeff * *
        timestep {dt}
        fix 1 all nve/sphere
        fix ts all {fix}
    """)


def test_warns_when_dt_passes_the_fraction_of_the_rayleigh_time(spheres):
    sim = scene(spheres, "test/granular/limits 0.005 0.1 0.2")
    sim.command("run 250")
    # said once, at the start of the run, though every check (steps 0, 100, 200) finds it
    assert sim.warnings == ["fix ts (check/timestep/gran) at step 0: time step 0.001 exceeds 0.1 of the "
                            "Rayleigh time 0.005 (dt/t_rayleigh = 0.2, dt/t_hertz = 0.01, "
                            "v_max*dt/skin = 0)"]
    assert sim.fixes["ts"].ratios == pytest.approx((0.2, 0.01, 0.0))


def test_silent_when_the_time_step_is_fine(spheres):
    sim = scene(spheres, "test/granular/limits 0.05 0.02 0.03")
    sim.v[:] = [100.0, 0.0, 0.0]
    sim.command("run 10")
    assert sim.warnings == []
    # as LIGGGHTS, the check at the start of a run warns but publishes nothing: step 0's row is zeros
    assert sim.fixes["ts"].vector(sim).tolist() == [0.0, 0.0, 0.0]
    sim.command("run 90")
    assert sim.fixes["ts"].ratios == pytest.approx((0.02, 0.05, 100.0 * 0.001 / 0.3))
    # LIGGGHTS's vector f_ts[1..3]: the skin ratio at the relative speed 2 v_max
    assert sim.fixes["ts"].vector(sim).tolist() == pytest.approx([0.02, 0.05, 2 * 100.0 * 0.001 / 0.3])


def test_warn_no_is_silent_and_vmax_is_the_least_speed(spheres):
    sim = scene(spheres, "test/granular/limits 0.005 0.1 0.2", fix="check/timestep/gran 100 0.1 0.1 warn no vmax 50")
    sim.command("run 100")
    assert sim.warnings == []
    # at rest, the skin ratio is that of vmax: 50 * 0.001 / 0.3
    assert sim.fixes["ts"].ratios[2] == pytest.approx(50 * 0.001 / 0.3)


def test_no_hertz_time_beside_a_rayleigh_time_leaves_that_ratio_out(spheres):
    sim = scene(spheres, "test/granular/limits 0.05 0 0.001")
    sim.command("run 100")
    assert sim.warnings == []
    assert sim.fixes["ts"].ratios == pytest.approx((0.02, None, 0.0))


@pytest.mark.parametrize("limits, fix, speed, steps, warning", [
    # no Hertz time: the contact time stands in
    ("test/granular/limits 0 0 0.004", "check/timestep/gran 100 0.1 0.2", 0.0, 0,
     "fix ts (check/timestep/gran) at step 0: time step 0.001 exceeds 0.2 of the contact time 0.004 "
     "(dt/t_rayleigh = n/a, dt/t_contact = 0.25, v_max*dt/skin = 0)"),
    # motion beyond the skin in one step is named with every limit passed
    ("test/granular/limits 0.005 0.1 0.2", "check/timestep/gran 100 0.1 0.1", 400.0, 0,
     "fix ts (check/timestep/gran) at step 0: time step 0.001 exceeds 0.1 of the Rayleigh time 0.005; "
     "particles move up to 0.4 per step, more than the skin 0.3 (dt/t_rayleigh = 0.2, dt/t_hertz = 0.01, "
     "v_max*dt/skin = 1.333)"),
    # every NEVERY steps: t_R = 0.1 / (1 + step), dt / t_R = 0.01 (1 + step) passes 0.1 from step 10,
    # seen at step 12
    ("test/granular/limits 0.1 0 0.5 1.0", "check/timestep/gran 4 0.1 0.1", 0.0, 20,
     "fix ts (check/timestep/gran) at step 12: time step 0.001 exceeds 0.1 of the Rayleigh time 0.007692 "
     "(dt/t_rayleigh = 0.13, dt/t_hertz = n/a, v_max*dt/skin = 0)"),
], ids=["contact time without a hertz time", "motion beyond the skin", "checks every nevery steps"])
def test_one_warning_names_the_limits_passed(spheres, limits, fix, speed, steps, warning):
    sim = scene(spheres, limits, fix=fix)
    sim.v[0] = [0.0, speed, 0.0]
    sim.command(f"run {steps}")
    assert sim.warnings == [warning]


def test_a_pair_style_without_limits_is_reported_once(spheres):
    sim = scene(spheres, "test/no_force", fix="check/timestep/gran 1 0.1 0.1")
    sim.command("run 5\nrun 5")
    assert sim.warnings == ["fix ts (check/timestep/gran): pair style test/no_force gives no "
                            "time-step limits (it has no timestep_limits method), so only the skin "
                            "ratio is checked"]
    assert sim.fixes["ts"].ratios == (None, None, 0.0)


def test_no_pair_style_is_reported(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        fix ts all check/timestep/gran 1 0.1 0.1
        run 2
    """)
    assert sim.warnings == ["fix ts (check/timestep/gran): no pair style is defined, so only the skin "
                            "ratio is checked"]


def test_error_yes_stops_the_run(spheres):
    sim = scene(spheres, "test/granular/limits 0.005 0.1 0.2",
                fix="check/timestep/gran 100 0.1 0.1 error yes")
    with pytest.raises(SimulationError) as error:
        sim.command("run 10")
    assert str(error.value).startswith("<command>:1: run: fix ts (check/timestep/gran) at step 0: time "
                                       "step 0.001 exceeds 0.1 of the Rayleigh time 0.005")


@pytest.mark.parametrize("args, message", [
    ("0 0.1 0.1", "nevery must be >= 1 (got 0)"),
    ("10 0.1", "missing argument fraction_h; usage: fix ID GROUP check/timestep/gran NEVERY "
     "FRACTION_R FRACTION_H [error yes|no] [warn yes|no] [vmax V]"),
    ("10 -0.1 0.1", "fraction_r must be > 0 (got -0.1)"),
    ("10 0.1 0.1 error maybe", "error must be yes or no (got maybe)"),
])
def test_bad_arguments_are_one_line_errors(spheres, args, message):
    sim = spheres("create_particle 1 single 0 0 0")
    with pytest.raises(ScriptError) as error:
        sim.command(f"fix 1 all check/timestep/gran {args}")
    assert error.value.message == message


# Three spheres of two materials falling under gravity onto a plane (LIGGGHTS syntax, this file's
# own scene), thermo every 1000 steps: step, atoms, ke, f_ts[1], f_ts[2], f_ts[3].
LIGGGHTS_SCENE = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 0. 0.15 units box
create_box 2 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + liggghts_material((5.e6, 1.e7), (0.45, 0.3), (0.9, 0.8, 0.8, 0.7), (0.05, 0.1, 0.1, 0.2)) + """\
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix zwalls1 all wall/gran model hertz tangential history primitive type 1 zplane 0.0
create_atoms 1 single 0.0 0.0 0.05
create_atoms 1 single 0.01 0.0 0.08
create_atoms 2 single -0.01 0.01 0.10
set atom 1 diameter 0.006 density 2500
set atom 2 diameter 0.004 density 2500
set atom 3 diameter 0.008 density 1500
velocity all set 0.3 0. -0.5
fix integr all nve/sphere
fix ts all check/timestep/gran 100 0.1 0.1
thermo_style custom step atoms ke f_ts[1] f_ts[2] f_ts[3]
thermo 1000
thermo_modify lost ignore norm no
run 6000
"""
# LIGGGHTS 3.8.0 (Debian's liggghts) on LIGGGHTS_SCENE, recorded on this machine kind. pdps's
# f_ts[2] was 1.28x these (it took half the particle's mass).
LIGGGHTS_ROWS = [
    [0, 3, 0.00013066931, 0, 0, 0],
    [1000, 3, 0.00017206981, 0.03970612, 0.015727561, 0.0066912152],
    [2000, 3, 0.00022086743, 0.03970612, 0.016125162, 0.0075808604],
    [3000, 3, 0.00027706217, 0.03970612, 0.01649486, 0.0084906566],
    [4000, 3, 0.00034065403, 0.03970612, 0.016839232, 0.0094147637],
    [5000, 3, 0.00041164301, 0.03970612, 0.017161016, 0.010349349],
    [6000, 3, 0.00038063439, 0.03970612, 0.017462769, 0.011291811],
]


def test_ratios_are_liggghts_on_every_row(pdps_cli):
    """The three ratios of a LIGGGHTS script equal LIGGGHTS's at every thermo row, to its printed
    digits: the Rayleigh time, the Hertz estimate with each particle's full mass, and the skin
    ratio at the relative speed 2 v_max; zeros at step 0, where LIGGGHTS has not checked yet."""
    from pdps_core.testing import thermo_rows
    result = pdps_cli(LIGGGHTS_SCENE, name="in.liggghts")
    assert result.returncode == 0, result.stderr
    rows = thermo_rows(result.stdout)
    assert len(rows) == len(LIGGGHTS_ROWS)
    for row, expected in zip(rows, LIGGGHTS_ROWS):
        assert row == pytest.approx(expected, rel=2e-7, abs=1e-12)
