r"""What LIGGGHTS's fix mesh/surface checks and repairs in a mesh as it reads it, and the walls it
extrudes from a planar one: the keywords ``precision``, ``heal``, ``curvature``,
``curvature_tolerant``, ``element_exclusion_list``, ``min_feature_length`` and ``extrude_planar``
(``pdps doc fix mesh/surface`` has the syntax). Read from LIGGGHTS 3.8.0's source and compared with
it on this machine (plugins/fix_wall/tests/data/liggghts.cases.json: mesh_heal, mesh_exclusion,
mesh_tolerant, mesh_extrude).

Nodes. Two nodes are one when each coordinate differs by less than ``precision`` (default
:math:`10^{-8}`, absolute, at most 0.001; LIGGGHTS's ``compDouble``). Two triangles are *duplicate*
when all three nodes of one are nodes of the other, and *neighbours* when they share two nodes (an
edge). Nodes are compared, never merged: every triangle keeps its own corners.

Checks, in LIGGGHTS's order, on the mesh as placed (after ``scale``, ``move``, ``rotate``):

- an angle of a triangle at or below the hard limit :math:`\arccos(0.9999995) = 0.0573°` is an
  error (triangles of zero area are dropped as the file is read);
- more than 5 neighbours of one triangle is an error;
- duplicate triangles are an error, unless ``heal auto_remove_duplicates``: then, as the file is
  read, a triangle duplicate of one read before it is left out (nodes compared unplaced);
- an angle smaller than the ``curvature`` (default LIGGGHTS's :math:`\arccos(1 - 10^{-5}) =
  0.256°`) is an error, or with ``curvature_tolerant yes`` a warning.

``element_exclusion_list write FILE`` writes the line number of each bad triangle into FILE instead
(one per line: those at the hard limit, then those with too many neighbours, then the earlier of each
duplicate pair, each line once; LIGGGHTS then stops at the first two kinds, pdps too, while with
duplicates both go on: LIGGGHTS with a sphere touching a triangle and its duplicate once, pdps with
the later of each pair left out, which measured the same); ``element_exclusion_list read FILE`` leaves the triangles of those lines out
as the file is read. A triangle's line is, as LIGGGHTS counts them from 1: in an ASCII STL file the
line of its ``facet``, in a binary STL file its number, in a legacy ASCII VTK file the line of its
cell. ``min_feature_length`` needs ``element_exclusion_list write`` and is refused as LIGGGHTS 3.8.0
refuses it (its feature removal is not in the public version).

``extrude_planar L`` on a planar mesh makes the walls of its boundary: each edge that no other
triangle shares is swept by :math:`-L\,\hat{\mathbf{n}}` (:math:`\hat{\mathbf{n}}` the unit normal of
the first triangle) into two triangles :math:`(\mathbf{b}, \mathbf{a}, \mathbf{b} + \mathbf{v})` and
:math:`(\mathbf{a}, \mathbf{a} + \mathbf{v}, \mathbf{b} + \mathbf{v})` for the edge from a to b, in
the triangles' and edges' order; another ``fix mesh/surface ... fix ID`` reads them as its mesh.
"""

import math
import os

import numpy as np
from numba import njit

from pdps_core.api import ScriptError

DEFAULT_PRECISION = 1e-8
LARGEST_PRECISION = 1e-3
HARD_LIMIT_COS = 0.9999995
DEFAULT_CURVATURE_COS = 1.0 - 1e-5
MOST_NEIGHBOURS = 5


# ---- the lines LIGGGHTS numbers the triangles by --------------------------------------------------
def element_lines(path, shown, count):
    """The line of each of the ``count`` triangles of a mesh file, in the file's order (LIGGGHTS's
    numbering); a ScriptError for a file that has none."""
    suffix = os.path.splitext(path)[1].lower()
    if suffix not in (".stl", ".vtk"):
        raise ScriptError(f"element_exclusion_list needs an STL or legacy ASCII VTK mesh file, whose triangles "
                          f"LIGGGHTS numbers by their lines (got {shown})")
    with open(path, "rb") as stream:
        head = stream.read(512)
    words = head.split()
    if suffix == ".stl":
        if words[:1] != [b"solid"]:
            return np.arange(1, count + 1, dtype=np.int64)
        lines = []
        with open(path, errors="replace") as stream:
            for number, line in enumerate(stream, start=1):
                if line.split()[:1] == ["facet"]:
                    lines.append(number)
    elif b"ASCII" in head:
        lines = vtk_cell_lines(path)
    else:
        raise ScriptError(f"element_exclusion_list needs an STL or legacy ASCII VTK mesh file, whose triangles "
                          f"LIGGGHTS numbers by their lines (got {shown}, a binary VTK file)")
    if len(lines) != count:
        raise ScriptError(f"element_exclusion_list: mesh file {shown} has {len(lines)} elements on lines but "
                          f"{count} triangles (a file of triangles only is numbered as LIGGGHTS numbers it)")
    return np.asarray(lines, dtype=np.int64)


