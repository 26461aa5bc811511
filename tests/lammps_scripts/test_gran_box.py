"""The benchmark kit's in.gran_box (gran_box/in.gran_box, a copy of ../shared/bench/lammps/in.gran_box,
unmodified: 4,000 frictional spheres between two walls under gravity, pair gran/hooke/history and fix
wall/gran) run with ``pdps run`` and shortened to NSTEPS, against LAMMPS's numbers recorded by
benchmarks/lammps_references/gran.py into gran_box/reference.txt:

- step 0: the kinetic energy velocity create gives (the temperature scaled to 0.5 exactly, whatever
  the random numbers), as printed, and all 4,000 spheres;
- step NSTEPS: no sphere lost, and the kinetic energy ``ke`` within 3 standard
  deviations of LAMMPS's mean over runs with other velocity seeds (the deviation of one run against
  a mean of several, sqrt(sd^2 + sd^2 / n)): velocity create draws pdps's own numbers until it
  reproduces LAMMPS's generator, so the trajectories are not LAMMPS's one by one.
"""

from pathlib import Path

from pdps_core.testing import bench_data

HERE = Path(__file__).parent / "gran_box"
NSTEPS = 2000


def reference():
    lines = (HERE / "reference.txt").read_text().splitlines()
    table = [line.split() for line in lines if not line.startswith("#") and not line.startswith("seeds")]
    header, rows = table[0], table[1:]
    seeded = next(line for line in lines if "runs with other velocity seeds" in line)
    runs = int(seeded.split(" over ")[1].split()[0])
    _, mean, sd = next(line for line in lines if line.startswith("seeds")).split()
    return header, rows, runs, float(mean), float(sd)


def test_gran_box_settles_as_in_lammps(pdps_cli, tmp_path):
    header, rows, runs, mean, sd = reference()
    bench_data("gran_box", tmp_path / "gran_box.data")
    done = pdps_cli((HERE / "in.gran_box").read_text(), "-var", "scenes", ".", "-var", "nsteps", str(NSTEPS),
                    "-var", "navg", str(NSTEPS // 2), "-log", "none", "--no-progress", name="in.gran_box")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "read as LAMMPS: atom_style on line 3"
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    assert lines[start].split() == header
    got = [line.split() for line in lines[start + 1:start + 3]]
    assert [row[0] for row in got] == [row[0] for row in rows] == ["0", str(NSTEPS)]
    first, last = dict(zip(header, got[0])), dict(zip(header, got[1]))
    want = dict(zip(header, rows[0]))
    assert first["Atoms"] == last["Atoms"] == "4000"
    assert f"{float(first['KinEng']):.8g}" == f"{float(want['KinEng']):.8g}"
    allowed = 3.0 * (sd * sd + sd * sd / runs) ** 0.5
    assert abs(float(last["KinEng"]) - mean) <= allowed, (float(last["KinEng"]), mean, allowed)
