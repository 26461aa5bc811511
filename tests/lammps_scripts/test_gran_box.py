"""The benchmark kit's in.gran_box (gran_box/in.gran_box, a copy of the benchmark kit's bench/lammps/in.gran_box,
unmodified: 4,000 frictional spheres between two walls under gravity, pair gran/hooke/history and fix
wall/gran) run with ``pdps run`` and shortened to NSTEPS, against LAMMPS's numbers recorded by
benchmarks/lammps_references/gran.py into gran_box/reference.txt.

velocity create draws LAMMPS's numbers in the LAMMPS dialect, so the run is LAMMPS's: the thermo
lines at steps 0 and NSTEPS (atoms and ke) equal LAMMPS's as printed (8 significant digits). The
step-NSTEPS kinetic energy also lies within 3 standard deviations of LAMMPS's mean over runs with
other velocity seeds, the spread of the scene itself (the deviation of one run against a mean of
several, sqrt(sd^2 + sd^2 / n)).

``c_ke`` is not compared: LAMMPS divides an extensive compute's value by the atom count in thermo
output with ``thermo_modify norm yes`` (lj units), pdps prints the total.
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


def test_gran_box_thermo_equals_lammps(pdps_cli, tmp_path):
    header, rows, runs, mean, sd = reference()
    bench_data("gran_box", tmp_path / "gran_box.data")
    done = pdps_cli((HERE / "in.gran_box").read_text(), "-var", "scenes", ".", "-var", "nsteps", str(NSTEPS),
                    "-var", "navg", str(NSTEPS // 2), "-log", "none", "--no-progress", name="in.gran_box")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "read as LAMMPS: atom_style on line 3"
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    assert lines[start].split() == header
    got = [dict(zip(header, line.split())) for line in lines[start + 1:start + 3]]
    want = [dict(zip(header, row)) for row in rows]
    for mine, lammps in zip(got, want):
        assert mine["Step"] == lammps["Step"]
        assert mine["Atoms"] == lammps["Atoms"] == "4000"
        assert f"{float(mine['KinEng']):.8g}" == f"{float(lammps['KinEng']):.8g}", mine["Step"]
    assert [row["Step"] for row in got] == ["0", str(NSTEPS)]
    allowed = 3.0 * (sd * sd + sd * sd / runs) ** 0.5
    assert abs(float(got[1]["KinEng"]) - mean) <= allowed, (float(got[1]["KinEng"]), mean, allowed)
