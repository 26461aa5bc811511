"""What DEM accuracy costs: restitution, overlap and contact-time error against time step and wall
time for pair dem/lsd and dem/hertz, and what a softer Young's modulus buys and costs (dem/hertz).

Units: lj, sphere diameter d = 1, mass m = 1 (density 6/pi), gravity g = 1 where there is any.
Materials: dem/lsd kn = 2e5 (LAMMPS's gran_box), dem/hertz Y = 1e7, nu = 0.3; friction 0.5.

1. Head-on collisions, sphere on sphere and sphere on a floor (fix wall/dem lsd for dem/lsd, fix
   wall/mesh model hertz for dem/hertz: wall/dem has no Hertz law), at relative normal speed 1 and
   requested restitution e = 0.5 and 0.9, with dt = t_c/5 ... t_c/100. t_c is the contact time of
   the continuous law: closed form for lsd, the damped Hertz equation integrated by RK4 to
   convergence for hertz. Each collision runs at 8 phases (where in a step the spheres first touch);
   measured: restitution (post/pre normal relative speed), max overlap sampled at the steps over the
   continuous law's max overlap, contact time (overlap zero crossings, interpolated between steps)
   over t_c. Warnings: fix check/timestep/gran 0.2 (Rayleigh) 0.1 (Hertz or contact time), and what
   the wall fixes say themselves.
2. Cost: 972 spheres settling in a walled box, taken at one moment of their pour and run for
   COST_STEPS steps at each dt = t_c/N (t_c at the pour's largest impact speed): wall seconds per
   unit of simulated time, per step, neighbor list builds; the fastest of COST_REPEATS runs.
3. The softer-modulus trick (dem/hertz): Y / 1, 10, 100, 1000 (and 10000, past where it holds) with
   dt = t_c/20 of each modulus; 2016 spheres poured into a 14 d x 14 d walled box (wall/mesh, same
   material) and settled until the kinetic energy is 1e-6 of its peak or MAX_SETTLE_TIME has passed.
   Measured: packing fraction of the central sub-volume SOFT_SUB_LO..SOFT_SUB_HI (3 d from the side
   walls, 2 d above the floor, about 2 d under the surface; partial spheres counted on a 0.025 d
   grid), overlaps, coordination, a head-on collision at the pour's largest impact speed, wall
   seconds per unit of simulated time. The cheap soft beds are poured again with other seeds to show
   the spread between pours.

    .venv/bin/pip install -e '.[bench]'           # matplotlib, for the plot
    .venv/bin/python benchmarks/accuracy_dem.py   # 8-15 minutes on one core, by the load

Writes benchmarks/results/accuracy_dem.json and docs/accuracy-dem.png; ``--parts`` runs some parts
and keeps the others from the results file, ``--plot-only`` redraws the plot.
"""

import argparse
import json
import math
import os
import pathlib
import re
import tempfile
import time

import numpy as np

from pdps_core.api import Fix, Simulation, registry
from pdps_granular_contact import contact_models

HERE = pathlib.Path(__file__).parent
RESULTS = HERE / "results" / "accuracy_dem.json"
PLOT = HERE.parent / "docs" / "accuracy-dem.png"

DIAMETER, RADIUS = 1.0, 0.5
DENSITY = 6.0 / math.pi                   # mass 1
MASS = DENSITY * math.pi / 6.0 * DIAMETER ** 3
GRAVITY = 1.0
KN = 2.0e5                                # dem/lsd
YOUNGS, POISSON = 1.0e7, 0.3              # dem/hertz
MU = 0.5
BED_RESTITUTION = 0.5

IMPACT_SPEED = 1.0
STEPS_PER_CONTACT = (5, 10, 20, 50, 100)
RESTITUTIONS = (0.5, 0.9)
PHASES = 8
CHECK = "fix ts all check/timestep/gran {every} 0.2 0.1"

COST_LENGTH, COST_LAYERS, COST_MOMENT = 11.0, 12, 3.0     # 972 spheres, taken 3 time units into the pour
COST_STEPS = 3000
COST_REPEATS = 3

SOFT_LENGTH, SOFT_LAYERS = 14.0, 14                       # 2016 spheres
SOFT_SUB_LO, SOFT_SUB_HI = (3.0, 3.0, 2.0), (11.0, 11.0, 7.0)
SOFTENING = (1, 10, 100, 1000, 10000)
SOFT_STEPS_PER_CONTACT = 20
FIRST_SEED = 99
REPEAT_SEEDS = (7, 2024)                  # the cheap soft beds poured again: the spread between pours
REPEATED = (100, 1000, 10000)
SETTLE_KE = 1.0e-6
MAX_SETTLE_TIME = 40.0                    # time units (sqrt(d/g)): the step budget of a settling bed
SETTLE_CHUNK = 0.5                        # time units between kinetic-energy checks


