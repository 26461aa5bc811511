"""fix rigid and rigid/nve: free rotation (conservation, the intermediate-axis instability), constant
force and torque against the analytic motion, rigid/nve's energy against rigid's, bodies across
periodic boundaries, degrees of freedom, and the errors of bad input."""

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, StyleArgs
from pdps_core.testing import build, register_styles

# a body of six unit masses on its principal axes: I = 2 (b^2 + c^2), 2 (a^2 + c^2), 2 (a^2 + b^2)
A, B, C = 1.0, 0.7, 0.4
MOMENTS = np.array([2 * (B * B + C * C), 2 * (A * A + C * C), 2 * (A * A + B * B)])    # 1.3, 2.32, 2.98
OCTAHEDRON = np.array([[A, 0, 0], [-A, 0, 0], [0, B, 0], [0, -B, 0], [0, 0, C], [0, 0, -C]])


class Probe(Fix):
    """``fix ID GROUP test/rigid_probe``: every step, the kinetic energy, angular momentum about the
    centre of mass and centre of mass of the group's particles (this rank's; serial tests)."""
    name = "test/rigid_probe"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.energy_, self.angmom, self.centre, self.x = [], [], [], []

    def end_of_step(self, sim):
        p = sim.particles
        order = np.argsort(p.tag[: p.nlocal])
        x = (p.x[: p.nlocal] + p.image[: p.nlocal] * sim.box.length)[order]
        v = p.v[: p.nlocal][order]
        centre = x.mean(axis=0)
        self.energy_.append(0.5 * float((v * v).sum()))
        self.angmom.append(np.cross(x - centre, v).sum(axis=0))
        self.centre.append(centre)
        self.x.append(x)


class Torque(Fix):
    """``fix ID GROUP test/torque TX TY TZ FX FY FZ``: on a body of unit masses, f_i = F/n +
    tau x r_i / sum |r_i|^2 (r_i from the centre of mass): total force F and, for a body flat in the
    plane normal to tau, total torque tau."""
    name = "test/torque"

    class Args(StyleArgs):
        tx: float
        ty: float
        tz: float
        fx: float
        fy: float
        fz: float

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        r = (p.x[:n] + p.image[:n] * sim.box.length)[chosen]
        r = r - r.mean(axis=0)
        tau = np.array([self.args.tx, self.args.ty, self.args.tz])
        force = np.array([self.args.fx, self.args.fy, self.args.fz])
        p.f[:n][chosen] += force / len(r) + np.cross(tau, r) / (r * r).sum()


register_styles(Probe, Torque)


def spinning(tmp_path, omega, style, dt=0.001, centre=(0.0, 0.0, 0.0), box=10.0, boundary="f f f"):
    x = OCTAHEDRON + np.asarray(centre)
    v = np.cross(omega, OCTAHEDRON)
    return build(tmp_path, x, v=v, lo=(-box,) * 3, hi=(box,) * 3, boundary=boundary,
                 setup=f"""
                 timestep {dt}
                 fix 1 all {style} single
                 fix 2 all test/rigid_probe
                 """)


def drift(probe):
    """Largest relative change of the kinetic energy and of |L - L0| / |L0| over the run."""
    energy = np.array(probe.energy_)
    angmom = np.array(probe.angmom)
    return (float(np.abs(energy / energy[0] - 1).max()),
            float(np.linalg.norm(angmom - angmom[0], axis=1).max() / np.linalg.norm(angmom[0])))


@pytest.mark.parametrize("omega", [(1.0, 0, 0), (0, 1.0, 0), (0, 0, 1.0), (0.6, 0.5, -0.7)],
                         ids=["axis1", "axis2", "axis3", "off-axis"])