def vtk_cell_lines(path):
    """The lines of a legacy VTK file's CELLS (LIGGGHTS counts every line, blank ones too)."""
    lines, wanted = [], 0
    with open(path, errors="replace") as stream:
        for number, line in enumerate(stream, start=1):
            words = line.split()
            if wanted and words:
                lines.append(number)
                wanted -= 1
            elif words[:1] == ["CELLS"] and len(words) > 1 and words[1].isdigit():
                wanted = int(words[1])
    return lines


def read_exclusion_list(path, shown):
    """The line numbers in an element exclusion list (one integer a line)."""
    if not os.path.isfile(path):
        raise ScriptError(f"element exclusion list {shown} does not exist")
    numbers = []
    with open(path, errors="replace") as stream:
        for number, line in enumerate(stream, start=1):
            word = line.strip()
            if not word:
                continue
            try:
                numbers.append(int(word))
            except ValueError:
                raise ScriptError(f"element exclusion list {shown}, line {number}: expected a line number "
                                  f"(got {word!r})") from None
    return np.asarray(sorted(set(numbers)), dtype=np.int64)


# ---- comparing nodes ------------------------------------------------------------------------------
@njit(cache=True)
def same_node(p, q, precision):
    for d in range(3):
        if p[d] != q[d] and not abs(p[d] - q[d]) < precision:
            return False
    return True


@njit(cache=True)
def shared_nodes(corners, i, j, precision):
    count = 0
    for a in range(3):
        for b in range(3):
            if same_node(corners[i, a], corners[j, b], precision):
                count += 1
                break
    return count


@njit(cache=True)
def duplicate_pairs(corners, precision):
    """(earlier, later) of every pair of duplicate triangles, by a sweep over their centres' x (the
    centres of duplicates are closer than ``precision``)."""
    n = corners.shape[0]
    centre_x = (corners[:, 0, 0] + corners[:, 1, 0] + corners[:, 2, 0]) / 3.0
    order = np.argsort(centre_x)
    pairs = []
    for a in range(n):
        i = order[a]
        for b in range(a + 1, n):
            j = order[b]
            if centre_x[j] - centre_x[i] > precision:
                break
            if shared_nodes(corners, i, j, precision) == 3:
                pairs.append((min(i, j), max(i, j)))
    out = np.empty((len(pairs), 2), dtype=np.int64)
    for k in range(len(pairs)):
        out[k, 0], out[k, 1] = pairs[k]
    return out


@njit(cache=True)
def edge_partners(corners, precision):
    """For each triangle and edge (nodes e, e+1), how many other triangles share that edge; and each
    triangle's number of neighbours (triangles sharing an edge with it)."""
    n = corners.shape[0]
    mid_x = np.empty(3 * n)
    for t in range(n):
        for e in range(3):
            mid_x[3 * t + e] = 0.5 * (corners[t, e, 0] + corners[t, (e + 1) % 3, 0])
    order = np.argsort(mid_x)
    partners = np.zeros((n, 3), dtype=np.int64)
    neighbours = np.zeros(n, dtype=np.int64)
    for a in range(3 * n):
        p = order[a]
        t, e = p // 3, p % 3
        for b in range(a + 1, 3 * n):
            q = order[b]
            if mid_x[q] - mid_x[p] > precision:
                break
            u, f = q // 3, q % 3
            if u == t:
                continue
            p0, p1 = corners[t, e], corners[t, (e + 1) % 3]
            q0, q1 = corners[u, f], corners[u, (f + 1) % 3]
            if ((same_node(p0, q0, precision) and same_node(p1, q1, precision))
                    or (same_node(p0, q1, precision) and same_node(p1, q0, precision))):
                partners[t, e] += 1
                partners[u, f] += 1
                neighbours[t] += 1
                neighbours[u] += 1
    return partners, neighbours


def smallest_angle_cos(corners):
    """The cosine of each triangle's smallest angle."""
    edge = np.roll(corners, -1, axis=1) - corners
    edge = edge / np.linalg.norm(edge, axis=2)[:, :, None]
    # the angle at node k lies between edge k (k -> k+1) and the reversed edge k-1
    cos = -(edge * np.roll(edge, 1, axis=1)).sum(axis=2)
    return cos.max(axis=1)