# ---- reference solutions ------------------------------------------------------------------------
def hertz_star(target, youngs):
    """(E*, R*, m*) of two equal spheres, or of a sphere on a wall of the same material."""
    e_star = youngs / (2.0 * (1.0 - POISSON ** 2))
    if target == "sphere":
        return e_star, RADIUS / 2.0, MASS / 2.0
    return e_star, RADIUS, MASS


def lsd_reference(target, e, speed):
    """Closed-form damped oscillator: contact time, restitution e, max overlap."""
    m_star = MASS / 2.0 if target == "sphere" else MASS
    cn = contact_models.lsd_damping(KN, m_star, e)
    gamma = cn / (2.0 * m_star)
    omega = math.sqrt(KN / m_star - gamma * gamma)
    peak = math.atan2(omega, gamma) / omega
    overlap = speed / omega * math.exp(-gamma * peak) * math.sin(omega * peak)
    return {"contact_time": math.pi / omega, "restitution": e, "max_overlap": overlap}


_HERTZ_UNIT = {}


def hertz_unit_solution(beta, dtau=2.0e-4):
    """The damped Hertz contact in units of the impact speed v and T = (m*^2 / (k^2 v))^(1/5),
    k = 4/3 E* sqrt(R*): s'' = -s^(3/2) - sqrt(5) |beta| s^(1/4) s', s(0) = 0, s'(0) = 1, by RK4.
    Returns (duration, restitution, max overlap) in those units."""
    if beta in _HERTZ_UNIT:
        return _HERTZ_UNIT[beta]
    damping = math.sqrt(5.0) * abs(beta)

    def rate(s, u):
        s = max(s, 0.0)
        return u, -s ** 1.5 - damping * s ** 0.25 * u

    s, u, t, deepest = 0.0, 1.0, 0.0, 0.0
    while True:
        k1 = rate(s, u)
        k2 = rate(s + 0.5 * dtau * k1[0], u + 0.5 * dtau * k1[1])
        k3 = rate(s + 0.5 * dtau * k2[0], u + 0.5 * dtau * k2[1])
        k4 = rate(s + dtau * k3[0], u + dtau * k3[1])
        s_new = s + dtau / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        u_new = u + dtau / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        if s_new <= 0.0:
            share = s / (s - s_new)
            _HERTZ_UNIT[beta] = (t + share * dtau, -(u + share * (u_new - u)), deepest)
            return _HERTZ_UNIT[beta]
        s, u, t = s_new, u_new, t + dtau
        deepest = max(deepest, s)


def hertz_reference(target, e, speed, youngs=YOUNGS):
    e_star, r_star, m_star = hertz_star(target, youngs)
    duration, restitution, deepest = hertz_unit_solution(contact_models.restitution_beta(e))
    k = 4.0 / 3.0 * e_star * math.sqrt(r_star)
    unit_time = (m_star ** 2 / (k * k * speed)) ** 0.2
    return {"contact_time": duration * unit_time, "restitution": restitution,
            "max_overlap": deepest * speed * unit_time,
            "elastic_hertz_time": contact_models.hertz_contact_time(e_star, r_star, m_star, speed)}


def reference(model, target, e, speed, youngs=YOUNGS):
    if model == "dem/lsd":
        return lsd_reference(target, e, speed)
    return hertz_reference(target, e, speed, youngs)


# ---- scenes -------------------------------------------------------------------------------------
class Trace(Fix):
    """Positions and velocities of all particles, in tag order, at setup and after every step."""
    name = "bench/dem/trace"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.x, self.v = [], []

    def setup(self, sim):
        self.end_of_step(sim)

    def end_of_step(self, sim):
        order = np.argsort(sim.tag)
        self.x.append(sim.x[order].copy())
        self.v.append(sim.v[order].copy())


def pair_commands(model, e, youngs=YOUNGS):
    if model == "dem/lsd":
        return f"pair_style dem/lsd {e} 1.0\npair_coeff * * kn {KN} e {e} mu {MU}"
    return f"pair_style dem/hertz\npair_coeff * * {youngs} {POISSON} {e} {MU}"


