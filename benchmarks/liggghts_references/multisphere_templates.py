"""Record what LIGGGHTS 3.8.0 computes of particletemplate/multisphere templates of pdps's own:
mass, bounding sphere, principal moments and inertia tensor, as its log prints them (%e, 7
digits), for plugins/fix_insert/tests/test_multisphere_template.py to compare with pdps's.

    python benchmarks/liggghts_references/multisphere_templates.py [LIGGGHTS]

Writes plugins/fix_insert/tests/data/liggghts.templates.json: each template's script line and the
numbers of the log's "Finished calculating properties of template" block.
"""

import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
LIGGGHTS = str(ROOT.parent / "shared" / "bench" / "liggghts")
OUT = ROOT / "plugins" / "fix_insert" / "tests" / "data" / "liggghts.templates.json"

HEAD = """atom_style sphere
atom_modify map array sort 0 0.0
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box
create_box 2 box
"""
# by name: the words after "fix ID all particletemplate/multisphere"
TEMPLATES = {
    # three overlapping spheres of different radii, Monte Carlo throughout
    "triple": "15485863 atom_type 1 density constant 2500 nspheres 3 ntry 100000 spheres 0.0 0.0 0.0 0.005 "
              "0.008 0.0 0.0 0.004 0.0 0.007 0.002 0.0045 type 1",
    # six spheres, a bent chain, ten times as many points
    "chain": "32452867 atom_type 1 density constant 1200 nspheres 6 ntry 1000000 spheres 0.0 0.0 0.0 0.003 "
             "0.004 0.001 0.0 0.0035 0.008 0.0 0.002 0.003 0.011 0.003 0.003 0.0025 0.012 0.007 0.001 0.003 "
             "0.009 0.010 -0.002 0.002 type 1",
    # mass and inertia given: the volume and centre by Monte Carlo, the density from them
    "given_volume": "15485863 atom_type 1 density constant 2500 nspheres 3 ntry 100000 spheres 0.0 0.0 0.0 "
                    "0.005 0.008 0.0 0.0 0.004 0.0 0.007 0.002 0.0045 type 1 mass 0.0025 inertia_tensor 3.1e-8 "
                    "-4e-9 1e-9 2.7e-8 -2e-9 4.0e-8 use_volume",
}
KEYS = ("mass", "r_bound", "r_equiv", "xcm", "bound_centre_body", "moments", "ex", "ey", "ez",
        "tensor_row1", "tensor_row2", "tensor_row3")


def numbers(line):
    return [float(w.strip(",")) for w in line.replace("=", " ").replace(",", " ").split()
            if w.strip(",").replace(".", "", 1).replace("e", "", 1).replace("-", "").replace("+", "").isdigit()]


def block(log):
    lines = log.splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("Finished calculating properties of template"))
    values = [numbers(line) for line in lines[start + 1:start + 11]]
    flat = [values[0][0], values[0][1], values[0][2], values[1], values[2], values[3], *values[4:10]]
    return dict(zip(KEYS, flat))


def main(program):
    recorded = {}
    for name, words in TEMPLATES.items():
        with tempfile.TemporaryDirectory() as folder:
            script = HEAD + f"fix pts all particletemplate/multisphere {words}\n"
            (Path(folder) / "in.template").write_text(script)
            done = subprocess.run([program, "-in", "in.template", "-log", "log.template", "-echo", "none"],
                                  cwd=folder, capture_output=True, text=True)
            log = (Path(folder) / "log.template").read_text()
        if done.returncode != 0 or "ERROR" in log:
            sys.exit(f"{name}: LIGGGHTS failed: {done.stderr[-300:]}{log[-300:]}")
        recorded[name] = {"template": words, **block(log)}
        print(name, recorded[name]["mass"], recorded[name]["moments"])
    OUT.write_text(json.dumps({"program": "LIGGGHTS 3.8.0 (Debian's liggghts)", "recorded_by": Path(__file__).name,
                               "templates": recorded}, indent=1) + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else LIGGGHTS)
