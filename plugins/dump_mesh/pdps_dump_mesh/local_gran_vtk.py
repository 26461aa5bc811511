"""Dump ``local/gran/vtk``: the force network for ParaView, one line per granular contact, as
LIGGGHTS's dump local/gran/vtk writes it: the rows of a ``compute pair/gran/local`` or ``compute
wall/gran/local`` as VTK line cells, one file per frame and a ``.series`` file listing them.

Syntax::

    dump ID all local/gran/vtk N FILE COMPUTE_ID

N is the interval in steps; FILE has one ``*`` (replaced by the step) and ends in ``.vtp`` (VTK's XML
PolyData, ASCII), ``.vtu`` (XML unstructured grid, through meshio) or ``.vtk`` (legacy VTK, through
meshio: an unstructured grid of lines where LIGGGHTS writes POLYDATA lines; the same points, lines
and arrays). Each contact is a line between its two points, the compute's ``pos`` columns (which it
must have): two particles' centres for pair/gran/local (wrapped into the box, so a contact across a
periodic boundary spans the box, as in LIGGGHTS), the contact point on the wall and the particle's
centre for wall/gran/local. The other columns are the lines' cell data, named and ordered as
LIGGGHTS names them, all Float64: ``vel1`` ``vel2`` (3 each, from vel), ``id1`` ``id2`` (the first two
id columns: the particles' ids; for a wall the mesh number and the triangle), ``force`` (3),
``torque`` (3), ``contact_area``, ``delta``, ``heat_flux``. The history columns are not written
(LIGGGHTS's neither), nor is the third id column. A rank-0 gather writes each frame in a parallel
run; the lines come in no fixed order.

The compute's group selects the contacts. LIGGGHTS 3.8.0 reads no group of the dump (its source
packs every row of the compute; measured: group low and all give the same file), so a group other
than ``all`` is refused rather than ignored. Refused at the dump line too: a compute that is no
pair/gran/local or wall/gran/local (LIGGGHTS's pair/gran/local/bond needs a cohesion bond pair
model, which pdps has not), one without ``pos``, and LIGGGHTS's parallel piece files ``.pvtp`` and
``.pvtu`` (pdps writes one file per frame from rank 0).

Checked against LIGGGHTS 3.8.0 (plugins/dump_mesh/tests/data/liggghts_local_gran_vtk.json):
points, lines and every array of both computes' frames, to the digits LIGGGHTS prints.

Example (LIGGGHTS's manual)::

    compute cpgl all pair/gran/local pos vel force
    dump dmp2 all local/gran/vtk 100 post/forcechain*.vtp cpgl
"""

import numpy as np
from pdps_core.api import ContactRows, ScriptError, StyleArgs, param

from .frames import MeshDump
from .vtk import DumpVTK, series_json

# compute keyword -> the cell arrays of its columns (name, width), None where a column is not written
ARRAYS = {"vel": [("vel1", 3), ("vel2", 3)], "id": [("id1", 1), ("id2", 1), (None, 1)], "force": [("force", 3)],
          "torque": [("torque", 3)], "contactArea": [("contact_area", 1)], "delta": [("delta", 1)],
          "heatFlux": [("heat_flux", 1)]}