def write_stl(path, quads):
    """An ASCII STL of the quads (each 4 corners), two triangles each."""
    lines = ["solid wall"]
    for a, b, c, d in quads:
        for triangle in ((a, b, c), (a, c, d)):
            lines += ["facet normal 0 0 0", "outer loop"]
            lines += [f"vertex {p[0]!r} {p[1]!r} {p[2]!r}" for p in triangle]
            lines += ["endloop", "endfacet"]
    lines.append("endsolid wall")
    pathlib.Path(path).write_text("\n".join(lines) + "\n")


def open_box_quads(length, height):
    def corner(x, y, z):
        return (x * length, y * length, z * height)
    return [[corner(0, 0, 0), corner(1, 0, 0), corner(1, 1, 0), corner(0, 1, 0)],
            [corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1)],
            [corner(0, 1, 0), corner(1, 1, 0), corner(1, 1, 1), corner(0, 1, 1)],
            [corner(0, 0, 0), corner(0, 1, 0), corner(0, 1, 1), corner(0, 0, 1)],
            [corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)]]


def wall_commands(model, e, region_block, stl, youngs=YOUNGS):
    """A wall/dem block container for dem/lsd, a wall/mesh of the same material for dem/hertz."""
    if model == "dem/lsd":
        return f"region walls block {region_block}\nfix w all wall/dem lsd region walls {e} {KN} {MU}"
    return f"fix w all wall/mesh file {stl} model hertz {youngs} {POISSON} {e} {MU}"


def collision(model, target, e, steps_per_contact, phase, workdir, speed=IMPACT_SPEED, youngs=YOUNGS):
    """One head-on collision; the spheres first touch ``phase`` of a step after the start."""
    ref = reference(model, target, e, speed, youngs)
    dt = ref["contact_time"] / steps_per_contact
    gap = speed * dt * phase
    sim = Simulation(screen=False, log=None)
    lines = ["units lj", "particle_style sphere", "boundary f f f"]
    if target == "sphere":
        lines += ["region box block 0 20 0 10 0 10", "create_box 1 box"]
        lines += [f"create_particle 1 single {10.0 + s * 0.5 * (DIAMETER + gap)!r} 5 5 "
                  f"diameter {DIAMETER} density {DENSITY!r}" for s in (-1, 1)]
    else:
        stl = workdir / "floor.stl"
        write_stl(stl, [[(-5, -5, 0), (15, -5, 0), (15, 15, 0), (-5, 15, 0)]])
        lines += ["region box block 0 10 0 10 0 10", "create_box 1 box",
                  f"create_particle 1 single 5 5 {RADIUS + gap!r} diameter {DIAMETER} density {DENSITY!r}",
                  wall_commands(model, e, "0 10 0 10 0 10", stl, youngs)]
    lines += [pair_commands(model, e, youngs), f"timestep {dt!r}", "fix 1 all nve/sphere",
              CHECK.format(every=10 ** 9), "fix trace all bench/dem/trace"]
    sim.command("\n".join(lines))
    if target == "sphere":
        sim.v[np.argsort(sim.tag)] = [[0.5 * speed, 0, 0], [-0.5 * speed, 0, 0]]
        axis, reach = 0, DIAMETER
    else:
        sim.v[:] = [0.0, 0.0, -speed]
        axis, reach = 2, RADIUS
    sim.command(f"run {int(math.ceil(2.0 * steps_per_contact)) + 4}")
    trace = sim.fixes["trace"]
    x, v = np.array(trace.x), np.array(trace.v)
    sim.close()
    if target == "sphere":
        overlap = reach - (x[:, 1, axis] - x[:, 0, axis])
        after = v[-1, 1, axis] - v[-1, 0, axis]
    else:
        overlap = reach - x[:, 0, axis]
        after = v[-1, 0, axis]
    inside = np.flatnonzero(overlap > 0.0)
    first, last = inside[0], inside[-1]
    if last + 1 >= len(overlap) or (np.diff(inside) != 1).any():
        raise RuntimeError(f"{model} {target} e={e} dt=t_c/{steps_per_contact}: contact did not end once")
    start = first - 1 + -overlap[first - 1] / (overlap[first] - overlap[first - 1])
    end = last + overlap[last] / (overlap[last] - overlap[last + 1])
    return {"restitution": after / speed, "max_overlap": float(overlap.max()),
            "contact_time": (end - start) * dt, "dt": dt, "warnings": list(dict.fromkeys(sim.warnings))}


