"""What dump vtk and dump xdmf share: one file per frame, a series file that lists them, mesh walls.

File names come from a pattern with one ``*``, replaced by the step: ``frames/p_*.vtu`` gives
``frames/p_0.vtu``, ``frames/p_100.vtu``, ... The series file takes the pattern without the ``*``
and the separator before it (``frames/p.vtu.series``, ``frames/p.xdmf``; ``series`` when nothing is
left). Frame names in the series are relative to it, so a folder of frames can be moved whole.

Particles are points (one vertex cell each), sorted by id, with the point data ``id``, ``type``,
``v``, ``f`` and, when the particles have them (``particle_style sphere``), ``radius`` and ``omega``.
In a parallel run rank 0 gathers the particles and writes every file.

Mesh walls (keyword ``walls yes``): every fix with a triangulated surface (the api's
``TriangleSurface``: ``vertices`` n x 3, ``triangles`` m x 3 corner rows, ``moving``), as fix
wall/mesh and mesh/surface have, is written as a surface of its own: once, to ``STEM_wall_FIXID.EXT``, if the fix says it does
not move (``moving`` false) and has no per-face values, else one file per frame
``STEM_wall_FIXID_STEP.EXT`` with its own series file ``STEM_wall_FIXID`` + series suffix. A fix
that offers per-face values (``SurfaceValues``: ``face_data(sim)``; fix mesh/surface/stress: ``force``,
``pressure``, ``shear``) has them written as cell data of its triangles.

A run that stops keeps every complete frame: each file is written under a temporary name and
renamed, and the series file is rewritten (the same way) after the frame it adds is in place, so it
never names a frame that is missing or cut short. Re-writing the series costs time in proportion to
the frames so far: fine for thousands of frames.
"""

import os
import tempfile

import numpy as np
from pdps_core.api import Dump, ScriptError, StyleArgs, SurfaceValues, TriangleSurface, keyword, param

SEPARATORS = "_.-"


class MeshDumpArgs(StyleArgs):
    every: int = param(ge=1, unit="timesteps")
    file: str
    walls: bool = keyword(False)


def replace_atomically(path, write):
    """``write(tmp)`` fills a temporary file beside ``path``, which is then renamed to ``path``:
    a reader, or a crash, sees the old file or the whole new one, never half of it."""
    # a name of our own rather than mkstemp's, whose file would keep mode 0600 after the rename
    tmp = os.path.join(os.path.dirname(path), f".{os.path.basename(path)}.{os.getpid()}.tmp")
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


class Pattern:
    """Frame, series and wall file names from ``dir/stem_*.ext`` (module docstring)."""

    def __init__(self, pattern, extensions, example):
        if pattern.count("*") != 1:
            raise ScriptError(f"the file name needs one * (replaced by the step), e.g. {example} "
                              f"(got {pattern})")
        self.head, self.tail = pattern.split("*")
        if not self.tail.endswith(extensions) or os.sep in self.tail:
            raise ScriptError(f"the file name must end in * and {' or '.join(extensions)}, "
                              f"e.g. {example} (got {pattern})")
        self.base = self.head.rstrip(SEPARATORS)
        named = self.base and not self.base.endswith(os.sep)
        self.stem = self.base if named else self.base + "series"
        self.wall_stem = f"{self.base}_wall" if named else self.base + "wall"

    def frame(self, step):
        return f"{self.head}{step}{self.tail}"

    def series(self):
        return self.stem + self.tail

    def wall(self, fix_id, step=None):
        """The wall's file: one for all frames (step None), or the one of a frame."""
        name = f"{self.wall_stem}_{fix_id.replace(os.sep, '_')}"
        return f"{name}{self.tail}" if step is None else f"{name}_{step}{self.tail}"


class Series:
    """The frames written so far, rewritten whole after each new frame by ``render(frames) ->
    text``; ``frames`` maps file names (relative to the series file) to (time, whether empty)."""

    def __init__(self, path, render):
        self.path = path
        self.render = render
        self.frames = {}

    def add(self, frame_path, time, empty=False):
        name = os.path.relpath(frame_path, os.path.dirname(self.path) or ".")
        # a frame written again (reset_timestep) keeps its place and takes the new time
        self.frames[name] = (float(time), empty)

        def write(tmp):
            with open(tmp, "w") as handle:
                handle.write(self.render(self.frames))
        replace_atomically(self.path, write)