def test_free_body_conserves_energy_and_angular_momentum(tmp_path, omega):
    """1e5 steps of dt = 2.5e-4 (4 turns): the splitting's energy error is O(dt^2) and bounded,
    1.3e-8 off-axis at dt = 5e-4."""
    sim = spinning(tmp_path, np.array(omega), "rigid/nve", dt=0.00025)
    sim.run(100_000)
    energy, angmom = drift(sim.fixes["2"])
    print(f"omega {omega}: energy {energy:.2e}, angular momentum {angmom:.2e} over 1e5 steps")
    assert energy < 1e-8
    assert angmom < 1e-8
    # the spin about a principal axis stays an exact spin
    if np.count_nonzero(omega) == 1:
        assert sim.fixes["1"].omega[0] == pytest.approx(omega, abs=1e-9)


def axis_alignment(probe, pair):
    """Cosine between the axis through particles ``pair`` and the angular momentum, per step."""
    x = np.array(probe.x)
    axis = x[:, pair[0]] - x[:, pair[1]]
    axis /= np.linalg.norm(axis, axis=1)[:, None]
    angmom = np.array(probe.angmom)
    return (axis * angmom).sum(axis=1) / np.linalg.norm(angmom, axis=1)


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_only_the_intermediate_axis_is_unstable(tmp_path, axis):
    """A spin about principal axis k with a 1 % wobble: about the smallest and largest moments the
    axis stays within a few degrees of L; about the middle one it turns over (Dzhanibekov)."""
    omega = np.full(3, 0.01)
    omega[axis] = 2.0
    sim = spinning(tmp_path, omega, "rigid/nve", dt=0.002)
    sim.run(20_000)
    pairs = [(0, 1), (2, 3), (4, 5)]
    cosine = axis_alignment(sim.fixes["2"], pairs[axis])
    print(f"axis {axis + 1} (I = {MOMENTS[axis]:.3g}): cos(axis, L) from {cosine[0]:.4f}, min {cosine.min():.4f}")
    if axis == 1:
        assert cosine.min() < -0.99
    else:
        assert cosine.min() > 0.99


@pytest.mark.parametrize("style", ["rigid", "rigid/nve"])
def test_constant_force_and_torque_follow_the_analytic_motion(tmp_path, style):
    """A flat body (in the xy plane) under a constant force and a constant torque along z, the
    normal of its plane and one of its principal axes: X = X0 + F t^2 / 2M, phi = tau t^2 / 2 I_z.
    The force is defined before the body, so that the body's setup sums it (fixes set up in script
    order, as LAMMPS's: after it, the first half-kick would miss it)."""
    flat = np.array([[1.0, 0, 0], [-1.0, 0, 0], [0, 0.5, 0], [0, -0.5, 0]])
    dt, steps = 0.001, 4000
    tau, force = 0.3, np.array([0.2, -0.1, 0.05])
    sim = build(tmp_path, flat, lo=(-10,) * 3, hi=(10,) * 3, boundary="f f f",
                setup=f"""
                timestep {dt}
                fix 2 all test/torque 0 0 {tau} {force[0]} {force[1]} {force[2]}
                fix 1 all {style} single
                fix 3 all test/rigid_probe
                """)
    sim.run(steps)
    probe = sim.fixes["3"]
    t = dt * steps
    mass, inertia_z = 4.0, 2 * 1.0 + 2 * 0.25
    assert probe.centre[-1] == pytest.approx(force * t * t / (2 * mass), rel=1e-12, abs=1e-14)
    phi = tau * t * t / (2 * inertia_z)
    x = probe.x[-1][0] - probe.centre[-1]
    angle = np.arctan2(x[1], x[0])
    print(f"{style}: rotation angle {angle:.12f} against {phi:.12f} (error {abs(angle / phi - 1):.1e})")
    assert angle == pytest.approx(phi, rel=1e-6)
    assert sim.fixes["1"].omega[0, 2] == pytest.approx(tau * t / inertia_z, rel=1e-12)