def collision_row(model, target, e, steps_per_contact, workdir, speed=IMPACT_SPEED, youngs=YOUNGS,
                  phases=PHASES):
    """A collision at ``phases`` phases: mean and worst error against the continuous solution."""
    ref = reference(model, target, e, speed, youngs)
    runs = [collision(model, target, e, steps_per_contact, (k + 0.5) / phases, workdir, speed, youngs)
            for k in range(phases)]
    restitution = np.array([r["restitution"] for r in runs])
    overlap = np.array([r["max_overlap"] for r in runs]) / ref["max_overlap"]
    duration = np.array([r["contact_time"] for r in runs]) / ref["contact_time"]
    error = restitution / e - 1.0
    warnings = sorted({w for r in runs for w in r["warnings"]})
    return {"model": model, "target": target, "e": e, "steps_per_contact": steps_per_contact,
            "speed": speed, "youngs": youngs if model == "dem/hertz" else None,
            "dt": runs[0]["dt"], "reference": ref,
            "restitution_mean": float(restitution.mean()), "restitution_error_mean": float(error.mean()),
            "restitution_error_worst": float(error[np.argmax(abs(error))]),
            "overlap_ratio_mean": float(overlap.mean()), "overlap_ratio_min": float(overlap.min()),
            "overlap_ratio_max": float(overlap.max()),
            "contact_time_ratio_mean": float(duration.mean()),
            "contact_time_ratio_min": float(duration.min()), "contact_time_ratio_max": float(duration.max()),
            "warnings": warnings}


# ---- beds ---------------------------------------------------------------------------------------
def pour_top(layers):
    return 1.0 + 1.1 * (layers - 1)


def bed_contact_time(model, layers, youngs=YOUNGS):
    """t_c of the bed: two spheres meeting at the largest impact speed of the pour, sqrt(2 g z_top)."""
    speed = math.sqrt(2.0 * GRAVITY * pour_top(layers))
    return reference(model, "sphere", BED_RESTITUTION, speed, youngs)["contact_time"], speed


def bed(model, dt, length, layers, workdir, youngs=YOUNGS, seed=FIRST_SEED):
    """Spheres on a lattice of spacing 1.1 (random velocities 0.5), in a box of side ``length`` with
    walls, falling under gravity."""
    height = pour_top(layers) + 4.0
    stl = workdir / f"box_{length}.stl"
    write_stl(stl, open_box_quads(length, height))
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
units lj
particle_style sphere
boundary f f f
region box block 0 {length} 0 {length} 0 {height}
create_box 1 box
lattice spacing x 1.1 y 1.1 z 1.1
region pour block 0.6 {length - 0.6} 0.6 {length - 0.6} 1 {pour_top(layers) + 0.5}
create_particle 1 region pour diameter {DIAMETER} density {DENSITY!r}
velocity all create 0.5 {seed} gaussian
{pair_commands(model, BED_RESTITUTION, youngs)}
{wall_commands(model, BED_RESTITUTION, f"0 {length} 0 {length} 0 {height}", stl, youngs)}
neighbor 0.2 bin
timestep {dt!r}
fix grav all gravity {GRAVITY} vector 0 0 -1
fix 1 all nve/sphere
{CHECK.format(every=1000)}
thermo 0
""")
    return sim


def add_breakdown(sim, into):
    """Add the last run's seconds per stage (Pair, Neigh, ...) and per fix to ``into``."""
    for name, seconds in list(sim.timers.stage.items()) + list(sim.timers.style.items()):
        into[name] = into.get(name, 0.0) + seconds
    return into


def kinetic_energies(sim):
    """Translational and rotational kinetic energy of each particle."""
    p, n = sim.particles, sim.particles.nlocal
    inertia = 0.4 * p.rmass[:n] * p.radius[:n] ** 2
    return (0.5 * p.rmass[:n] * (p.v[:n] ** 2).sum(axis=1),
            0.5 * inertia * (p.omega[:n] ** 2).sum(axis=1))


def kinetic_energy(sim):
    translation, rotation = kinetic_energies(sim)
    return float(translation.sum() + rotation.sum())


