"""CPU time per call of each granular style's per-step work, on the gran_box scene's state.

Three scenes on the same 4,000 spheres (pdps_core.testing.bench_data("gran_box")), each run 2000
steps so that the spheres have settled and touch, then every style's per-step hook (and the pair
style's compute) called again and again on that state:

- ``lammps``: LAMMPS's script (benchmarks/scenes/lammps/in.gran_box): gran/hooke/history,
  wall/gran zplane, gravity, nve/sphere;
- ``pdps``: pdps's script (benchmarks/scenes/in.gran_box): dem/lsd, wall/dem on a block region;
- ``mesh``: pdps's script with the floor and the ceiling made of a two-triangle STL square each
  (wall/mesh).

CPU time (time.process_time), best of five repeats of 2000 calls: other work on the machine
lengthens wall times, not this. A force computation called again on the same positions does the
work of one step (its springs grow a little, no particle moves); nve/sphere moves the spheres by
dt v per call, so it is timed last.

    .venv/bin/python benchmarks/granular_styles.py [--calls 2000]
"""

import argparse
import pathlib
import tempfile
import time

from pdps_core.api import Simulation
from pdps_core.testing import bench_data

SCENES = pathlib.Path(__file__).parent / "scenes"
SQUARE = pathlib.Path(__file__).parents[1] / "plugins" / "fix_wall" / "tests" / "data" / "square.stl"
MESH_FLOOR = ("fix w all wall/mesh file {stl} scale 11.1 move 11.1 11.1 {z} model lsd 0.5 200000.0 50.0 "
              "57142.857 25.0 0.5")


def scripts(data):
    lammps = (SCENES / "lammps" / "in.gran_box").read_text()
    pdps = (SCENES / "in.gran_box").read_text()
    floor, ceiling = (MESH_FLOOR.format(stl=SQUARE, z=z) for z in (0, 40))
    mesh = "\n".join(floor if line.startswith("fix w all wall/dem") else line
                     for line in pdps.splitlines() if not line.startswith("region walls"))
    mesh = mesh.replace(floor, floor + "\n" + ceiling.replace("fix w all", "fix w2 all"))
    variables = {"scenes": str(data.parent), "out": str(data.parent), "data": str(data),
                 "nsteps": "2000", "navg": "1000"}
    return {"lammps": lammps, "pdps": pdps, "mesh": mesh}, variables


def cpu_us(call, calls):
    call()
    best = float("inf")
    for _ in range(5):
        t0 = time.process_time()
        for _ in range(calls):
            call()
        best = min(best, (time.process_time() - t0) / calls)
    return best * 1e6


def measure(text, variables, calls):
    sim = Simulation(screen=False, log=None, variables=variables)
    sim.command(text)
    sim.run_state.in_setup = False
    rows = [(f"pair {sim.pair.name}", cpu_us(lambda: sim.pair.compute(sim, sim.pair_list, False, False), calls))]
    for hook in ("post_force", "initial_integrate", "final_integrate"):
        for fix in sim.fixes.values():
            if callable(getattr(fix, hook, None)):
                method = getattr(fix, hook)
                rows.append((f"fix {fix.id} ({fix.name}) {hook}", cpu_us(lambda m=method: m(sim), calls)))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=2000)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        data = bench_data("gran_box", pathlib.Path(folder) / "gran_box.data")
        texts, variables = scripts(data)
        for scene, text in texts.items():
            print(f"{scene}:")
            for label, us in measure(text, variables, args.calls):
                print(f"  {label:40s} {us:8.2f} us")


if __name__ == "__main__":
    main()