def test_rigid_nve_conserves_energy_better_than_rigid(tmp_path):
    """The same off-axis tumble at a coarse time step: the symplectic rigid/nve keeps the energy,
    Richardson iteration (rigid) drifts (LAMMPS's documentation says as much)."""
    errors = {}
    for style in ("rigid", "rigid/nve"):
        sim = spinning(tmp_path, np.array([0.6, 2.0, -0.7]), style, dt=0.01)
        sim.run(20_000)
        errors[style] = drift(sim.fixes["2"])[0]
    print(f"largest relative energy error over 2e4 steps at dt = 0.01: rigid {errors['rigid']:.2e}, "
          f"rigid/nve {errors['rigid/nve']:.2e}")
    assert errors["rigid/nve"] < errors["rigid"]


def test_body_across_a_periodic_boundary_moves_as_one_inside(tmp_path):
    """The same tumbling body whole in the middle of the box and split across the corner of a
    periodic box (image flags not set: the particles sit where they are wrapped): the same motion."""
    omega = np.array([0.6, 0.5, -0.7])
    inside = spinning(tmp_path, omega, "rigid/nve", box=5.0, boundary="p p p")
    inside.run(2000)
    corner = spinning(tmp_path, omega, "rigid/nve", centre=(5.0, 5.0, 5.0), box=5.0, boundary="p p p")
    p = corner.particles
    assert np.any(p.image[: p.nlocal] != 0) or np.any(np.abs(p.x[: p.nlocal]) < 4.9)
    corner.run(2000)
    a, b = inside.fixes["2"], corner.fixes["2"]
    # unwrapped, every particle is where the centred body's is, moved by (5, 5, 5)
    shift = np.array(b.x[-1]) - np.array(a.x[-1]) - 5.0
    assert np.abs(shift).max() < 1e-10
    assert b.energy_[-1] == pytest.approx(a.energy_[-1], rel=1e-12)
    xcm = corner.fixes["1"].xcm[0]
    assert np.all((xcm >= -5.0) & (xcm < 5.0))


def test_temperature_counts_six_degrees_of_freedom_per_body(tmp_path):
    """Two bodies of 6 and 4 particles and 3 free particles: N_dof = 3 * 13 - 3 - (3*6 - 6) - (3*4 - 6)."""
    x = np.vstack([OCTAHEDRON, OCTAHEDRON[:4] + 4.0, [[-4, -4, -4], [-4, 4, -4], [4, -4, 4]]])
    v = np.random.default_rng(3).normal(size=(13, 3))
    sim = build(tmp_path, x, v=v, lo=(-10,) * 3, hi=(10,) * 3, boundary="f f f", setup="""
        group a id 1:6
        group b id 7:10
        fix 1 all rigid group 2 a b
        run 0
        """)
    from pdps_core.api import observables
    assert observables.degrees_of_freedom(sim) == 3 * 13 - 3 - 12 - 6
    ke = 0.5 * float((sim.v ** 2).sum())
    assert observables.temperature(sim) == pytest.approx(2 * ke / 18, rel=1e-12)


def test_linear_body_has_five_degrees_of_freedom(tmp_path):
    x = np.array([[0.0, 0, 0], [1.0, 0, 0], [2.0, 0, 0]])
    sim = build(tmp_path, x, v=np.zeros((3, 3)), lo=(-10,) * 3, hi=(10,) * 3, setup="""
        fix 1 all rigid single
        run 0
        """)
    from pdps_core.api import observables
    assert observables.degrees_of_freedom(sim) == 9 - 3 - (9 - 5)


def test_particle_in_two_bodies_is_an_error_naming_both(tmp_path):
    x = OCTAHEDRON
    sim = build(tmp_path, x, lo=(-10,) * 3, hi=(10,) * 3, setup="""
        group left id 1:4
        group right id 3:6
        """)
    with pytest.raises(ScriptError, match=r"particle 3 is in two bodies: group left \(body 1\) and group "
                                          r"right \(body 2\)"):
        sim.command("fix 1 all rigid group 2 left right")
    sim.command("group first id 1:3\ngroup second id 3:6\nfix 1 first rigid single")
    with pytest.raises(ScriptError, match="particle 3 is in two bodies: body 1 of fix 2 and body 1 of fix 1"):
        sim.command("fix 2 second rigid/nve single")