class DumpLocalGranVTK(MeshDump):
    name = "local/gran/vtk"
    usage = "dump ID all local/gran/vtk N FILE_*.vtp COMPUTE_ID"
    extensions = (".vtp", ".vtu", ".vtk")
    example = "post/forcechain_*.vtp"
    series_suffix = ".series"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        compute: str

    def __init__(self, sim, id, group, args):
        if args.file.endswith((".pvtp", ".pvtu")):
            raise ScriptError(f"local/gran/vtk: parallel piece files (.pvtp, .pvtu) are not supported: pdps "
                              f"writes one file per frame from rank 0; use .vtp or .vtu (got {args.file})")
        if group != "all":
            raise ScriptError(f"local/gran/vtk: the compute's group selects the contacts (LIGGGHTS reads no "
                              f"dump group): use group all (got {group})")
        super().__init__(sim, id, group, args)
        compute = sim.computes.get(args.compute)
        if compute is None:
            raise ScriptError(f"local/gran/vtk: no compute {args.compute}")
        if not isinstance(compute, ContactRows):
            raise ScriptError(f"local/gran/vtk: compute {args.compute} ({compute.name}) is not a compute "
                              "pair/gran/local or wall/gran/local")
        if "pos" not in compute.keywords:
            raise ScriptError(f"local/gran/vtk: compute {args.compute} writes no positions (add pos)")
        self.compute = compute

    def write(self, sim):
        rows = self.compute.local(sim)
        layout = self.compute.contact_columns(sim)
        table = sim.comm.gather_rows(np.ascontiguousarray(rows, dtype=np.float64))
        if not sim.comm.is_root:
            return
        n = len(table)
        points, data, start = None, {}, 0
        for keyword, width in layout:
            block = table[:, start:start + width]
            start += width
            if keyword == "pos":
                # each line's two points, one after the other
                points = np.ascontiguousarray(block.reshape(2 * n, 3))
                continue
            offset = 0
            for array, size in ARRAYS.get(keyword, ()):
                if array is not None:
                    values = block[:, offset:offset + size]
                    data[array] = np.ascontiguousarray(values[:, 0] if size == 1 else values)
                offset += size
        lines = np.arange(2 * n, dtype=np.int64).reshape(n, 2)
        path = self.pattern.frame(sim.step)
        if path.endswith(".vtp"):
            self.write_frame(path, points, lines, {}, sim.time, data)
        else:
            self.write_frame(path, points, [("line", lines)], {}, sim.time, {k: [v] for k, v in data.items()})
        self.series.add(path, sim.time, empty=n == 0)

    def write_mesh(self, tmp, points, cells, point_data, time, cell_data):
        if self.pattern.tail.endswith(".vtp"):
            write_polydata_lines(tmp, points, cells, cell_data)
        elif not len(points):
            # a frame without contacts: meshio writes no file of an empty line block
            DumpVTK.write_mesh(self, tmp, np.zeros((0, 3)), [], {}, time, {})
        else:
            DumpVTK.write_mesh(self, tmp, points, cells, point_data, time, cell_data)

    def render_series(self, frames, surface):
        return series_json(frames)


def write_polydata_lines(path, points, lines, cell_data):
    """A VTK XML PolyData file (ASCII) of ``lines`` (n, 2) between ``points`` (2n, 3), with
    ``cell_data`` {name: (n,) or (n, 3)} (meshio writes no PolyData)."""

    def ascii(values):
        return " ".join(f"{v:.17g}" for v in np.ravel(values))

    n = len(lines)
    arrays = "".join(
        f'        <DataArray type="Float64" Name="{name}"'
        + (f' NumberOfComponents="{values.shape[1]}"' if np.ndim(values) == 2 else "")
        + f' format="ascii">\n          {ascii(values)}\n        </DataArray>\n'
        for name, values in cell_data.items())
    text = (
        '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
        f'  <PolyData>\n    <Piece NumberOfPoints="{2 * n}" NumberOfVerts="0" NumberOfLines="{n}" '
        'NumberOfStrips="0" NumberOfPolys="0">\n'
        f"      <CellData>\n{arrays}      </CellData>\n"
        '      <Points>\n        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">\n'
        f"          {ascii(points)}\n        </DataArray>\n      </Points>\n"
        '      <Lines>\n        <DataArray type="Int64" Name="connectivity" format="ascii">\n'
        f"          {ascii(np.ravel(lines))}\n        </DataArray>\n"
        '        <DataArray type="Int64" Name="offsets" format="ascii">\n'
        f"          {ascii(2 * np.arange(1, n + 1))}\n        </DataArray>\n      </Lines>\n"
        "    </Piece>\n  </PolyData>\n</VTKFile>\n")
    with open(path, "w") as handle:
        handle.write(text)