def first_of_duplicates(count, pairs):
    """Which of ``count`` triangles stay when each one duplicate (``pairs``: earlier, later) of a
    triangle kept before it is left out."""
    keep = np.ones(count, dtype=bool)
    for earlier, later in pairs[np.argsort(pairs[:, 1], kind="stable")]:
        if keep[earlier]:
            keep[later] = False
    return keep


def healed(corners, precision):
    """Which triangles stay when duplicates of earlier ones are left out (heal auto_remove_duplicates)."""
    return first_of_duplicates(len(corners), duplicate_pairs(corners, precision))


# ---- the checks of a placed mesh ------------------------------------------------------------------
def check_mesh(mesh_id, shown, corners, lines, precision, curvature_cos, tolerant, healing, numbered, listing, warn):
    """LIGGGHTS's quality checks (module docstring), in its order; ``listing``: None, or (the list's
    name, the path it is written to here: None on ranks other than the first) for
    element_exclusion_list write; ``numbered``: ``lines`` are the file's lines (else the triangles'
    numbers). Returns the duplicate pairs (a list goes on with them)."""
    cos = smallest_angle_cos(corners)
    sliver = np.flatnonzero(cos >= HARD_LIMIT_COS)
    _, neighbours = edge_partners(corners, precision)
    crowded = np.flatnonzero(neighbours > MOST_NEIGHBOURS)
    pairs = duplicate_pairs(corners, precision)
    if listing is not None and listing[1] is not None:
        listed = list(lines[sliver]) + list(lines[crowded]) + list(lines[np.unique(pairs[:, 0])])
        with open(listing[1], "w") as stream:
            stream.write("".join(f"{line}\n" for line in dict.fromkeys(int(k) for k in listed)))
    where = f"fix {mesh_id}: mesh file {shown}"
    kind = "of line " if numbered else ""
    if len(sliver):
        angle = math.degrees(math.acos(min(1.0, cos[sliver[0]])))
        raise ScriptError(f"{where}: the triangle {kind}{lines[sliver[0]]} has an angle of {angle:.3g} degrees "
                          f"(at most {math.degrees(math.acos(HARD_LIMIT_COS)):.4f}: {len(sliver)} such); "
                          "element_exclusion_list write FILE lists them, read FILE leaves them out")
    if len(crowded):
        t = crowded[0]
        raise ScriptError(f"{where}: the triangle {kind}{lines[t]} has {neighbours[t]} neighbours "
                          f"(at most {MOST_NEIGHBOURS}: {len(crowded)} such); element_exclusion_list write FILE "
                          "lists them, read FILE leaves them out")
    if len(pairs) and listing is None:
        earlier, later = pairs[np.lexsort((pairs[:, 0], pairs[:, 1]))][0]
        remedy = ("lower the precision" if healing
                  else "heal auto_remove_duplicates leaves the later out")
        raise ScriptError(f"{where}: the triangles {'of lines ' if numbered else ''}{lines[earlier]} and {lines[later]} are duplicate "
                          f"(nodes within precision {precision:g}); {remedy}")
    if len(pairs):
        warn(f"fix {mesh_id}: mesh file {shown} has {len(pairs)} duplicate triangle(s), listed in {listing[0]}; "
             "the later of each is left out (LIGGGHTS runs on with them, its spheres touching a triangle and its "
             "duplicate once: measured)")
    narrow = np.flatnonzero(cos > curvature_cos)
    if len(narrow):
        t = narrow[0]
        message = (f"{where}: the triangle {kind}{lines[t]} has an angle of "
                   f"{math.degrees(math.acos(min(1.0, cos[t]))):.3g} degrees, smaller than the curvature "
                   f"{math.degrees(math.acos(curvature_cos)):.3g} ({len(narrow)} such)")
        if not tolerant:
            raise ScriptError(f"{message}; lower curvature or give curvature_tolerant yes")
        warn(message)
    return pairs


# ---- extruding a planar mesh ----------------------------------------------------------------------
def extruded_corners(corners, length, precision):
    """The walls swept from the boundary edges of a planar mesh (module docstring), (2k, 3, 3)."""
    a, b = corners[0, 1] - corners[0, 0], corners[0, 2] - corners[0, 0]
    normal = np.cross(a, b)
    sweep = -length * normal / np.linalg.norm(normal)
    partners, _ = edge_partners(corners, precision)
    walls = []
    for t in range(len(corners)):
        for e in range(3):
            if partners[t, e] == 0:
                start, end = corners[t, e], corners[t, (e + 1) % 3]
                walls.append((end, start, end + sweep))
                walls.append((start, start + sweep, end + sweep))
    return np.array(walls, dtype=np.float64).reshape(-1, 3, 3)