@pytest.mark.parametrize("line, message", [
    ("fix 1 all rigid/nvt single temp 1 1 1 langevin 1 1 1 4", "keyword langevin of fix rigid/nvt: fix rigid/nvt "
     "thermostats with temp; langevin is for rigid and rigid/nve"),
    ("fix 1 all rigid/nve molecule temp 1 1 1", r"keyword temp of fix rigid/nve: only fix rigid/nvt and rigid/npt take "
     r"it \(LAMMPS's page: not rigid or rigid/nve\)"),
    ("fix 1 all rigid single tparam 3 1 3", "keyword tparam of fix rigid: only fix rigid/nvt and rigid/npt"),
    ("fix 1 all rigid single langevin 1 1 0 4", r"langevin: Tperiod must be > 0 \(got 0\)"),
    ("fix 1 all rigid single langevin 1 1 nan 4", r"langevin must be a finite number \(got nan\)"),
    ("fix 1 all rigid single langevin 1 1 1 0", r"langevin: the seed must be a positive integer \(got 0\)"),
    ("fix 1 all rigid/nve single langevin -1 1 1 4", r"langevin: Tstart and Tstop must be >= 0 \(got -1 1\)"),
    ("fix 1 all rigid single langevin 1 1 1", "langevin"),
    ("fix 1 all rigid single mol water", r"keyword mol of fix rigid: only fix rigid/small and its variants take it"),
    ("fix 1 all rigid/npt single temp 1 1 1 iso 1 1 1 mol water", r"keyword mol of fix rigid/npt: only fix rigid/small"),
    ("fix 1 all rigid single reinit maybe", "reinit must be one of"),
    ("fix 1 all rigid single force 2 off off off", r"force: body range 2 is not within 1..1"),
    ("fix 1 all rigid single torque 1*x on on on", "torque: body '1\\*x' is not a number or a range"),
    ("fix 1 all rigid single force * off maybe on", "must be one of"),
    ("fix 1 all rigid group 2 all", r"bodystyle group 2 needs 2 value\(s\) after 2 \(got 1\)"),
    ("fix 1 all rigid single all", "unknown keyword all"),
    ("fix 1 all rigid molecule", "bodystyle molecule needs molecule ids"),
    ("fix 1 all rigid wobbly", "must be one of"),
])
def test_bad_input_is_one_line(tmp_path, line, message):
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3)
    with pytest.raises(ScriptError, match=message):
        sim.command(line)


def test_a_lone_particle_is_no_body(tmp_path):
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3, setup="group one id 2\ngroup two id 3:6")
    with pytest.raises(ScriptError, match="body 1 has 1 particle"):
        sim.command("fix 1 all rigid group 2 one two")


def test_force_and_torque_flags_by_body_range(tmp_path):
    """Three bodies pushed along x and twisted about z; force 2* off off off holds bodies 2 and 3 in
    place, torque *1 off off off stops body 1 turning."""
    flat = np.array([[1.0, 0, 0], [-1.0, 0, 0], [0, 0.5, 0], [0, -0.5, 0]])
    x = np.vstack([flat + [0, -5, 0], flat, flat + [0, 5, 0]])
    sim = build(tmp_path, x, lo=(-10,) * 3, hi=(10,) * 3, boundary="f f f", setup="""
        group b1 id 1:4
        group b2 id 5:8
        group b3 id 9:12
        fix 1 all rigid/nve group 3 b1 b2 b3 force 2* off off off torque *1 off off off
        fix 2 b1 test/torque 0 0 0.3 0.2 0 0
        fix 3 b2 test/torque 0 0 0.3 0.2 0 0
        fix 4 b3 test/torque 0 0 0.3 0.2 0 0
        run 500
        """)
    fix = sim.fixes["1"]
    assert fix.vcm[0, 0] > 0 and np.all(fix.vcm[1:] == 0.0)
    assert np.all(fix.omega[0] == 0.0) and np.all(fix.omega[1:, 2] > 0)


