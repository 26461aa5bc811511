"""Write floor.stl: a square plate of 0.12 m x 0.12 m at z = 0 as 8 x 8 x 2 triangles (normals up), so
that dump mesh/vtk shows how the bed's weight spreads over the floor. Run: python make_floor.py"""

import numpy as np

HALF, CELLS = 0.06, 8


def main():
    edges = np.linspace(-HALF, HALF, CELLS + 1)
    lines = ["solid floor"]
    for i in range(CELLS):
        for j in range(CELLS):
            a = (edges[i], edges[j], 0.0)
            b = (edges[i + 1], edges[j], 0.0)
            c = (edges[i + 1], edges[j + 1], 0.0)
            d = (edges[i], edges[j + 1], 0.0)
            for tri in ((a, b, c), (a, c, d)):
                lines += ["  facet normal 0 0 1", "    outer loop"]
                lines += [f"      vertex {x:.6f} {y:.6f} {z:.6f}" for x, y, z in tri]
                lines += ["    endloop", "  endfacet"]
    lines.append("endsolid floor")
    with open("floor.stl", "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
