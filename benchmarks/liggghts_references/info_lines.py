"""Record the lines LIGGGHTS 3.8.0's ``info`` prints for a small granular script (SCRIPT), which
tests/test_info.py makes pdps print again, fact by fact.

    python benchmarks/liggghts_references/info_lines.py

The script defines regions (one side out), a group, variables of three styles, computes, fixes and
a dump, in a box with periodic and fixed faces, then asks ``info all`` before and after ``run 0``
(the ghost cutoff is known after it). The lines that change from run to run (the date, memory,
times, the build) are left out; the rest go to tests/data/liggghts_info.txt.
"""

import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cases import HEAD, LIGGGHTS  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = HEAD.replace("boundary f f f", "boundary f f p") + """\
region bed block -0.03 0.03 -0.03 0.03 0.0 0.06 units box
region hole sphere 0 0 0 0.01 side out units box
lattice sc 0.02 origin 0.5 0.5 0.5
create_atoms 1 region bed
region top block INF INF INF INF 0.04 INF units box
group top region top
set group top type 2
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.012 density 1500
variable a equal 2.5
variable s string hello
variable w atom x*2
compute rke all erotate/sphere
compute sum top reduce sum x y z vx vy vz
fix grav all gravity 9.81 vector 0.0 0.0 -1.0
fix integr all nve/sphere
dump d1 top custom 100 dump.info id type x y z
info all out overwrite info.before
run 0
info sys comm groups out overwrite info.after
"""
VARYING = ("Printed on", "LIGGGHTS(R) version", "sizeof(", "OS information", "Memory allocation",
           "Total dynamically", "Maximum resident", "Total time", "  CPU time", " Wall time")


def kept(text):
    return [line for line in text.splitlines() if line.strip() and not line.startswith(VARYING)]


def main():
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / "in.info").write_text(SCRIPT)
        subprocess.run([LIGGGHTS, "-in", "in.info", "-log", "none", "-echo", "none"], cwd=folder, check=True,
                       capture_output=True)
        lines = []
        for name in ("before", "after"):
            lines += [f"== {name}"] + kept((Path(folder) / f"info.{name}").read_text())
    (ROOT / "tests" / "data" / "liggghts_info.txt").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