def test_rigid_nvt_conserves_its_extended_energy_and_heats_toward_the_target(tmp_path):
    """Four free tumbling bodies (periodic box) under rigid/nvt (temp 2 2 0.5), heated from T = 0.03
    over 20 time units: their kinetic energy plus the chains' energy (f_ID less the bodies'
    temperature, LAMMPS's scalar) stays constant to second order in dt."""
    from pdps_core.api import observables
    from pdps_fix_rigid.rigid import FixRigid
    errors = {}
    for dt in (0.002, 0.001):
        rng = np.random.default_rng(7)
        x = np.vstack([OCTAHEDRON + centre for centre in ([-5, -5, 0], [5, -5, 0], [-5, 5, 0], [5, 5, 0])])
        sim = build(tmp_path, x, v=0.1 * rng.normal(size=(24, 3)), lo=(-10,) * 3, hi=(10,) * 3, setup=f"""
            timestep {dt}
            group b1 id 1:6
            group b2 id 7:12
            group b3 id 13:18
            group b4 id 19:24
            fix 1 all rigid/nvt group 4 b1 b2 b3 b4 temp 2.0 2.0 0.5
            """)
        fix = sim.fixes["1"]

        def extended():
            return observables.kinetic_energy(sim) + fix.scalar(sim) - FixRigid.scalar(fix, sim)

        sim.run(0)
        start, cold = extended(), FixRigid.scalar(fix, sim)
        sim.run(round(20 / dt))
        errors[dt] = abs(extended() / start - 1)
        hot = FixRigid.scalar(fix, sim)
        print(f"rigid/nvt at dt = {dt}: extended energy {errors[dt]:.1e} from its start; bodies' T from "
              f"{cold:.3f} to {hot:.3f}")
        assert cold < 0.1 and hot > 0.5
    assert errors[0.001] < 1e-4
    assert 3.0 < errors[0.002] / errors[0.001] < 5.0


def test_rigid_nvt_needs_temp(tmp_path):
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3)
    with pytest.raises(ScriptError, match="fix rigid/nvt needs temp TSTART TSTOP TDAMP"):
        sim.command("fix 1 all rigid/nvt single")
    with pytest.raises(ScriptError, match="tparam: TCHAIN and TITER must be from 1 to 1000 and TORDER 3 or 5"):
        sim.command("fix 1 all rigid/nvt single temp 1 1 1 tparam 3 1 4")
    with pytest.raises(ScriptError, match=r"keyword iso of fix rigid/nvt: only fix rigid/nph and rigid/npt take it "
                                          r"\(as LAMMPS\)"):
        sim.command("fix 1 all rigid/nvt single temp 1 1 1 iso 1 1 1")