def cost_row(model, steps_per_contact, state, length, layers, workdir):
    """Wall time of COST_STEPS steps from the same moment of a pour, at dt = t_c/N: the fastest of
    COST_REPEATS runs, as other work on a shared machine only ever adds time."""
    t_c, _ = bed_contact_time(model, layers)
    dt = t_c / steps_per_contact
    walls, breakdowns = [], []
    for _ in range(COST_REPEATS):
        sim = bed(model, dt, length, layers, workdir)
        order = np.argsort(sim.tag)
        sim.x[order], sim.v[order] = state["x"], state["v"]
        sim.particles.omega[: sim.nlocal][order] = state["omega"]
        sim.command("run 0")
        builds = sim.neighbor.builds
        start = time.perf_counter()
        sim.command(f"run {COST_STEPS}")
        walls.append(time.perf_counter() - start)
        breakdowns.append(add_breakdown(sim, {}))
        sim.close()
    wall = min(walls)
    return {"model": model, "steps_per_contact": steps_per_contact, "dt": dt, "particles": sim.nlocal,
            "steps": COST_STEPS, "wall": wall, "walls": walls, "ms_per_step": 1e3 * wall / COST_STEPS,
            "breakdown": breakdowns[walls.index(wall)],
            "wall_per_time": wall / (COST_STEPS * dt), "neighbor_builds": sim.neighbor.builds - builds,
            "warnings": list(dict.fromkeys(sim.warnings))}


def pour_state(model, length, layers, workdir, moment):
    """Positions, velocities and spins (tag order) of the pour at time ``moment``, run at t_c/20."""
    t_c, _ = bed_contact_time(model, layers)
    dt = t_c / 20.0
    sim = bed(model, dt, length, layers, workdir)
    sim.command(f"run {int(round(moment / dt))}")
    order = np.argsort(sim.tag)
    state = {"x": sim.x[order].copy(), "v": sim.v[order].copy(),
             "omega": sim.particles.omega[: sim.nlocal][order].copy()}
    sim.close()
    return state


def contacts(sim):
    """Overlaps of all touching sphere pairs (from the pair style's neighbor list)."""
    p, nlist = sim.particles, sim.pair_list
    n = p.nlocal
    i = np.repeat(np.arange(n), np.diff(nlist.offsets[: n + 1]))
    j = nlist.neighbors[: nlist.offsets[n]]
    overlap = p.radius[i] + p.radius[j] - np.linalg.norm(p.x[i] - p.x[j], axis=1)
    return overlap[overlap > 0.0]


def packing_fraction(x, radius, lo, hi, blocks=2, spacing=0.025):
    """Sum of the sphere volumes inside the box [lo, hi) over its volume, partial spheres counted on
    a grid of cell centres ``spacing`` apart; also the same per block of a blocks^3 split (a spread)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    cells = np.round((hi - lo) / spacing).astype(int)
    block_of = [np.arange(cells[d]) * blocks // cells[d] for d in range(3)]
    block_cells = np.einsum("i,j,k->ijk", *[np.bincount(b, minlength=blocks) for b in block_of]).ravel()
    filled = np.zeros(blocks ** 3)
    for centre, r in zip(x, radius):
        first = np.maximum(np.floor((centre - r - lo) / spacing).astype(int), 0)
        last = np.minimum(np.ceil((centre + r - lo) / spacing).astype(int), cells)
        if (last <= first).any():
            continue
        span = [np.arange(first[d], last[d]) for d in range(3)]
        offset = [lo[d] + spacing * (span[d] + 0.5) - centre[d] for d in range(3)]
        inside = (offset[0][:, None, None] ** 2 + offset[1][None, :, None] ** 2
                  + offset[2][None, None, :] ** 2) < r * r
        b = [block_of[d][span[d]] for d in range(3)]
        index = (b[0][:, None, None] * blocks + b[1][None, :, None]) * blocks + b[2][None, None, :]
        filled += np.bincount(index[inside], minlength=blocks ** 3)
    return float(filled.sum() / cells.prod()), filled / block_cells


def settle(sim, dt, budget=MAX_SETTLE_TIME):
    """Run in chunks until the kinetic energy is SETTLE_KE of its peak or the budget of simulated
    time is spent; returns (simulated time, steps, wall seconds, final KE / peak KE, history of
    (time, kinetic energy, its translational part), seconds per stage and fix)."""
    chunk = max(1, int(round(SETTLE_CHUNK / dt)))
    peak, steps, wall, history, breakdown = kinetic_energy(sim), 0, 0.0, [], {}
    while steps * dt < budget:
        start = time.perf_counter()
        sim.command(f"run {chunk}")
        wall += time.perf_counter() - start
        add_breakdown(sim, breakdown)
        steps += chunk
        translation, rotation = kinetic_energies(sim)
        energy = float(translation.sum() + rotation.sum())
        peak = max(peak, energy)
        history.append((steps * dt, energy, float(translation.sum())))
        if energy < SETTLE_KE * peak:
            break
    return steps * dt, steps, wall, history[-1][1] / peak, history, breakdown


def wall_overlap(x, length):
    """Largest overlap of a sphere with the box's floor or side walls."""
    gaps = np.concatenate([x[:, 2], x[:, 0], length - x[:, 0], x[:, 1], length - x[:, 1]])
    return float(max(RADIUS - gaps.min(), 0.0))


