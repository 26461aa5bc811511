"""Record LIGGGHTS 3.8.0's dump image pictures of the bed of cases.py, which
plugins/dump_image/tests/test_liggghts_images.py makes pdps draw again, pixel by pixel.

    python benchmarks/liggghts_references/images.py [LIGGGHTS]

Two scripts: the bed (27 spheres of two types falling onto a wall, with velocities that vary from
sphere to sphere) with one dump image per case (each a set of keywords and dump_modify lines), every
200 steps over 400 steps: 3 pictures per case; and a 2-d lattice of point particles (FLAT), two
cases every 100 steps over 200. The pictures go, as numbers ((height, width, 3)
bytes, top row first), into plugins/dump_image/tests/data/liggghts_images.npz (PPM files as
written; JPEG files decoded by Pillow), the script into liggghts_images.json beside it, with the
scene and the run apart, for the tests' own dumps of the same scene (movies, PNG, two ranks).
"""

import io
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cases import BED, HEAD, LIGGGHTS, PROGRAM, ROOT  # noqa: E402

DATA = ROOT / "plugins" / "dump_image" / "tests" / "data"
EVERY, STEPS = 200, 400

# name: (the dump line's words after the file, the dump_modify lines' words after the ID, file suffix)
CASES = {
    "default": ("type diameter size 100 75", [], "ppm"),
    "view_zoom": ("type diameter size 120 90 view 80 -30 zoom 1.8 box no 0.0", [], "ppm"),
    "center_up": ("type diameter size 90 90 center d 0.3 0.6 0.4 up 1 0 0 zoom 2", [], "ppm"),
    "view_from_top": ("type diameter size 80 60 view 0 0 box yes 0.05", [], "ppm"),
    "view_from_below": ("type diameter size 80 60 view 180 45", [], "ppm"),
    "axes_shiny": ("type diameter size 120 90 axes yes 0.5 0.03 box yes 0.01 shiny 0.3", [], "ppm"),
    "ssao": ("type diameter size 120 90 ssao yes 15485863 0.6 zoom 1.5", [], "ppm"),
    "ssao_weak": ("type diameter size 100 75 ssao yes 32452843 0.2 shiny 0.0 view 70 120", [], "ppm"),
    "amap_continuous": ("vz diameter size 100 75 zoom 1.6",
                        ["amap min max cf 0.0 3 min blue 0.5 white max red"], "ppm"),
    "amap_absolute": ("vx diameter size 100 75 zoom 1.6",
                      ["amap -0.04 0.04 ca 0.0 4 min navy -0.01 lime 0.02 orange max crimson"], "ppm"),
    "amap_sequential": ("vz radius size 100 75 zoom 1.6 adiam 0.011",
                        ["amap -1.0 0.0 sa 0.25 3 red green blue"], "ppm"),
    "amap_default": ("z diameter size 100 75", [], "ppm"),
    "colors": ("type type size 110 80 zoom 1.4",
               ["adiam 1 0.01 adiam 2 0.013 color mycolor 0.2 0.6 0.9 acolor 1 gold acolor 2 mycolor "
                "backcolor white boxcolor black"], "ppm"),
    "acolor_list": ("type diameter size 100 75", ["acolor * orchid/teal backcolor lightgrey"], "ppm"),
    "element": ("element element size 100 75 adiam 0.011", ["element O Fe"], "ppm"),
    "variables": ("type diameter size 100 75 view v_theta v_phi zoom v_zoom up v_ux 0 1", [], "ppm"),
    "jpeg": ("type diameter size 96 72 zoom 1.3", [], "jpg"),
}
# a second scene: a 2-d Lennard-Jones-units lattice of point particles in a periodic box (pair soft),
# for dump image's 2-d defaults (view 0 0, up 0 1 0), a group, and a view of the plane from aside
FLAT = """units lj
dimension 2
atom_style atomic
atom_modify map array
boundary p p p
region box block 0 8 0 6 -0.5 0.5
create_box 2 box
lattice sq 1.0
create_atoms 1 box
region half block 0 4 INF INF INF INF units box
group half region half
set group half type 2
mass 1 1.0
mass 2 2.0
velocity all ramp vx -0.5 0.5 y 0 6 units box
velocity all ramp vy -0.3 0.4 x 0 8 sum yes units box
pair_style soft 1.0
pair_coeff * * 10.0
neighbor 0.3 bin
fix integr all nve
fix 2d all enforce2d
timestep 0.005
"""
FLAT_CASES = {
    "flat_default": ("all", "type type size 80 60 adiam 0.8", []),
    "flat_group": ("half", "vx type size 80 60 view 30 60 up 0 0 1",
                   ["adiam * 0.9 amap min max cf 0 2 min blue max yellow"]),
}
FLAT_EVERY = 100
VARIABLES = """variable theta equal 50+step/20
variable phi equal -40+step/10
variable zoom equal 1.2+step/1000
variable ux equal 0.3
"""


RUN = f"fix integr all nve/sphere\nthermo {EVERY}\nrun {STEPS}\n"


def script():
    dumps = []
    for name, (words, modify, suffix) in CASES.items():
        dumps.append(f"dump {name} all image {EVERY} {name}.*.{suffix} {words}\n")
        dumps += [f"dump_modify {name} {line}\n" for line in modify]
    return HEAD + BED + VARIABLES + "".join(dumps) + RUN


def flat_script():
    dumps = []
    for name, (group, words, modify) in FLAT_CASES.items():
        dumps.append(f"dump {name} {group} image {FLAT_EVERY} {name}.*.ppm {words}\n")
        dumps += [f"dump_modify {name} {line}\n" for line in modify]
    return FLAT + "".join(dumps) + f"thermo {FLAT_EVERY}\nrun {STEPS // 2}\n"


def run(liggghts, text, folder):
    (folder / "in.case").write_text(text)
    done = subprocess.run([liggghts, "-in", "in.case", "-log", "none", "-echo", "none"], cwd=folder,
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"LIGGGHTS failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")


def picture(path):
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.uint8)


def main(liggghts=LIGGGHTS):
    text, flat = script(), flat_script()
    pictures = {}
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        run(liggghts, text, folder)
        for name, (_, _, suffix) in CASES.items():
            for step in range(0, STEPS + 1, EVERY):
                pictures[f"{name}.{step}"] = picture(folder / f"{name}.{step}.{suffix}")
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        run(liggghts, flat, folder)
        for name in FLAT_CASES:
            for step in range(0, STEPS // 2 + 1, FLAT_EVERY):
                pictures[f"{name}.{step}"] = picture(folder / f"{name}.{step}.ppm")
    DATA.mkdir(parents=True, exist_ok=True)
    buffer = io.BytesIO()
    np.savez_compressed(buffer, **pictures)
    (DATA / "liggghts_images.npz").write_bytes(buffer.getvalue())
    table = {"program": PROGRAM, "scene": HEAD + BED + VARIABLES, "run": RUN,
             "every": EVERY, "steps": STEPS,
             "scripts": {"bed": text, "flat": flat},
             "cases": {**{name: {"suffix": suffix, "script": "bed"} for name, (_, _, suffix) in CASES.items()},
                       **{name: {"suffix": "ppm", "script": "flat"} for name in FLAT_CASES}}}
    (DATA / "liggghts_images.json").write_text(json.dumps(table, indent=1) + "\n")
    print(f"{len(pictures)} pictures -> {DATA / 'liggghts_images.npz'} ({len(buffer.getvalue())} bytes)")


if __name__ == "__main__":
    main(*sys.argv[1:])