def particle_frame(sim, group):
    """(points n x 3, point data) of the group's particles, sorted by id; None on every rank but 0
    of a parallel run, where rank 0 gathers the rows of all."""
    p = sim.particles
    chosen = np.flatnonzero(sim.groups.select(sim, group))
    columns = [("id", p.tag, 1), ("type", p.type, 1), ("x", p.x, 3), ("v", p.v, 3), ("f", p.f, 3)]
    columns += [(name, p.arrays[name], 1 if name == "radius" else 3)
                for name in ("radius", "omega") if p.has(name)]
    # one float table per rank (ids exact below 2**53), gathered whole
    local = np.column_stack([np.asarray(values[chosen], dtype=np.float64).reshape(len(chosen), width)
                             for _, values, width in columns])
    table = sim.comm.gather_rows(local)
    if not sim.comm.is_root:
        return None
    table = table[np.argsort(table[:, 0], kind="stable")]
    data, start = {}, 0
    for name, _, width in columns:
        block = table[:, start:start + width]
        data[name] = np.ascontiguousarray(block[:, 0] if width == 1 else block)
        start += width
    data["id"] = data["id"].astype(np.int64)
    data["type"] = data["type"].astype(np.int32)
    return data.pop("x"), data


def vertex_cells(n):
    return [("vertex", np.arange(n, dtype=np.int64).reshape(-1, 1))]


def mesh_walls(sim):
    """(fix id, fix) for every fix with a triangulated surface (module docstring)."""
    for ident, fix in sim.fixes.items():
        if isinstance(fix, TriangleSurface):
            yield ident, fix


def face_data(sim, fix):
    """Per-triangle values a mesh fix offers through ``face_data(sim)`` ({name: (m,) or (m, k)
    array}: fix mesh/surface/stress's force, pressure and shear), else {}."""
    return dict(fix.face_data(sim)) if isinstance(fix, SurfaceValues) else {}


class MeshDump(Dump):
    """A dump of one file per frame plus a series file; subclasses give the format:
    ``extensions``, ``example``, ``write_mesh(tmp, points, cells, point_data, time, cell_data)`` and
    ``render_series(frames, surface)``; ``series_suffix`` makes a series file's name from a frame
    pattern's."""
    extensions: tuple = ()
    example: str = ""
    series_suffix: str = ""
    Args = MeshDumpArgs

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.pattern = Pattern(args.file, self.extensions, self.example)
        directory = os.path.dirname(self.pattern.head) or "."
        if sim.comm.is_root:           # rank 0 alone writes
            try:
                with tempfile.NamedTemporaryFile(dir=directory, prefix=".pdps-probe-"):
                    pass
            except OSError as exc:
                raise ScriptError(f"cannot write dump files in {directory}: {exc.strerror}") from None
        self.series = Series(self.pattern.series() + self.series_suffix,
                             lambda frames: self.render_series(frames, False))
        self.wall_series = {}
        self.walls_written = {}     # fix id -> the static fix object whose surface is on disk

    def write_frame(self, path, points, cells, point_data, time, cell_data=None):
        replace_atomically(path, lambda tmp: self.write_mesh(tmp, points, cells, point_data, time,
                                                             cell_data or {}))

    def write(self, sim):
        frame = particle_frame(sim, self.group)
        if frame is None:
            return
        points, data = frame
        path = self.pattern.frame(sim.step)
        self.write_frame(path, points, vertex_cells(len(points)), data, sim.time)
        self.series.add(path, sim.time, empty=len(points) == 0)
        if self.args.walls:
            self.write_walls(sim)

    def write_walls(self, sim):
        for ident, fix in mesh_walls(sim):
            cells = [("triangle", np.asarray(fix.triangles, dtype=np.int64))]
            points = np.asarray(fix.vertices, dtype=np.float64)
            faces = face_data(sim, fix)
            if not fix.moving and not faces:
                if self.walls_written.get(ident) is not fix:
                    self.write_frame(self.pattern.wall(ident), points, cells, {}, sim.time)
                    self.walls_written[ident] = fix
                continue
            series = self.wall_series.get(ident)
            if series is None:
                series = self.wall_series[ident] = Series(
                    self.pattern.wall(ident) + self.series_suffix,
                    lambda frames: self.render_series(frames, True))
            path = self.pattern.wall(ident, sim.step)
            self.write_frame(path, points, cells, {}, sim.time,
                             {name: [values] for name, values in faces.items()})
            series.add(path, sim.time)

    def write_mesh(self, tmp, points, cells, point_data, time, cell_data):
        raise NotImplementedError

    def render_series(self, frames, surface):
        raise NotImplementedError