def soft_row(factor, length, layers, sub_lo, sub_hi, workdir, seed):
    """Pour and settle the bed with Young's modulus YOUNGS / factor at dt = t_c/20 of that modulus
    (``seed``: of the initial velocities)."""
    youngs = YOUNGS / factor
    t_c, speed = bed_contact_time("dem/hertz", layers, youngs)
    dt = t_c / SOFT_STEPS_PER_CONTACT
    rayleigh = contact_models.rayleigh_time(RADIUS, DENSITY, youngs / (2.0 * (1.0 + POISSON)), POISSON)
    impact = collision_row("dem/hertz", "sphere", BED_RESTITUTION, SOFT_STEPS_PER_CONTACT, workdir,
                           speed=speed, youngs=youngs, phases=4)
    sim = bed("dem/hertz", dt, length, layers, workdir, youngs=youngs, seed=seed)
    simulated, steps, wall, ke_ratio, history, breakdown = settle(sim, dt)
    n = sim.nlocal
    x, radius = sim.x.copy(), sim.particles.radius[:n].copy()
    phi, blocks = packing_fraction(x, radius, sub_lo, sub_hi)
    overlap = contacts(sim)
    translation, rotation = kinetic_energies(sim)
    energy = translation + rotation
    row = {"factor": factor, "seed": seed, "youngs": youngs,
           "stiffness_number": youngs / (DENSITY * GRAVITY * DIAMETER),
           "dt": dt, "contact_time": t_c, "rayleigh_time": rayleigh, "dt_over_rayleigh": dt / rayleigh,
           "impact_speed": speed, "particles": n, "steps": steps, "simulated_time": simulated,
           "wall": wall, "wall_per_time": wall / simulated, "ms_per_step": 1e3 * wall / steps,
           "settled": ke_ratio < SETTLE_KE, "ke_over_peak": ke_ratio,
           "ke_share_of_one_particle": float(energy.max() / energy.sum()),
           "ke_share_rotational": float(rotation.sum() / energy.sum()),
           "load_average_after": os.getloadavg()[0],
           "packing_fraction": phi, "packing_spread": float(blocks.std(ddof=1) / math.sqrt(len(blocks))),
           "packing_blocks": blocks.tolist(), "surface": float(np.percentile(x[:, 2], 95)),
           "overlap_max": float(overlap.max()), "overlap_mean": float(overlap.mean()),
           "coordination": 2.0 * len(overlap) / n, "wall_overlap_max": wall_overlap(x, length),
           "impact": impact, "ke_history": history, "breakdown": breakdown,
           "warnings": list(dict.fromkeys(sim.warnings))}
    sim.close()
    return row


# ---- running and reporting ----------------------------------------------------------------------
def machine():
    model = "unknown"
    cpuinfo = pathlib.Path("/proc/cpuinfo")
    if cpuinfo.exists():
        found = re.search(r"model name\s*:\s*(.+)", cpuinfo.read_text())
        model = found.group(1).strip() if found else model
    return {"cpu": model, "cores": os.cpu_count(), "load_average_at_start": os.getloadavg()[0]}


def run_collisions(workdir):
    rows = []
    for model in ("dem/lsd", "dem/hertz"):
        for e in RESTITUTIONS:
            for target in ("sphere", "wall"):
                for n in STEPS_PER_CONTACT:
                    row = collision_row(model, target, e, n, workdir)
                    rows.append(row)
                    print(collision_summary(row), flush=True)
    return rows


def collision_summary(row):
    return (f"{row['model']:<9} {row['target']:<6} e={row['e']:<3} dt=t_c/{row['steps_per_contact']:<3} "
            f"e_meas/e-1 = {100 * row['restitution_error_mean']:+6.2f} % "
            f"(worst {100 * row['restitution_error_worst']:+6.2f} %)  "
            f"overlap/analytic = {row['overlap_ratio_mean']:.3f} "
            f"[{row['overlap_ratio_min']:.3f}, {row['overlap_ratio_max']:.3f}]  "
            f"t_c/analytic = {row['contact_time_ratio_mean']:.3f}  warnings: {len(row['warnings'])}")


