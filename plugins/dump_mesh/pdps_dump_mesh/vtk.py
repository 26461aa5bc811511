"""Dump ``vtk``: particles for ParaView, one VTK file per frame and a ``.series`` file listing them.

Syntax::

    dump ID GROUP vtk N FILE [walls yes|no]

N is the interval in steps. FILE has one ``*``, replaced by the step, and ends in ``.vtu`` (VTK's XML
unstructured grid, compressed binary: the one to use) or ``.vtk`` (legacy VTK). Each frame holds the
group's particles as points (VTK_VERTEX cells), sorted by id, with the point data ``id``, ``type``,
``v``, ``f``, and ``radius`` and ``omega`` when the particles have them (``particle_style sphere``).

The series file is FILE without the ``*`` and the separator before it, plus ``.series``
(``frames/p_*.vtu`` -> ``frames/p.vtu.series``): ParaView opens it as one data set whose time is
the simulation time, in the JSON form ParaView reads::

    {"file-series-version": "1.0", "files": [{"name": "p_0.vtu", "time": 0.0}, ...]}

``walls yes`` also writes the surface of every mesh wall (fix wall/mesh, fix mesh/surface): once if
it does not move (``p_wall_FIXID.vtu``), else a file per frame with a series of its own
(``p_wall_FIXID_STEP.vtu``, ``p_wall_FIXID.vtu.series``). A fix mesh/surface/stress is written every
frame with the cell data ``force`` (3 values), ``pressure`` and ``shear`` of each triangle (the
forces the particles exert on it, LIGGGHTS's mesh/vtk output). Default ``no``.

Each file is written under a temporary name and renamed, and the series file is rewritten after
each frame is in place: a run that stops leaves complete frames and a series naming only those.

Example::

    dump movie all vtk 100 frames/p_*.vtu walls yes
"""

import json

import meshio

from .frames import MeshDump


class DumpVTK(MeshDump):
    name = "vtk"
    usage = "dump ID GROUP vtk N FILE_*.vtu [walls yes|no]"
    extensions = (".vtu", ".vtk")
    example = "frames_*.vtu"
    series_suffix = ".series"

    def write_mesh(self, tmp, points, cells, point_data, time, cell_data):
        kind = "vtu" if self.pattern.tail.endswith(".vtu") else "vtk"
        if not len(points):
            # a frame with no particle: meshio's legacy writer fails on an empty vertex block
            cells, point_data = [], {}
        meshio.write(tmp, meshio.Mesh(points, cells, point_data=point_data, cell_data=cell_data),
                     file_format=kind)

    def render_series(self, frames, surface):
        return series_json(frames)


def series_json(frames):
    """ParaView's series file of the frames {name: (time, empty)}, one frame per line."""
    files = ",\n".join(f"    {json.dumps({'name': name, 'time': time})}"
                       for name, (time, _) in frames.items())
    return f'{{\n  "file-series-version": "1.0",\n  "files": [\n{files}\n  ]\n}}\n'