@pytest.mark.parametrize("reinit, expected", [("yes", 0.0), ("no", None)])
def test_reinit(tmp_path, reinit, expected):
    """Velocities changed between runs: reinit yes sets the bodies up from them again, reinit no
    goes on with the bodies (and sets the particles' velocities back from them)."""
    v = np.cross([0.3, 0.2, 0.5], OCTAHEDRON) + [0.1, 0, 0]
    sim = build(tmp_path, OCTAHEDRON, v=v, lo=(-10,) * 3, hi=(10,) * 3, boundary="f f f",
                setup=f"fix 1 all rigid/nve single reinit {reinit}\nrun 100")
    before = 0.5 * float((sim.v ** 2).sum())
    sim.command("velocity all set 0 0 0\nrun 0")
    after = 0.5 * float((sim.v ** 2).sum())
    assert after == pytest.approx(before if expected is None else expected, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("text, message", [
    ("", "no count of bodies"),
    ("# only a comment\n1 2\n", ":2: the first line is the number of bodies that follow \\(got 1 2\\)"),
    ("2\n1 " + "1 " * 18 + "0\n", "2 bodies announced, 1 lines follow"),
    ("1\n1 1 2 3\n", ":2: 4 values; a line is ID masstotal"),
    ("1\n2 " + "1 " * 18 + "0\n", ":2: no body 2 in fix 1 \\(its bodies: 1..1\\)"),
    ("1\n1 0 " + "1 " * 17 + "0\n", ":2: masstotal must be > 0"),
    ("1\n1 nan " + "1 " * 17 + "0\n", ":2: masstotal must be > 0 and every value finite"),
    ("1\n1 x " + "1 " * 17 + "0\n", ":2: not numbers"),
    ("1\n1 1 0 0 0 1 1 1 0 0 0 0 0 0 0 0 0 0 -9223372036854775809 0\n", ":2: image flags 0 -9223372036854775809 0 beyond"),
    ("1\n1 1 0 0 0 1 1 1 0 0 0 0 0 0 0 0 0 \xf4\x90 0 0\n", "not a text file"),
    ("1\n1 1 0 0 0 1 1 -1 0 0 0 0 0 0 0 0 0 0 0 0\n", ":2: the inertia tensor of body 1 has a negative principal moment"),
])
def test_bad_infile_is_one_line(tmp_path, text, message):
    (tmp_path / "bodies.txt").write_bytes(text.encode("latin-1"))
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3)
    with pytest.raises(ScriptError, match=message):
        sim.command(f"fix 1 all rigid single infile {tmp_path / 'bodies.txt'}")
    with pytest.raises(ScriptError, match="cannot read it"):
        sim.command(f"fix 1 all rigid single infile {tmp_path / 'missing.txt'}")


def test_infile_mass_slows_the_body_under_a_force(tmp_path):
    """The file's mass, not the particles' (6), is what a force accelerates: twice the mass, half the
    velocity gain; the body's other values as the particles give them."""
    (tmp_path / "bodies.txt").write_text("1\n1 12 0 0 0 " + " ".join(map(str, MOMENTS)) + " 0 0 0 0 0 0 0 0 0 0 0 0\n")
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3, boundary="f f f", setup=f"""
        fix 2 all test/torque 0 0 0 0.6 0 0
        fix 1 all rigid single infile {tmp_path / 'bodies.txt'}
        run 1000
        """)
    assert sim.fixes["1"].vcm[0] == pytest.approx([0.6 / 12 * 1000 * 0.005, 0, 0], rel=1e-12, abs=1e-15)


def test_a_body_wider_than_half_the_box_is_warned_about(tmp_path):
    """Two particles near opposite faces with image flags 0 make a body 19 wide in a box of 20 (as
    LAMMPS reads it too): a warning asks whether the image flags are right; a whole body gets none."""
    sim = build(tmp_path, [[-9.5, 0, 0], [9.5, 0, 0], [0, 0, 0], [0, 1, 0]], lo=(-10,) * 3, hi=(10,) * 3,
                setup="group pair id 1 2\ngroup near id 3 4\nfix 1 all rigid group 2 pair near\nrun 0")
    assert sim.warnings == ["fix 1: body 1 is 19 wide along x, more than half the periodic box (20): are its "
                            "particles' image flags those of one whole body?"]


def test_a_body_emptied_between_runs_is_one_line(tmp_path):
    x = np.vstack([OCTAHEDRON, OCTAHEDRON[:3] + 4.0])
    sim = build(tmp_path, x, lo=(-10,) * 3, hi=(10,) * 3, setup="""
        group a id 1:6
        group b id 7:9
        fix 1 all rigid group 2 a b
        run 10
        group gone id 7 8
        delete_atoms group gone
        """)
    with pytest.raises(ScriptError, match=r"fix 1: body 2 has 1 particle\(s\) left; a rigid body needs at least 2"):
        sim.command("run 10")