def run_cost(workdir):
    rows = []
    for model in ("dem/lsd", "dem/hertz"):
        state = pour_state(model, COST_LENGTH, COST_LAYERS, workdir, COST_MOMENT)
        for n in STEPS_PER_CONTACT:
            row = cost_row(model, n, state, COST_LENGTH, COST_LAYERS, workdir)
            rows.append(row)
            shares = time_shares(row)
            print(f"{model:<9} {row['particles']} spheres dt=t_c/{n:<3} ({row['dt']:.3g}): "
                  f"{row['ms_per_step']:.2f} ms/step, {row['wall_per_time']:.1f} wall s per time unit, "
                  f"{row['neighbor_builds']} list builds in {row['steps']} steps; "
                  f"pair {shares['pair']:.0f} %, walls {shares['walls']:.0f} %", flush=True)
    return rows


def time_shares(row):
    """Percent of a row's wall time spent in the pair style and in the wall fix."""
    breakdown, wall = row["breakdown"], row["wall"]
    walls = sum(seconds for name, seconds in breakdown.items() if name.startswith("fix w "))
    return {"pair": 100.0 * breakdown.get("Pair", 0.0) / wall, "walls": 100.0 * walls / wall}


def run_soft(workdir):
    rows = []
    runs = [(factor, FIRST_SEED) for factor in SOFTENING]
    runs += [(factor, seed) for factor in REPEATED for seed in REPEAT_SEEDS]
    for factor, seed in runs:
        row = soft_row(factor, SOFT_LENGTH, SOFT_LAYERS, SOFT_SUB_LO, SOFT_SUB_HI, workdir, seed)
        rows.append(row)
        impact = row["impact"]
        shares = time_shares(row)
        print(f"Y/{factor:<5} seed {seed:<4} dt={row['dt']:.3g} "
              f"(t_c/{SOFT_STEPS_PER_CONTACT}, {row['dt_over_rayleigh']:.2f} t_R): "
              f"{'settled' if row['settled'] else 'NOT settled'} "
              f"after {row['simulated_time']:.1f} time units, "
              f"{row['steps']} steps, {row['wall']:.0f} s wall ({row['wall_per_time']:.1f} s per time unit); "
              f"phi = {row['packing_fraction']:.4f} +- {row['packing_spread']:.4f}, "
              f"overlap max/mean = {row['overlap_max']:.4f}/{row['overlap_mean']:.4f} d, "
              f"Z = {row['coordination']:.2f}; "
              f"time in pair {shares['pair']:.0f} %, walls {shares['walls']:.0f} %; "
              f"impact at v={row['impact_speed']:.2f}: t_c = {impact['reference']['contact_time']:.4g}, "
              f"max overlap = {impact['reference']['max_overlap']:.4f} d", flush=True)
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--parts", nargs="+", choices=("collisions", "cost", "soft"),
                        default=["collisions", "cost", "soft"],
                        help="parts to run; the others are kept from the results file")
    parser.add_argument("--plot-only", action="store_true", help="redraw the plot from the results file")
    args = parser.parse_args()
    if args.plot_only:
        plot(json.loads(RESULTS.read_text()))
        return
    registry.register("fix", Trace.name, Trace)
    results = json.loads(RESULTS.read_text()) if RESULTS.exists() else {}
    results["machine"] = machine()
    runners = {"collisions": run_collisions, "cost": run_cost, "soft": run_soft}
    started = time.perf_counter()
    with tempfile.TemporaryDirectory() as scratch:
        for part in args.parts:
            start = time.perf_counter()
            results[part] = runners[part](pathlib.Path(scratch))
            results.setdefault("wall_seconds", {})[part] = time.perf_counter() - start
            RESULTS.parent.mkdir(exist_ok=True)
            RESULTS.write_text(json.dumps(results, indent=1))
    print(f"total {time.perf_counter() - started:.0f} s")
    plot(results)


