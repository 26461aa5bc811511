"""Write hopper.stl: a square hopper, a vertical bin over a funnel that narrows to an outlet.

    outlet: |x|, |y| <= 4 at z = 0           (eight particle diameters: no arching for d = 1)
    funnel: widens to |x|, |y| <= 10 at z = 10 (walls 31 degrees from the vertical)
    bin:    vertical walls |x|, |y| = 10 from z = 10 to z = 30, open at the top

Each quadrilateral face is written as two triangles with normals pointing into the hopper.
    python make_hopper.py            # writes hopper.stl next to this script
"""

import pathlib

import numpy as np

OUTLET, TOP, FUNNEL_HEIGHT, BIN_TOP = 4.0, 10.0, 10.0, 30.0


def square(half, z):
    return [np.array(p, dtype=float) for p in
            [(-half, -half, z), (half, -half, z), (half, half, z), (-half, half, z)]]


def faces():
    low, mid, high = square(OUTLET, 0.0), square(TOP, FUNNEL_HEIGHT), square(TOP, BIN_TOP)
    quads = []
    for k in range(4):
        nxt = (k + 1) % 4
        quads.append((low[k], low[nxt], mid[nxt], mid[k]))     # funnel side
        quads.append((mid[k], mid[nxt], high[nxt], high[k]))   # bin side
    for a, b, c, d in quads:
        for tri in ((a, b, c), (a, c, d)):
            normal = np.cross(tri[1] - tri[0], tri[2] - tri[0])
            centre = sum(tri) / 3
            inward = -centre * [1, 1, 0]
            if normal @ inward < 0:
                tri = (tri[0], tri[2], tri[1])
                normal = -normal
            yield normal / np.linalg.norm(normal), tri


def write(path):
    lines = ["solid hopper"]
    for normal, tri in faces():
        lines.append(f"  facet normal {normal[0]:.6g} {normal[1]:.6g} {normal[2]:.6g}")
        lines.append("    outer loop")
        lines += [f"      vertex {p[0]:.6g} {p[1]:.6g} {p[2]:.6g}" for p in tri]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid hopper")
    path.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    write(pathlib.Path(__file__).with_name("hopper.stl"))