def test_custom_bodystyle_takes_body_ids_from_a_property_or_a_variable(tmp_path):
    """Two tetrahedra of the octahedron's corners split by a per-particle property (3 and 7: bodies 1 and
    5 by LAMMPS's value - smallest + 1) or by an atom-style variable (truncated: 1.9 and 2.2 -> 1 and 2):
    the same two bodies as bodystyle group, with the same motion under a force; only the group's particles."""
    setup = """
        group left id 1 3 5
        group right id 2 4 6
        velocity all set 0.1 -0.2 0.3
        velocity left set -0.3 0.1 0.2
        fix push all addforce 0.2 0.0 -0.1
        """
    runs = {}
    for style in ("group 2 left right", "custom i_flag", "custom v_b"):
        sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3, setup=setup + """
            fix p all property/atom flag scalar no no no 7
            set group left property/atom flag 3
            variable b atom 1.9+0.3*(id%2==0)
            """)
        sim.command(f"fix 1 all rigid {style}\nthermo_style custom step f_1\nrun 200")
        fix = sim.fixes["1"]
        runs[style] = (fix.xcm.copy(), fix.vcm.copy(), fix.angmom.copy())
        if style == "custom i_flag":
            assert list(fix.body_ids) == [1, 5]
        if style == "custom v_b":
            assert list(fix.body_ids) == [1, 2]
    for style in ("custom i_flag", "custom v_b"):
        for ours, theirs in zip(runs[style], runs["group 2 left right"]):
            assert ours == pytest.approx(theirs, rel=1e-13, abs=1e-14)


@pytest.mark.parametrize("line, message", [
    ("fix 1 all rigid custom", r"bodystyle custom takes 1 value\(s\): word \(got nothing\)"),
    ("fix 1 all rigid custom flag", "bodystyle custom needs one i_NAME"),
    ("fix 1 all rigid custom v_a v_b", "unknown keyword v_b"),
    ("fix 1 all rigid custom v_nope", "bodystyle custom v_nope: variable nope is not defined"),
    ("fix 1 all rigid custom i_nope", "bodystyle custom i_nope: no per-particle property nope"),
    ("fix 1 all rigid custom i_half", "bodystyle custom i_half: property half holds values that are not integers"),
    ("fix 1 all rigid custom v_huge", r"bodystyle custom v_huge: values must be integers within \+-2147483647"),
])
def test_bad_custom_bodystyle_is_one_line(tmp_path, line, message):
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3,
                setup="fix p all property/atom half scalar no no no 0.5\nvariable huge atom 1e12*id")
    with pytest.raises(ScriptError, match=message):
        sim.command(line)


def test_the_gravity_keyword_pulls_each_body_by_its_mass(tmp_path):
    """gravity FIX_ID adds M g to each body's force (LAMMPS's): with an infile's mass of 12 for particles
    of 6, the body still falls with g (fix gravity on its particles would give it g / 2), and f_ID's
    force column reads -M g from the set-up on (LAMMPS's numbers: the recorder's scene infile gravity)."""
    (tmp_path / "bodies.txt").write_text("1\n1 12 0 0 0 " + " ".join(map(str, MOMENTS)) + " 0 0 0 0 0 0 0 0 0 0 0 0\n")
    runs = {}
    for keyword in ("gravity down", ""):
        group = "none" if keyword else "all"
        sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3, boundary="f f f", setup=f"""
            group none empty
            fix down {group} gravity 0.5 vector 0 0 -1
            fix 1 all rigid single infile {tmp_path / 'bodies.txt'} {keyword}
            run 0
            """)
        assert sim.fixes["1"].fcm[0] == pytest.approx([0, 0, -0.5 * (12 if keyword else 6)], abs=1e-14)
        sim.command("run 1000")
        runs[keyword] = (sim.fixes["1"].vcm[0, 2], sim.warnings)
    assert runs["gravity down"][0] == pytest.approx(-0.5 * 1000 * 0.005, rel=1e-12)
    assert runs[""][0] == pytest.approx(-0.5 * 0.5 * 1000 * 0.005, rel=1e-12)
    assert runs["gravity down"][1] == []
    assert runs[""][1] == ["fix 1: gravity may not be correctly applied to rigid bodies if they consist of overlapped "
                           "particles (the infile's masses; use the gravity keyword, as LAMMPS says)"] * 2


