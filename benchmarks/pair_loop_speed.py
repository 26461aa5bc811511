"""Speed of the core-owned pair loop: force-law styles against hand-written loops.

1. pair dpd as a force law (the core's generated loop) against the hand-written loop it replaced
   (kept below verbatim, from the commit before the core owned the loop), on a water-like scene
   (4,000 particles, rho = 4).
2. pair formula with the Lennard-Jones formula against pair lj/cut, on LAMMPS's in.lj melt
   (32,000 atoms, rc = 2.5).

Each timing is the pair computation alone (``pair.compute`` on a built neighbor list, forces
cleared in between), the best of REPEAT rounds of CALLS calls, the styles interleaved so that both
see the same machine load. Times are this process's CPU time (time.process_time), which a loaded
machine disturbs far less than wall time. Usage: ``python benchmarks/pair_loop_speed.py [--repeat 7]``.
"""

import argparse
import math
import pathlib
import sys
import tempfile
import time

import numpy as np
from numba import njit

from pdps_core.api import Simulation, pair_gaussian
from pdps_core.testing import bench_data

EPSILON = 1.0e-10


@njit(cache=True)
def dpd_hand_written(x, v, f, type_, tag, offsets, neighbors, nlocal, a, gamma, sigma, cut,
                     dt_inv_sqrt, seed, step, eflag, thermostat):
    """pair dpd's loop as it was written by hand (plugins/pair_dpd, commit 1f0b2fa)."""
    energy = 0.0
    for i in range(nlocal):
        ti = type_[i]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            tj = type_[j]
            delx = x[i, 0] - x[j, 0]
            dely = x[i, 1] - x[j, 1]
            delz = x[i, 2] - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            rc = cut[ti, tj]
            if rsq >= rc * rc:
                continue
            r = math.sqrt(rsq)
            if r < EPSILON:
                continue
            rinv = 1.0 / r
            w = 1.0 - r / rc
            fpair = a[ti, tj] * w
            if thermostat:
                dot = (delx * (v[i, 0] - v[j, 0]) + dely * (v[i, 1] - v[j, 1])
                       + delz * (v[i, 2] - v[j, 2]))
                xi = pair_gaussian(seed, step, tag[i], tag[j])
                fpair += -gamma[ti, tj] * w * w * dot * rinv + sigma[ti, tj] * w * xi * dt_inv_sqrt
            fpair *= rinv
            f[i, 0] += delx * fpair
            f[i, 1] += dely * fpair
            f[i, 2] += delz * fpair
            f[j, 0] -= delx * fpair
            f[j, 1] -= dely * fpair
            f[j, 2] -= delz * fpair
            if eflag:
                energy += 0.5 * a[ti, tj] * rc * w * w
    return energy


def best(function, calls, results, name, clear):
    clear()
    t0 = time.process_time()
    for _ in range(calls):
        function()
    results.setdefault(name, []).append((time.process_time() - t0) / calls)


def water():
    sim = Simulation(screen=False, log=None)
    sim.command("""
        units lj
        region box block 0 10 0 10 0 10
        create_box 1 box
        create_particle 1 random 4000 5821 box
        mass 1 1.0
        velocity all create 1.0 4928
        pair_style dpd 1.0 1.0 3442527
        pair_coeff * * 25.0 4.5 1.0
        timestep 0.04
        fix 1 all nve
        run 200
    """)
    return sim


def lj(folder, style):
    bench_data("lj_fcc", folder / "lj_fcc.data")      # the in.lj configuration
    sim = Simulation(screen=False, log=None)
    coeff = "1 1 1.0 1.0 2.5" if style == "lj/cut" else '1 1 "4*eps*((sig/r)^12 - (sig/r)^6)" eps 1.0 sig 1.0'
    sim.command(f"read_data {folder / 'lj_fcc.data'}\npair_style {style} 2.5\npair_coeff {coeff}\n"
                "neighbor 0.3 bin\nrun 0")
    return sim


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    results = {}

    sim = water()
    p, pair, nlist = sim.particles, sim.pair, sim.pair_list
    clear = lambda: p.f.fill(0.0)  # noqa: E731
    for eflag, label in ((False, "force only"), (True, "with energy")):
        law = lambda: pair.compute(sim, nlist, eflag, False)  # noqa: E731
        hand = lambda: dpd_hand_written(p.x, p.v, p.f, p.type, p.tag, nlist.offsets,  # noqa: E731
                                        nlist.neighbors, p.nlocal, pair.a, pair.gamma, pair.sigma,
                                        pair.cut, 1.0 / math.sqrt(sim.dt), pair.args.seed, sim.step,
                                        eflag, True)
        for k in range(args.repeat):
            best(law, 20, results, f"dpd law, {label}", clear)
            best(hand, 20, results, f"dpd hand, {label}", clear)
    pairs = len(nlist.neighbors)

    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        cut, formula = lj(folder, "lj/cut"), lj(folder, "formula")
        for k in range(args.repeat):
            for name, s in (("lj/cut", cut), ("formula (LJ)", formula)):
                q = s.particles
                best(lambda: s.pair.compute(s, s.pair_list, True, False), 5, results, name,
                     lambda: q.f.fill(0.0))
        forces = [np.array(s.f) for s in (cut, formula)]
        relative = np.abs(forces[0] - forces[1]).max() / np.abs(forces[0]).max()

    print(f"{'style':<24} {'ms per call':>12}")
    for name, times in results.items():
        print(f"{name:<24} {1e3 * min(times):>12.3f}")
    for label in ("force only", "with energy"):
        ratio = min(results[f"dpd law, {label}"]) / min(results[f"dpd hand, {label}"])
        print(f"dpd ({pairs} listed pairs), {label}: force law / hand-written = {ratio:.3f}")
    print(f"lj: formula / lj/cut = {min(results['formula (LJ)']) / min(results['lj/cut']):.3f}; "
          f"largest force difference {relative:.2e} of the largest force")


if __name__ == "__main__":
    main()
