"""Record LIGGGHTS 3.8.0's dump local/gran/vtk frames of a small granular scene, which
plugins/dump_mesh/tests/test_local_gran_vtk.py makes pdps write again and compares array by array.

    python benchmarks/liggghts_references/local_gran_vtk.py [LIGGGHTS]

The scene: four spheres (diameter 10 mm) in a ring around a box periodic in x, each overlapping its
neighbours by 10 um (the ring closes across the periodic boundary), on a mesh floor of two triangles
(three of them pressed into it by 5-20 um), and a larger sphere (12 mm) pressed onto two of them;
gravity, pair gran hertz/history, wall/gran hertz/history on the mesh. A compute pair/gran/local
(pos vel id force torque contactArea delta) is dumped to .vtp and .vtu, a compute wall/gran/local of
the four small spheres' group to legacy .vtk, at steps 0, 100 and 200. The numbers of each frame
(points, lines, cell arrays, as the files print them: points in Float32, arrays at 17 digits in the
XML files, 11 in the legacy one) go into plugins/dump_mesh/tests/data/liggghts_local_gran_vtk.json
with the script and the floor's STL text.
"""

import json
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import meshio
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cases import LIGGGHTS, MATERIAL, PROGRAM, ROOT  # noqa: E402

DATA = ROOT / "plugins" / "dump_mesh" / "tests" / "data" / "liggghts_local_gran_vtk.json"
STEPS = (0, 100, 200)
FILES = {"pair": ".vtp", "pairu": ".vtu", "wall": ".vtk"}


def square_stl(half_x, half_y, z):
    corners = [(-half_x, -half_y), (half_x, -half_y), (half_x, half_y), (-half_x, half_y)]
    facets = []
    for a, b, c in ((0, 1, 2), (0, 2, 3)):
        vertices = "".join(f"      vertex {corners[k][0]} {corners[k][1]} {z}\n" for k in (a, b, c))
        facets.append(f"  facet normal 0 0 1\n    outer loop\n{vertices}    endloop\n  endfacet\n")
    return "solid floor\n" + "".join(facets) + "endsolid floor\n"


STL = square_stl(0.0199, 0.0099, 0.0)
SCRIPT = """atom_style granular
atom_modify map array
boundary p p f
newton off
communicate single vel yes
units si
region box block -0.01998 0.01998 -0.01 0.01 0 0.04 units box
create_box 2 box
neighbor 0.002 bin
neigh_modify delay 0
""" + MATERIAL + """pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
create_atoms 1 single -0.014985 0.0003 0.00499 units box
create_atoms 1 single -0.004995 -0.0002 0.004995 units box
create_atoms 1 single 0.004995 0.0001 0.00498 units box
create_atoms 1 single 0.014985 -0.0001 0.00501 units box
create_atoms 2 single 0.0002 0.0 0.0145 units box
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.012 density 1500
group low type 1
fix cad all mesh/surface file floor.stl type 1
fix meshfloor all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
compute pl all pair/gran/local pos vel id force torque contactArea delta
compute wl low wall/gran/local pos vel id force torque contactArea delta
fix integr all nve/sphere
dump d1 all local/gran/vtk 100 pair_*.vtp pl
dump d2 all local/gran/vtk 100 wall_*.vtk wl
dump d3 all local/gran/vtk 100 pairu_*.vtu pl
run 200
"""


def read_xml(path):
    """(points (2n, 3), lines (n, 2), {name: values}) of an ASCII VTK XML PolyData file."""
    piece = ElementTree.parse(path).getroot().find("PolyData/Piece")

    def values(array):
        return np.array((array.text or "").split(), dtype=np.float64)

    points = values(piece.find("Points/DataArray")).reshape(-1, 3)
    lines = values(piece.find("Lines/DataArray[@Name='connectivity']")).astype(np.int64).reshape(-1, 2)
    data = {}
    for array in piece.find("CellData"):
        width = int(array.get("NumberOfComponents", "1"))
        v = values(array)
        data[array.get("Name")] = v.reshape(-1, width) if width > 1 else v
    return points, lines, data


def read_meshio(path):
    """The same of a file meshio reads (.vtu, legacy unstructured grid)."""
    mesh = meshio.read(path)
    lines = mesh.cells[0].data if mesh.cells else np.zeros((0, 2), dtype=np.int64)
    data = {name: np.asarray(blocks[0], dtype=np.float64) for name, blocks in mesh.cell_data.items()}
    return np.asarray(mesh.points, dtype=np.float64), lines, data


def read_legacy_polydata(path):
    """The same of a legacy ASCII VTK POLYDATA file of LINES (OFFSETS/CONNECTIVITY) with FIELD cell data."""
    words = Path(path).read_text().split()
    k = words.index("POINTS")
    npoints = int(words[k + 1])
    points = np.array(words[k + 3:k + 3 + 3 * npoints], dtype=np.float64).reshape(-1, 3)
    k = words.index("LINES")
    nlines = int(words[k + 1]) - 1
    k = words.index("CONNECTIVITY")
    lines = np.array(words[k + 2:k + 2 + 2 * nlines], dtype=np.int64).reshape(-1, 2)
    data = {}
    if "FIELD" in words:
        k = words.index("FIELD")
        count, k = int(words[k + 2]), k + 3
        for _ in range(count):
            name, width, n = words[k], int(words[k + 1]), int(words[k + 2])
            v = np.array(words[k + 4:k + 4 + width * n], dtype=np.float64)
            data[name] = v.reshape(-1, width) if width > 1 else v
            k += 4 + width * n
    return points, lines, data


def frame(points, lines, data):
    return {"points": points.tolist(), "lines": lines.tolist(), "cell_data": {k: v.tolist() for k, v in data.items()}}


def main(liggghts=LIGGGHTS):
    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "floor.stl").write_text(STL)
        (Path(tmp) / "in.script").write_text(SCRIPT)
        subprocess.run([liggghts, "-in", "in.script", "-log", "none", "-echo", "none"], cwd=tmp, check=True,
                       capture_output=True)
        frames = {}
        for stem, ext in FILES.items():
            for step in STEPS:
                path = Path(tmp) / f"{stem}_{step}{ext}"
                read = {".vtp": read_xml, ".vtu": read_meshio, ".vtk": read_legacy_polydata}[ext]
                frames[path.name] = frame(*read(path))
    DATA.write_text(json.dumps({"program": PROGRAM, "script": SCRIPT, "floor.stl": STL, "frames": frames},
                               indent=1) + "\n")
    print(f"wrote {DATA}: {len(frames)} frames")


if __name__ == "__main__":
    main(*sys.argv[1:])