@pytest.mark.parametrize("setup, message", [
    ("fix 1 all rigid single gravity nope", "fix 1: cannot find fix gravity ID nope"),
    ("fix f all addforce 1 0 0\nfix 1 all rigid single gravity f", "fix 1: gravity fix ID f is not a gravity fix style "
     r"\(addforce\)"),
])
def test_a_gravity_keyword_without_a_gravity_fix_is_one_line(tmp_path, setup, message):
    sim = build(tmp_path, OCTAHEDRON, lo=(-10,) * 3, hi=(10,) * 3, setup=setup)
    with pytest.raises(ScriptError, match=message):
        sim.command("run 0")


# Three bodies of three particles with random velocities; the infile names body 2 only (mass 3,
# centre, inertia, vcm 0.1 0.2 0.3, angmom 0 0 0.5). LAMMPS 22 Jul 2025 on this script, thermo
# step temp ke: without the infile and with it. Bodies 1 and 3 move as without the file; pdps
# started them at rest (ke 0.0297 instead of 1.877).
RIGID_INFILE = """
units lj
atom_style atomic
region box block -10 10 -10 10 -10 10
create_box 1 box
mass 1 1.0
create_atoms 1 single 0 0 0
create_atoms 1 single 1 0 0
create_atoms 1 single 0 1 0
create_atoms 1 single 5 5 5
create_atoms 1 single 6 5 5
create_atoms 1 single 5 6.5 5
create_atoms 1 single -5 -5 -5
create_atoms 1 single -4 -5 -5
create_atoms 1 single -5 -5 -3.8
group b1 id 1:3
group b2 id 4:6
group b3 id 7:9
velocity all create 2.0 4928459
pair_style lj/cut 1.0
pair_coeff 1 1 0.0 1.0
fix 1 all rigid group 3 b1 b2 b3 {infile}
thermo_style custom step temp ke
thermo 50
run 100
"""
RIGID_INFILE_BODIES = ("1\n2 3.0 5.3333333333333333 5.5 5.0 1.5 0.666666666666667 2.1666666666666667 0.0 0.0 0.0 "
                       "0.1 0.2 0.3 0.0 0.0 0.5 0 0 0\n")
RIGID_INFILE_LAMMPS = {
    "": [[0, 2.7672877, 2.3060731], [50, 2.7672887, 2.3060739], [100, 2.7672902, 2.3060752]],
    "infile bodies.in": [[0, 2.2525458, 1.8771215], [50, 2.2525468, 1.8771223], [100, 2.2525483, 1.8771236]],
}


@pytest.mark.parametrize("infile", sorted(RIGID_INFILE_LAMMPS))
def test_bodies_an_infile_leaves_out_take_their_particles_motion_as_lammps(pdps_cli, tmp_path, infile):
    from pdps_core.testing import thermo_rows
    (tmp_path / "bodies.in").write_text(RIGID_INFILE_BODIES)
    result = pdps_cli(RIGID_INFILE.format(infile=infile), name="in.rigid")
    assert result.returncode == 0, result.stderr
    np.testing.assert_allclose(thermo_rows(result.stdout), RIGID_INFILE_LAMMPS[infile], rtol=5e-8)
