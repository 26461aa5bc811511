"""Dump ``xdmf``: particles for ParaView and VisIt as XDMF 3, one file per frame and a time series
file that gathers them.

Syntax::

    dump ID GROUP xdmf N FILE [walls yes|no]

N is the interval in steps. FILE has one ``*``, replaced by the step, and ends in ``.xdmf`` (or
``.xmf``). Each frame is a complete XDMF file written by meshio's ``TimeSeriesWriter`` (one time
step, the data inline as text, so no HDF5 library is needed): the group's particles as points
(Polyvertex), sorted by id, at the frame's simulation time, with the point data ``id``, ``type``,
``v``, ``f``, and ``radius`` and ``omega`` when the particles have them (``particle_style sphere``).

The series file is FILE without the ``*`` and the separator before it (``frames/p_*.xdmf`` ->
``frames/p.xdmf``): a temporal collection with one grid per frame, which takes the frame's
time and includes its points and data from the frame file (XInclude), so particles may move, come
and go between frames. Open it in ParaView (Xdmf3 reader).

``walls yes`` also writes the surface of every mesh wall (fix wall/mesh) as triangles: once if it
does not move (``p_wall_FIXID.xdmf``), else a file per frame with a series of its own
(``p_wall_FIXID_STEP.xdmf``, ``p_wall_FIXID.xdmf``). Default ``no``.

Each file is written under a temporary name and renamed, and the series file is rewritten after
each frame is in place: a run that stops leaves complete frames and a series naming only those.

Example::

    dump movie all xdmf 100 frames/p_*.xdmf
"""

import xml.etree.ElementTree as ET

import meshio

from .frames import MeshDump

XINCLUDE = "http://www.w3.org/2001/XInclude"
MESH = "mesh"               # the name of the grid of points and cells in a frame file


class DumpXDMF(MeshDump):
    name = "xdmf"
    usage = "dump ID GROUP xdmf N FILE_*.xdmf [walls yes|no]"
    extensions = (".xdmf", ".xmf")
    example = "frames_*.xdmf"

    def write_mesh(self, tmp, points, cells, point_data, time, cell_data):
        if len(points) == 0:
            # empty data items make ParaView's XDMF reader abort: a grid with a time and nothing else
            root = ET.Element("Xdmf", Version="3.0")
            collection = ET.SubElement(ET.SubElement(root, "Domain"), "Grid", Name="particles",
                                       GridType="Collection", CollectionType="Temporal")
            grid = ET.SubElement(collection, "Grid", Name=MESH, GridType="Uniform")
            ET.SubElement(grid, "Time", Value=repr(float(time)))
            ET.ElementTree(root).write(tmp, xml_declaration=True)
            return
        # HDF5 would need h5py and keeps a file open across frames; inline text is crash-safe
        with meshio.xdmf.TimeSeriesWriter(tmp, data_format="XML") as writer:
            writer.mesh_name = MESH
            writer.write_points_cells(points, cells)
            writer.write_data(time, point_data=point_data, cell_data=cell_data)

    def render_series(self, frames, surface):
        root = ET.Element("Xdmf", Version="3.0")
        collection = ET.SubElement(ET.SubElement(root, "Domain"), "Grid",
                                   Name="walls" if surface else "particles",
                                   GridType="Collection", CollectionType="Temporal")
        parts = [f"//Grid[@Name='{MESH}']/*"]
        if not surface:
            parts.append("//Grid[@CollectionType='Temporal']/Grid/Attribute")
        for name, (time, empty) in frames.items():
            grid = ET.SubElement(collection, "Grid", Name=name, GridType="Uniform")
            ET.SubElement(grid, "Time", Value=repr(time))
            for part in [] if empty else parts:
                ET.SubElement(grid, f"{{{XINCLUDE}}}include", href=name, xpointer=f"xpointer({part})")
        ET.register_namespace("xi", XINCLUDE)
        ET.indent(root)
        return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"
