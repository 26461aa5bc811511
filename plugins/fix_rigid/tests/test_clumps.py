"""Granular clumps: 24 rigid bodies of 2 to 5 overlapping spheres (their own 2/5 m R^2 in the
inertia, their contact torques in the body's) fall under gravity onto a wall/gran floor through
gran/hooke/history contacts, contacts within a clump excluded. They settle without interpenetrating,
and 2 ranks run what 1 runs (to round-off through the first impacts; the settled bed alike after)."""

import math

import numpy as np
import pytest

from pdps_core.testing import run_ranks, thermo_rows


def clumps(path, seed=5, cells=(4, 2, 3)):
    """Clumps on a lattice 2.5 apart, each a random chain of spheres of one diameter d (0.8-1.0),
    0.55 d from one to the next, random particle velocities; returns each clump's first and last id."""
    rng = np.random.default_rng(seed)
    rows, bodies, tag = [], [], 0
    for k, cell in enumerate(np.mgrid[0:cells[0], 0:cells[1], 0:cells[2]].reshape(3, -1).T):
        centre = cell * 2.5 + np.array([1.25, 1.25, 2.0])
        d = rng.uniform(0.8, 1.0)
        points = [np.zeros(3)]
        while len(points) < 2 + k % 4:
            step = rng.normal(size=3)
            candidate = points[rng.integers(len(points))] + 0.55 * d * step / np.linalg.norm(step)
            if all(np.linalg.norm(candidate - p) > 0.45 * d for p in points):
                points.append(candidate)
        points = np.array(points)
        first = tag + 1
        for p in points - points.mean(axis=0) + centre:
            tag += 1
            rows.append((tag, d, p, rng.normal(scale=0.3, size=3)))
        bodies.append((first, tag))
    lines = ["clumps", "", f"{len(rows)} atoms", "1 atom types", "", f"0 {cells[0] * 2.5} xlo xhi",
             f"0 {cells[1] * 2.5} ylo yhi", "0 12 zlo zhi", "", "Atoms # sphere", ""]
    lines += [f"{t} 1 {float(d)!r} 1.9098593171027440 {float(p[0])!r} {float(p[1])!r} {float(p[2])!r}"
              for t, d, p, _ in rows]
    lines += ["", "Velocities", ""]
    lines += [f"{t} {float(u[0])!r} {float(u[1])!r} {float(u[2])!r} 0 0 0" for t, _, _, u in rows]
    path.write_text("\n".join(lines) + "\n")
    return bodies


def script(bodies, steps):
    groups = "\n".join(f"group c{k} id {a}:{b}\nneigh_modify exclude group c{k} c{k}"
                       for k, (a, b) in enumerate(bodies, 1))
    names = " ".join(f"c{k}" for k in range(1, len(bodies) + 1))
    return f"""units lj
atom_style sphere
boundary p p f
comm_modify vel yes
read_data clumps.data
pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
{groups}
timestep 0.0002
fix 1 all rigid/nve group {len(bodies)} {names}
fix 2 all gravity 10.0 vector 0 0 -1
fix 3 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 NULL
thermo_style custom step f_1 f_1[1][3] f_1[24][1]
thermo_modify format float %.15g
thermo 1000
run {steps}
write_data settled.data
"""


def settled(path):
    """(id, diameter, position) of the particles write_data wrote."""
    lines = path.read_text().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("Atoms")) + 2
    rows = []
    for line in lines[start:]:
        if not line.strip():
            break
        words = line.split()
        rows.append((int(words[0]), float(words[2]), [float(w) for w in words[4:7]]))
    rows.sort()
    return np.array([r[1] for r in rows]), np.array([r[2] for r in rows])


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    done = {}
    for ranks in (1, 2):
        folder = tmp_path_factory.mktemp(f"clumps{ranks}")
        bodies = clumps(folder / "clumps.data")
        result = run_ranks(script(bodies, 15000), ranks, folder)
        done[ranks] = (bodies, np.array(thermo_rows(result.stdout)), *settled(folder / "settled.data"),
                       settled(folder / "clumps.data")[1])
    return done


@pytest.mark.parametrize("ranks", [1, 2])
def test_clumps_settle_without_interpenetrating(runs, ranks):
    bodies, thermo, diameter, x, start = runs[ranks]
    body = np.zeros(len(x), dtype=int)
    for k, (a, b) in enumerate(bodies):
        body[a - 1:b] = k
    gap = np.linalg.norm(x[:, None] - x[None], axis=2) - 0.5 * (diameter[:, None] + diameter[None])
    other = body[:, None] != body[None]
    overlap = float(-(gap[other].min()) / diameter.min())
    floor = float(-(x[:, 2] - 0.5 * diameter).min() / diameter.min())
    peak, last = thermo[:, 1].max(), thermo[-1, 1]
    print(f"{ranks} rank(s): deepest overlap between clumps {overlap:.3%} of a diameter, into the floor "
          f"{floor:.3%}; bodies' temperature from a peak of {peak:.3g} to {last:.3g}")
    assert overlap < 0.02 and floor < 0.02
    assert last < 0.1 * peak
    # each clump is still the shape it was made (write_data wraps positions: take the nearest image)
    periods = np.array([10.0, 5.0])
    for a, b in bodies:
        now = x[a - 1:b, None] - x[None, a - 1:b]
        now[..., :2] -= np.round(now[..., :2] / periods) * periods
        made = start[a - 1:b, None] - start[None, a - 1:b]
        assert np.linalg.norm(now, axis=2) == pytest.approx(np.linalg.norm(made, axis=2), abs=1e-9)