def plot(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 3, figsize=(16, 9))
    (error_ax, ratio_ax, cost_ax), (packing_ax, overlap_ax, speed_ax) = axes
    floor = 1e-4            # |mean error| below this is drawn at it (log axis)
    colors = {("dem/lsd", 0.5): "C0", ("dem/lsd", 0.9): "C1", ("dem/hertz", 0.5): "C2",
              ("dem/hertz", 0.9): "C3"}
    collisions = [r for r in results.get("collisions", []) if r["target"] == "sphere"]
    for (model, e), color in colors.items():
        rows = [r for r in collisions if r["model"] == model and r["e"] == e]
        if not rows:
            continue
        n = [r["steps_per_contact"] for r in rows]
        error_ax.loglog(n, [max(abs(r["restitution_error_worst"]), floor) for r in rows], "v-", color=color,
                        label=f"{model} e={e}: worst phase")
        error_ax.loglog(n, [max(abs(r["restitution_error_mean"]), floor) for r in rows], "o:", color=color,
                        alpha=0.6, label=f"{model} e={e}: mean of 8 phases")
        ratio_ax.semilogx(n, [r["overlap_ratio_mean"] for r in rows], "o-", color=color,
                          label=f"{model} e={e}: max overlap")
        ratio_ax.semilogx(n, [r["contact_time_ratio_mean"] for r in rows], "s--", color=color,
                          label=f"{model} e={e}: contact time")
    error_ax.set(xlabel="steps per contact t_c / dt", ylabel="|e_measured / e - 1|",
                 title="restitution error (sphere-sphere = sphere-wall)")
    ratio_ax.axhline(1.0, color="gray", lw=0.8)
    ratio_ax.set(xlabel="steps per contact t_c / dt", ylabel="measured / continuous law",
                 title="max overlap (sampled at steps), contact time")
    for model, color in (("dem/lsd", "C0"), ("dem/hertz", "C2")):
        cost = {r["steps_per_contact"]: r["wall_per_time"]
                for r in results.get("cost", []) if r["model"] == model}
        rows = [r for r in collisions
                if r["model"] == model and r["e"] == 0.5 and r["steps_per_contact"] in cost]
        if not rows:
            continue
        x = [cost[r["steps_per_contact"]] for r in rows]
        cost_ax.loglog(x, [abs(r["restitution_error_worst"]) for r in rows], "v-", color=color,
                       label=f"{model} e=0.5, worst phase")
        cost_ax.loglog(x, [abs(r["restitution_error_mean"]) for r in rows], "o:", color=color, alpha=0.6,
                       label=f"{model} e=0.5, mean")
        for r, wall in zip(rows, x):
            cost_ax.annotate(f"t_c/{r['steps_per_contact']}", (wall, abs(r["restitution_error_worst"])),
                             fontsize=7, xytext=(3, 3), textcoords="offset points")
    particles = next((r["particles"] for r in results.get("cost", [])), "~1000")
    cost_ax.set(xlabel=f"wall s per unit of simulated time ({particles} settling spheres)",
                ylabel="|e_measured / e - 1|", title="restitution error against cost")
    soft = [r for r in results.get("soft", []) if r["seed"] == FIRST_SEED]
    repeats = [r for r in results.get("soft", []) if r["seed"] != FIRST_SEED]
    if soft:
        factors = [r["factor"] for r in soft]
        packing_ax.errorbar(factors, [r["packing_fraction"] for r in soft],
                            yerr=[r["packing_spread"] for r in soft], fmt="o-", color="C2", capsize=3,
                            label=f"seed {FIRST_SEED} (bars: spread of 8 sub-blocks)")
        packing_ax.plot([r["factor"] for r in repeats], [r["packing_fraction"] for r in repeats], "o",
                        mfc="none", color="C2", label="other pours")
        packing_ax.set_xscale("log")
        packing_ax.set(xlabel="Young's modulus divided by", ylabel="packing fraction",
                       title=f"settled bed (dem/hertz, dt = t_c/{SOFT_STEPS_PER_CONTACT})")
        overlap_ax.loglog(factors, [r["impact"]["reference"]["max_overlap"] for r in soft], "v-", color="C3",
                          label=f"impact at {soft[0]['impact_speed']:.1f} sqrt(g d): max overlap")
        overlap_ax.loglog(factors, [r["overlap_max"] for r in soft], "^-", color="C1",
                          label="settled bed: max overlap")
        overlap_ax.loglog(factors, [r["overlap_mean"] for r in soft], "o-", color="C0",
                          label="settled bed: mean overlap")
        overlap_ax.set(xlabel="Young's modulus divided by", ylabel="overlap / d", title="overlaps")
        speed_ax.loglog(factors, [r["wall_per_time"] for r in soft], "s-", color="C4",
                        label="wall s per unit of simulated time")
        speed_ax.loglog(factors, [r["wall"] for r in soft], "o--", color="C5",
                        label="wall s of the pour until settled (or 40 time units)")
        speed_ax.set(xlabel="Young's modulus divided by", ylabel="wall seconds",
                     title=f"cost ({soft[0]['particles']} spheres, 1 core)")
    for axis in axes.ravel():
        axis.grid(True, which="both", alpha=0.3)
        if axis.get_legend_handles_labels()[0]:
            axis.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(PLOT, dpi=100)


if __name__ == "__main__":
    main()