def test_two_ranks_run_what_one_runs(runs):
    one, two = runs[1][1], runs[2][1]
    assert one.shape == two.shape == (16, 4)
    # the same to round-off through the first impacts (steps 0-5000), after which collisions
    # amplify the order in which forces were summed
    assert two[:6] == pytest.approx(one[:6], rel=1e-10)
    # and settle into the same bed: its mean height alike within 5 %
    heights = [float(runs[ranks][3][:, 2].mean()) for ranks in (1, 2)]
    print(f"settled bed's mean height: {heights[0]:.4f} (1 rank), {heights[1]:.4f} (2 ranks)")
    assert heights[1] == pytest.approx(heights[0], rel=0.05)


# ---- contacts between clumps take the bodies' masses -------------------------------------------------
HEAD_ON = """units lj
atom_style sphere
boundary f p p
comm_modify vel yes
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 single {a1} 5 5
create_atoms 1 single {a2} 5 5
set atom * diameter 1.0 density 1.9098593171027440
group a id 1:2
velocity a set -0.5 0 0
neigh_modify exclude group a a
{second}
timestep 0.00001
fix 1 all rigid/nve group {nbody} {groups}
{contact}
thermo_style custom step f_1
run {steps}
"""
KN, GAMMA_N = 2000.0, 19.1


def restitution(m_eff, body_mass):
    """A linear spring kn with dashpot m_eff gamma_n on a relative coordinate of inertia body_mass:
    body_mass d'' = -kn d - m_eff gamma_n d', which ends (d = 0) after half a damped period with
    the rebound speed e times the impact speed, e = exp(-zeta pi / omega_d)."""
    zeta = 0.5 * GAMMA_N * m_eff / body_mass
    omega_d = math.sqrt(KN / body_mass - zeta * zeta)
    return math.exp(-zeta * math.pi / omega_d)


@pytest.mark.parametrize("target", ["clump", "wall", "dem wall"])
def test_a_clump_bounces_with_the_restitution_of_its_body_mass(make_sim, target):
    """Dimers of unit-mass spheres (body mass 2) meet head-on along their axis through gran/hooke
    (a second dimer coming the other way: effective mass 2 x 2 / 4 = 1, inertia of the relative
    motion 1), wall/gran hooke (effective mass 2) or wall/dem's restitution form (e = 0.5 asked for
    the body's mass; 0.61 for a particle's): the rebound speed is e times the impact speed,
    e from the body masses (LAMMPS's mass_rigid), 0.503 and 0.370, where the particles' masses would
    give 0.714 and 0.619. LAMMPS 22 Jul 2025 prints the same rebound speeds to all 15 digits
    (0.251622820266156 and 0.184801197332536); the analytic e holds to the step on which the contact ends: the dashpot stops within
    one step, gamma_n dt / (2 e) = 2.6e-4 of the rebound at most."""
    if target == "clump":
        script = HEAD_ON.format(a1=5.25, a2=5.75, nbody=2, groups="a b", steps=20000, second=(
            "create_atoms 1 single 4.2 5 5\ncreate_atoms 1 single 3.7 5 5\n"
            "set atom 3*4 diameter 1.0 density 1.9098593171027440\n"
            "group b id 3:4\nvelocity b set 0.5 0 0\nneigh_modify exclude group b b"),
            contact=f"pair_style gran/hooke {KN} NULL {GAMMA_N} NULL 0.5 0\npair_coeff * *")
        expected, particles = restitution(1.0, 1.0), restitution(0.5, 1.0)
    elif target == "wall":
        script = HEAD_ON.format(a1=0.55, a2=1.05, nbody=1, groups="a", steps=25000, second="",
                                contact=f"fix 2 all wall/gran hooke {KN} NULL {GAMMA_N} NULL 0.5 0 xplane 0.0 NULL")
        expected, particles = restitution(2.0, 2.0), restitution(1.0, 2.0)
    else:
        # wall/dem's restitution form: C_n = 2 zeta sqrt(kn m*) for e = 0.5, m* the body's mass 2
        script = HEAD_ON.format(a1=0.55, a2=1.05, nbody=1, groups="a", steps=25000, second="",
                                contact=f"region inside block 0 10 0 10 0 10\nfix 2 all wall/dem lsd region inside 0.5 {KN} 0.0")
        zeta = -math.log(0.5) / math.sqrt(math.pi ** 2 + math.log(0.5) ** 2)
        damping = 2.0 * zeta * math.sqrt(KN * 1.0)          # what a particle's mass of 1 would give
        expected = 0.5
        omega = math.sqrt(KN / 2.0 - (damping / 4.0) ** 2)
        particles = math.exp(-damping / 4.0 * math.pi / omega)
    sim = make_sim()
    sim.command(script)
    rebound = float(sim.fixes["1"].vcm[0, 0]) / 0.5
    print(f"{target}: e = {rebound:.6f}, analytic for the body mass {expected:.6f} "
          f"({rebound / expected - 1:.1e}), for the particles' mass {particles:.6f}")
    assert rebound == pytest.approx(expected, rel=3e-4)
