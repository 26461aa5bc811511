"""Dump ``image``: a rendered picture of the group's particles every N steps, as LIGGGHTS 3.8.0's and
LAMMPS's dump image draw it (render.py: camera, lights, shading, SSAO).

Syntax::

    dump ID GROUP image N FILE COLOR DIAMETER [keyword value ...]

- FILE has a ``*``, replaced by the step (one picture per file). A name ending in ``.jpg``/``.jpeg``
  (either case) is written as JPEG (quality 85, as LIGGGHTS's libjpeg call), ``.png``/``.PNG`` as
  PNG, any other as binary PPM (P6), gzip-compressed where the name ends in ``.gz`` (as LAMMPS
  built with gzip; LIGGGHTS 3.8.0 here was built without it, and without PNG).
- COLOR: ``type`` (the type's color: red, green, blue, yellow, aqua, cyan, then again from red),
  ``element`` (the color of the type's element, dump_modify element; C by default), or a per-atom
  attribute read through the color map (``dump_modify amap``; default min blue to max red).
- DIAMETER: ``type`` (the type's diameter, 1.0 unless ``dump_modify adiam``), ``element``, or a
  per-atom attribute (``diameter``, ``radius``, ...); a particle whose diameter is <= 0 is not drawn.
- Attributes: ``id type mass x y z xs ys zs xu yu zu ix iy iz vx vy vz fx fy fz q radius diameter
  omegax omegay omegaz tqx tqy tqz``, ``c_ID``, ``c_ID[k]``, ``f_ID``, ``f_ID[k]``, ``v_NAME``
  (as dump custom's).

Keywords (defaults as LIGGGHTS's):

- ``adiam D``: every particle of diameter D (distance).
- ``atom yes|no``: draw the particles (yes).
- ``bond COLOR WIDTH``: COLOR ``atom`` (each half in its particle's color), ``type`` (bond type's
  color, dump_modify bcolor) or ``none``; WIDTH a diameter (distance), ``atom`` (the smaller
  particle's), ``type`` (dump_modify bdiam, 0.5) or ``none``. Default ``atom 0.5`` in a scene with
  bonds, none without; a bond is drawn when both its particles are; one that crosses a periodic
  boundary is drawn as two halves from each particle towards its partner's nearest image.
- ``size W H``: pixels (512 512).
- ``view THETA PHI``: degrees from +z, and about z from +x (60 30; 0 0 in 2-d). Numbers or v_NAME.
- ``center s|d CX CY CZ``: the point looked at, as fractions of the box (s 0.5 0.5 0.5); ``s``:
  placed once, at the dump command; ``d``: again for each picture. Numbers or v_NAME (then d).
- ``up UX UY UZ``: the direction that is up in the picture (0 0 1; 0 1 0 in 2-d). Numbers or v_NAME.
- ``zoom Z``: > 0, the box appears Z times larger (1). Number or v_NAME.
- ``persp P``: 0 only (the default, no perspective). LIGGGHTS 3.8.0 refuses every persp ("Dump
  image persp option is not yet supported"), LAMMPS 22 Jul 2025 has none (measured).
- ``box yes|no D``: the box's 12 edges, of diameter D times the shortest box edge (yes 0.02).
- ``axes yes|no L D``: x, y, z axes in red, green, blue from 10 % of the longest edge below the
  box's lower corner, L times each edge long, D times the shortest edge thick (no). Edges and axes of
  diameter 0 (or axes of length 0) are not drawn; LIGGGHTS 3.8.0 divides by their zero size and
  leaves a stray black pixel or so (measured: one, in a 100 by 75 picture of the bed).
- ``shiny S``: 0 to 1, the specular highlight's strength and sharpness (1).
- ``ssao yes|no SEED F``: screen-space ambient occlusion of strength F (0 to 1), jittered with a
  RanMars generator of SEED (in the LIGGGHTS dialect a prime > 10000, as LIGGGHTS asks); no.

dump_modify keywords: ``acolor TYPES C`` (C a color or C1/C2/... given in turn), ``adiam TYPES D``,
``amap lo hi style delta N entries...`` (colors.py), ``backcolor C`` (black), ``bcolor BONDTYPES
C``, ``bdiam BONDTYPES D``, ``boxcolor C`` (yellow), ``color NAME R G B`` (a new color, each 0-1),
``element E1 ... EN`` (one per type), plus every and first. Colors are the 140 names of colors.py.

The view is fixed when the dump is defined (the box then) unless a view value is a variable or the
center is ``d``. In a parallel run rank 0 gathers the particles drawn (id, position, color and
diameter values) and draws them in id order: the picture is the same on any number of ranks, and
the same as LIGGGHTS's on one (LIGGGHTS on several ranks jitters SSAO with one generator per rank).
Where LIGGGHTS 3.8.0 departs from its manual pdps follows the manual: LIGGGHTS refuses every
discrete color map (it reads ``min``/``max`` of a ``d`` entry into the wrong slot) and its dump
movie every keyword (measured here).

Example::

    dump pic all image 1000 grains.*.png type diameter size 640 480 view 80 -30 zoom 1.5 box no 0.0
    dump_modify pic acolor 1 gold acolor 2 steelblue backcolor white
"""

import gzip
import math
import os
import re
import tempfile
from typing import Literal

import numpy as np

from pdps_core.api import (Dump, FloatOrVariable, PeratomReference, ScriptError, SimulationError, StyleArgs,
                           VariableRef, keyword, observables, param, type_range)

from . import render
from .colors import TYPE_COLORS, ColorMap, Palette, element
from .ranmars import RanMars

MY_PI = render.MY_PI
VECTOR = {"x": ("x", 0), "y": ("x", 1), "z": ("x", 2), "vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2),
          "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2), "ix": ("image", 0), "iy": ("image", 1),
          "iz": ("image", 2), "omegax": ("omega", 0), "omegay": ("omega", 1), "omegaz": ("omega", 2),
          "tqx": ("torque", 0), "tqy": ("torque", 1), "tqz": ("torque", 2)}
SPECIAL = ("id", "mass", "xs", "ys", "zs", "xu", "yu", "zu", "q", "radius", "diameter")
NEEDED = {"radius": "radius", "diameter": "radius", "q": "q"}
REFERENCE = re.compile(r"^(c|f|v)_([A-Za-z0-9_]+)(?:\[(\d+)\])?$")
YesNo = Literal["yes", "no"]
MAX_PIXELS = 50_000_000


def _is_prime(n):
    if n < 2:
        return False
    k = 2
    while k * k <= n:
        if n % k == 0:
            return False
        k += 1
    return True


def _file_kind(path):
    for suffix, kind in ((".jpg", "jpg"), (".JPG", "jpg"), (".jpeg", "jpg"), (".JPEG", "jpg"),
                         (".png", "png"), (".PNG", "png")):
        if len(path) > len(suffix) and path.endswith(suffix):
            return kind
    return "ppm"


class DumpImage(Dump):
    name = "image"
    usage = "dump ID GROUP image N FILE.*.ppm|jpg|png COLOR DIAMETER [keyword value ...]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        color: str
        diameter: str
        adiam: float | None = keyword(None, gt=0, unit="distance")
        atom: YesNo = keyword("yes")
        bond: tuple[str, str] | None = keyword(None)
        size: tuple[int, int] = keyword((512, 512), unit=("1", "1"))
        view: tuple[FloatOrVariable, FloatOrVariable] | None = keyword(None, unit=("degrees", "degrees"))
        center: tuple[Literal["s", "d"], FloatOrVariable, FloatOrVariable, FloatOrVariable] = keyword(
            ("s", 0.5, 0.5, 0.5), unit=("1", "dimensionless", "dimensionless", "dimensionless"))
        up: tuple[FloatOrVariable, FloatOrVariable, FloatOrVariable] | None = keyword(
            None, unit=("dimensionless", "dimensionless", "dimensionless"))
        zoom: FloatOrVariable = keyword(1.0, unit="dimensionless")
        persp: FloatOrVariable = keyword(0.0, unit="dimensionless")
        box: tuple[YesNo, float] = keyword(("yes", 0.02), unit=("1", "dimensionless"))
        axes: tuple[YesNo, float, float] = keyword(("no", 0.0, 0.0), unit=("1", "dimensionless", "dimensionless"))
        shiny: float = keyword(1.0, ge=0.0, le=1.0, unit="dimensionless")
        ssao: tuple[YesNo, int, float] | None = keyword(None, unit=("1", "1", "dimensionless"))

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.path = args.file
        self.check_file(sim, args.file)
        self.kind = _file_kind(args.file)
        width, height = args.size
        if width <= 0 or height <= 0:
            raise ScriptError(f"size must be two whole numbers > 0 (got {width} {height})")
        if width * height > MAX_PIXELS:
            raise ScriptError(f"size {width} {height}: at most {MAX_PIXELS:.0e} pixels (27 bytes each in the "
                              "renderer's buffers)")
        self.width, self.height = width, height
        ntypes = sim.ntypes
        self.palette = Palette()
        self.colormap = ColorMap(self.palette)
        self.type_colors = np.array([[0.0, 0.0, 0.0]] + [self.palette.rgb(TYPE_COLORS[(t - 1) % 6])
                                                        for t in range(1, ntypes + 1)])
        self.type_diameters = np.ones(ntypes + 1)
        self.elements = ["C"] * (ntypes + 1)
        self.background = (0, 0, 0)
        self.box_color = self.palette.rgb("yellow")
        self.color_kind, self.color_ref = self._attribute(sim, args.color, "color")
        self.diameter_kind, self.diameter_ref = self._attribute(sim, args.diameter, "diameter")
        if args.adiam is not None:
            self.diameter_kind = "number"
        self.draw_atoms = args.atom == "yes"
        self._bonds(sim, args.bond)
        self._view(sim, args)
        for name, values in (("box", args.box), ("axes", args.axes)):
            if any(v < 0.0 for v in values[1:]):
                raise ScriptError(f"{name}: the lengths and diameters must be >= 0 (got {' '.join(map(str, values))})")
        self.random = None
        self.ssao_on, self.ssao_strength = False, 0.0
        if args.ssao is not None:
            self._ssao(sim, args.ssao)
        self.camera = render.Camera()
        self.picture = None              # rank 0's buffers, made at its first picture
        self.frames = 0
        lo, hi = self._box(sim)
        self.center = self._center(sim, lo, hi)
        if not self.dynamic_view:
            try:
                self._set_camera(sim, lo, hi)
            except SimulationError as exc:
                raise ScriptError(str(exc).split(": ", 1)[1]) from None

    # ---- the words of the dump line ------------------------------------------------------------
    def check_file(self, sim, path):
        if "*" not in path:
            raise ScriptError(f"dump image writes one picture per file: put a * (the step) in {path}")
        if "%" in path:
            raise ScriptError(f"per-processor dump files (% in {path}) are not supported: rank 0 writes each picture")
        if sim.comm.is_root:             # rank 0 alone writes: its folder must take files now
            try:
                with tempfile.NamedTemporaryFile(dir=os.path.dirname(path) or ".", prefix=".pdps-probe-"):
                    pass
            except OSError as exc:
                raise ScriptError(f"cannot write pictures {path}: {exc.strerror}") from None

    def _attribute(self, sim, word, what):
        if word in ("type", "element"):
            return word, None
        if REFERENCE.match(word):
            return "reference", PeratomReference(sim, word, f"dump image {what} {word}")
        if word not in VECTOR and word not in SPECIAL:
            raise ScriptError(f"dump image {what} {word} is not an attribute pdps reads (type, element, "
                              f"{', '.join([*SPECIAL, *VECTOR])}, c_ID, c_ID[k], f_ID, f_ID[k], v_NAME)")
        needed = NEEDED.get(word) or VECTOR.get(word, (None,))[0]
        if needed in ("radius", "q", "omega", "torque") and not sim.particles.has(needed):
            raise ScriptError(f"dump image {what} {word} needs per-particle {needed}, which these particles lack")
        return "attribute", word

    def _bonds(self, sim, bond):
        nbondtypes = sim.nbondtypes
        self.bond_color, self.bond_width = ("atom", 0.5) if nbondtypes else (None, None)
        if bond is not None:
            if not nbondtypes:
                raise ScriptError("dump image bond: this box has no bond types")
            color, width = bond
            if color not in ("atom", "type", "none"):
                raise ScriptError(f"bond color must be atom, type or none (got {color})")
            if width in ("atom", "type", "none"):
                value = width
            else:
                try:
                    value = float(width)
                except ValueError:
                    raise ScriptError(f"bond width must be a number, atom, type or none (got {width})") from None
                if not (math.isfinite(value) and value > 0.0):
                    raise ScriptError(f"bond width must be > 0 (got {width})")
            self.bond_color, self.bond_width = color, value
            if color == "none" or width == "none":
                self.bond_color = self.bond_width = None
        self.bond_type_colors = np.array([[0.0, 0.0, 0.0]] + [self.palette.rgb(TYPE_COLORS[(t - 1) % 6])
                                                             for t in range(1, nbondtypes + 1)])
        self.bond_type_diameters = np.full(nbondtypes + 1, 0.5)

    def _view(self, sim, args):
        two_d = sim.dimension == 2
        self.theta = 0.0 if two_d else 60.0 * MY_PI / 180.0
        self.phi = 0.0 if two_d else 30.0 * MY_PI / 180.0
        self.theta_word = self.phi_word = None
        if args.view is not None:
            theta, phi = args.view
            if isinstance(theta, VariableRef):
                self.theta_word = theta
            else:
                self.theta = self._theta(theta)
            if isinstance(phi, VariableRef):
                self.phi_word = phi
            else:
                self.phi = phi * (MY_PI / 180.0)
        self.up = [0.0, 1.0, 0.0] if two_d else [0.0, 0.0, 1.0]
        self.up_words = list(args.up) if args.up is not None else list(self.up)
        self.up = [0.0 if isinstance(word, VariableRef) else float(word) for word in self.up_words]
        flag, *center = args.center
        self.center_words = center
        self.center_dynamic = flag == "d" or any(isinstance(c, VariableRef) for c in center)
        if not isinstance(args.zoom, VariableRef) and args.zoom <= 0.0:
            raise ScriptError(f"zoom must be > 0 (got {args.zoom})")
        if isinstance(args.persp, VariableRef) or args.persp != 0.0:
            raise ScriptError("persp: pdps draws no perspective (LIGGGHTS 3.8.0 refuses persp: \"not yet "
                              "supported\"; LAMMPS has none); leave persp out, or give 0")
        self.zoom_word = args.zoom
        self.dynamic_view = (self.center_dynamic or self.theta_word is not None or self.phi_word is not None
                             or any(isinstance(u, VariableRef) for u in self.up_words)
                             or isinstance(args.zoom, VariableRef))

    @staticmethod
    def _theta(degrees):
        if not 0.0 <= degrees <= 180.0:
            raise ScriptError(f"view: theta must be from 0 to 180 degrees (got {degrees:g})")
        return degrees * (MY_PI / 180.0)

    def _ssao(self, sim, words):
        flag, seed, strength = words
        if not 0.0 <= strength <= 1.0:
            raise ScriptError(f"ssao: the strength must be from 0.0 to 1.0 (got {strength:g})")
        if sim.dialect.name == "liggghts" and (seed < 10000 or not _is_prime(seed)):
            raise ScriptError(f"ssao: LIGGGHTS asks for a seed > 10000 that is a prime number (got {seed}); "
                              "e.g. 15485863, 32452843, 49979687")
        try:
            self.random = RanMars(seed)
        except ValueError as exc:
            raise ScriptError(f"ssao: {exc}") from None
        self.ssao_on = flag == "yes"
        self.ssao_strength = strength

    @property
    def ssao_enabled(self):
        return self.ssao_on

    # ---- dump_modify -----------------------------------------------------------------------------
    def modify_words(self, sim, keyword, rest):
        counts = {"acolor": 2, "adiam": 2, "backcolor": 1, "bcolor": 2, "bdiam": 2, "boxcolor": 1, "color": 4,
                  "element": sim.ntypes}
        if keyword in counts:
            return counts[keyword]
        if keyword == "amap":
            if len(rest) < 5:
                raise ScriptError("amap needs lo hi style delta N and N entries")
            if len(rest[2]) != 2 or rest[2][0] not in "cds":
                raise ScriptError(f"amap: style must be c, d or s followed by a or f (got {rest[2]})")
            try:
                n = int(rest[4])
            except ValueError:
                raise ScriptError(f"amap: N must be a whole number (got {rest[4]})") from None
            if n < 1:
                raise ScriptError(f"amap: N must be >= 1 (got {n})")
            return 5 + {"c": 2, "d": 3, "s": 1}[rest[2][0]] * n
        return None

    def modify(self, sim, keyword, values):
        if keyword in ("acolor", "bcolor"):
            count = sim.ntypes if keyword == "acolor" else sim.nbondtypes
            if keyword == "bcolor" and not count:
                raise ScriptError("dump_modify bcolor: this box has no bond types")
            lo, hi = type_range(values[0], count, "type" if keyword == "acolor" else "bond type")
            names = values[1].split("/")
            table = self.type_colors if keyword == "acolor" else self.bond_type_colors
            for m, t in enumerate(range(lo, hi + 1)):
                table[t] = self.palette.rgb(names[m % len(names)])
        elif keyword in ("adiam", "bdiam"):
            count = sim.ntypes if keyword == "adiam" else sim.nbondtypes
            if keyword == "bdiam" and not count:
                raise ScriptError("dump_modify bdiam: this box has no bond types")
            lo, hi = type_range(values[0], count, "type" if keyword == "adiam" else "bond type")
            diameter = _positive(values[1], keyword)
            (self.type_diameters if keyword == "adiam" else self.bond_type_diameters)[lo:hi + 1] = diameter
        elif keyword == "amap":
            self.colormap.reset(values, self.palette)
        elif keyword == "backcolor":
            rgb = self.palette.rgb(values[0], "backcolor")
            self.background = tuple(int(c * 255.0) for c in rgb)
        elif keyword == "boxcolor":
            self.box_color = self.palette.rgb(values[0], "boxcolor")
        elif keyword == "color":
            self.palette.add(values[0], *(_number(v, "color") for v in values[1:]))
        elif keyword == "element":
            if "element" in (self.color_kind, self.diameter_kind):
                for name in values:
                    element(name)
            self.elements[1:] = values
        else:
            super().modify(sim, keyword, values)

    # ---- the view --------------------------------------------------------------------------------
    @staticmethod
    def _box(sim):
        return sim.box.lo.tolist(), sim.box.hi.tolist()

    def _center(self, sim, lo, hi):
        c = [float(sim.evaluate(w)) for w in self.center_words]
        return [lo[d] + c[d] * (hi[d] - lo[d]) for d in range(3)]

    def _set_camera(self, sim, lo, hi):
        theta, phi = self.theta, self.phi
        if self.theta_word is not None:
            theta = self._theta(float(sim.evaluate(self.theta_word)))
        if self.phi_word is not None:
            phi = float(sim.evaluate(self.phi_word)) * (MY_PI / 180.0)
        # as LIGGGHTS: the up vector is kept normalised, and a variable sets its component anew, so
        # the others are those of the last picture's normalised vector
        up = [float(sim.evaluate(word)) if isinstance(word, VariableRef) else self.up[d]
              for d, word in enumerate(self.up_words)]
        zoom = float(sim.evaluate(self.zoom_word))
        if not zoom > 0.0:
            raise SimulationError(f"dump {self.id}: zoom must be > 0 (got {zoom:g})")
        try:
            self.camera.set(theta, phi, up, zoom, self.args.shiny, self.ssao_enabled, self.ssao_strength,
                            lo, hi, self.center, self.height)
        except ValueError as exc:
            raise SimulationError(f"dump {self.id}: {exc} (up {' '.join(f'{u:g}' for u in up)})") from None
        self.up = self.camera.up

    # ---- a picture ---------------------------------------------------------------------------------
    def _values(self, sim, kind, word, chosen):
        p = sim.particles
        if kind in ("type", "element"):
            return p.type[chosen].astype(np.float64)
        if kind == "number":                 # adiam: the attribute named is not read
            return np.zeros(len(chosen))
        if kind == "reference":
            return np.asarray(word.values(sim), dtype=np.float64)[chosen]
        if word in VECTOR:
            name, d = VECTOR[word]
            return np.asarray(p.arrays[name][chosen, d], dtype=np.float64)
        box = sim.box
        if word == "id":
            return p.tag[chosen].astype(np.float64)
        if word == "mass":
            return observables.masses(sim)[chosen]
        if word == "q":
            return p.q[chosen]
        if word in ("xs", "ys", "zs"):
            d = "xyz".index(word[0])
            return (p.x[chosen, d] - box.lo[d]) / box.length[d]
        if word in ("xu", "yu", "zu"):
            d = "xyz".index(word[0])
            return p.x[chosen, d] + p.image[chosen, d] * box.length[d]
        if word == "radius":
            return p.radius[chosen].copy()
        return 2.0 * p.radius[chosen]

    def _gather(self, sim):
        """Rank 0's table of every particle drawn, in id order: tag, type, x y z, color value,
        diameter value; and of their bonds: tag1, tag2, type."""
        p = sim.particles
        chosen = np.flatnonzero(sim.groups.select(sim, self.group))
        local = np.column_stack([p.tag[chosen].astype(np.float64), p.type[chosen].astype(np.float64),
                                 p.x[chosen], self._values(sim, self.color_kind, self.color_ref, chosen),
                                 self._values(sim, self.diameter_kind, self.diameter_ref, chosen)])
        table = sim.comm.gather_rows(local.reshape(len(chosen), 7))
        bonds = None
        if self.bond_color is not None and p.has("num_bond"):
            slots = p.bond_type.shape[1]
            stored = (np.arange(slots) < p.num_bond[chosen, None]) & (p.bond_type[chosen] != 0)
            rows, slot = np.nonzero(stored)
            mine = np.column_stack([p.tag[chosen[rows]], p.bond_atom[chosen[rows], slot],
                                    p.bond_type[chosen[rows], slot]]).astype(np.float64)
            bonds = sim.comm.gather_rows(mine.reshape(len(rows), 3))
        if table is not None:
            table = table[np.argsort(table[:, 0], kind="stable")]
            if bonds is not None:
                bonds = bonds[np.argsort(bonds[:, 0], kind="stable")]
        return table, bonds

    def _colors(self, kind, types, values):
        if kind == "type":
            return self.type_colors[types]
        if kind == "element":
            table = np.array([element(name)[0] for name in self.elements])
            return table[types]
        out = np.empty((len(values), 3))
        render.map_colors(values, *self.map_table, out)
        return out

    def _diameters(self, types, values):
        if self.diameter_kind == "number":
            return np.full(len(types), self.args.adiam)
        if self.diameter_kind == "type":
            return self.type_diameters[types]
        if self.diameter_kind == "element":
            table = np.array([element(name)[1] for name in self.elements], dtype=np.float64)
            return table[types]
        return values

    def render(self, sim):
        """Draw this step's picture on rank 0 (None elsewhere): the picture's rows, top row first."""
        lo, hi = self._box(sim)
        if self.center_dynamic:
            self.center = self._center(sim, lo, hi)
        if self.dynamic_view:
            self._set_camera(sim, lo, hi)
        table, bonds = self._gather(sim)
        if table is None:
            return None
        types = table[:, 1].astype(np.int64)
        if self.color_kind in ("attribute", "reference") and self.colormap.dynamic:
            values = table[:, 5]
            low = values.min() if len(values) else 1.0e20
            high = values.max() if len(values) else -1.0e20
            if len(values):
                self.colormap.minmax(low, high)
        self.map_table = self.colormap.table()
        colors = self._colors(self.color_kind, types, table[:, 5])
        diameters = self._diameters(types, table[:, 6])
        x = np.ascontiguousarray(table[:, 2:5])
        if self.picture is None:
            self.picture = render.Picture(self.width, self.height)
        pic, p = self.picture, self.camera.params
        pic.clear(self.background)
        args = (p, pic.width, pic.height, pic.depth, pic.surface, pic.rgb)
        if self.draw_atoms:
            render.draw_spheres(*args, x, np.ascontiguousarray(colors), np.ascontiguousarray(diameters))
        if bonds is not None and len(bonds):
            ends, bond_colors, bond_diameters = self._bond_cylinders(sim, table, x, colors, diameters, bonds)
            render.draw_cylinders(*args, ends, bond_colors, bond_diameters)
        if self.args.box[0] == "yes":
            self._draw_box(sim, args, lo, hi)
        if self.args.axes[0] == "yes":
            self._draw_axes(sim, args, lo, hi)
        if self.ssao_enabled:
            render.ssao(*args, self.camera.ssao_radius, self.camera.ssao_samples,
                        self.random.state, self.random.indices)
        return pic.rows()

    def _bond_cylinders(self, sim, table, x, colors, diameters, bonds):
        """The cylinders of the bonds whose particles are both drawn: (ends (n, 2, 3), colors, diameters).
        A bond is one cylinder, or two halves (each from its particle towards the other's nearest
        image) where its colors are its particles' or it crosses a periodic boundary."""
        tags = table[:, 0]
        i = np.searchsorted(tags, bonds[:, 0])
        j = np.searchsorted(tags, bonds[:, 1])
        i, j = np.minimum(i, len(tags) - 1), np.minimum(j, len(tags) - 1)
        drawn = (tags[i] == bonds[:, 0]) & (tags[j] == bonds[:, 1])
        i, j, btype = i[drawn], j[drawn], np.abs(bonds[drawn, 2]).astype(np.int64)
        if self.bond_width == "atom":
            diameter = np.minimum(diameters[i], diameters[j])
        elif self.bond_width == "type":
            diameter = self.bond_type_diameters[btype]
        else:
            diameter = np.full(len(i), float(self.bond_width))
        length = np.asarray(sim.box.length, dtype=np.float64)
        delta = x[j] - x[i]
        far = np.asarray(sim.box.periodic, dtype=bool) & (np.abs(delta) > 0.5 * length)
        shifted = np.where(far, np.where(delta < 0.0, delta + length, delta - length), delta)
        halves = far.any(axis=1) | (self.bond_color == "atom")
        if self.bond_color == "atom":
            first, second = colors[i], colors[j]
        else:
            first = second = self.bond_type_colors[btype]
        whole = ~halves
        ends = np.concatenate([np.stack([x[i][whole], x[j][whole]], axis=1),
                               np.stack([x[i][halves], x[i][halves] + 0.5 * shifted[halves]], axis=1),
                               np.stack([x[j][halves] - 0.5 * shifted[halves], x[j][halves]], axis=1)])
        # LIGGGHTS draws each bond's pieces in turn: the order matters only where two depths tie
        order = np.concatenate([np.flatnonzero(whole), np.flatnonzero(halves),
                                np.flatnonzero(halves)])
        piece = np.concatenate([np.zeros(whole.sum()), np.zeros(halves.sum()), np.ones(halves.sum())])
        sequence = np.lexsort((piece, order))
        out_colors = np.concatenate([first[whole], first[halves], second[halves]])
        out_diameters = np.concatenate([diameter[whole], diameter[halves], diameter[halves]])
        return (np.ascontiguousarray(ends[sequence]), np.ascontiguousarray(out_colors[sequence]),
                np.ascontiguousarray(out_diameters[sequence]))

    def _shortest(self, sim, lo, hi):
        edges = [hi[d] - lo[d] for d in range(3 if sim.dimension == 3 else 2)]
        shortest = min(edges[0], edges[1])
        return min(shortest, edges[2]) if len(edges) == 3 else shortest

    def _draw_box(self, sim, args, lo, hi):
        diameter = self._shortest(sim, lo, hi) * self.args.box[1]
        if diameter <= 0.0:
            return
        corners = [[(lo, hi)[(k >> d) & 1][d] for d in range(3)] for k in range(8)]
        edges = ((0, 1), (2, 3), (0, 2), (1, 3), (0, 4), (1, 5), (2, 6), (3, 7), (4, 5), (6, 7), (4, 6), (5, 7))
        ends = np.array([(corners[a], corners[b]) for a, b in edges], dtype=np.float64)
        render.draw_cylinders(*args, ends, np.tile(self.box_color, (12, 1)), np.full(12, diameter))

    def _draw_axes(self, sim, args, lo, hi):
        _, length, thickness = self.args.axes
        diameter = self._shortest(sim, lo, hi) * thickness
        if diameter <= 0.0 or length <= 0.0:
            return
        edges = [hi[d] - lo[d] for d in range(3 if sim.dimension == 3 else 2)]
        offset = max(edges[0], edges[1])
        if len(edges) == 3:
            offset = max(offset, edges[2])
        offset *= 0.1
        axes = [[lo[0], lo[1], lo[2]], [hi[0], lo[1], lo[2]], [lo[0], hi[1], lo[2]], [lo[0], lo[1], hi[2]]]
        axes = [[c - offset for c in corner] for corner in axes]
        for k in (1, 2, 3):
            axes[k] = [axes[0][d] + length * (axes[k][d] - axes[0][d]) for d in range(3)]
        ends = np.array([(axes[0], axes[k]) for k in (1, 2, 3)], dtype=np.float64)
        colors = np.array([self.palette.rgb(name) for name in ("red", "green", "blue")])
        render.draw_cylinders(*args, ends, colors, np.full(3, diameter))

    def write(self, sim):
        rows = self.render(sim)
        self.frames += 1
        if rows is None:
            return
        path = self.path.replace("*", str(sim.step))
        try:
            write_picture(path, rows, self.kind)
        except OSError as exc:
            raise SimulationError(f"dump {self.id}: cannot write {path}: {exc.strerror}") from None


def ppm_bytes(rows):
    """A binary PPM (P6) of (height, width, 3) bytes, top row first."""
    height, width = rows.shape[:2]
    return f"P6\n{width} {height}\n255\n".encode() + np.ascontiguousarray(rows).tobytes()


def write_picture(path, rows, kind):
    """Write a picture: PPM, or through Pillow JPEG (quality 85, as LIGGGHTS) or PNG."""
    if kind == "ppm":
        with (gzip.open if path.endswith(".gz") else open)(path, "wb") as handle:
            handle.write(ppm_bytes(rows))
        return
    from PIL import Image            # only a dump that writes JPEG or PNG loads Pillow
    picture = Image.fromarray(np.ascontiguousarray(rows), "RGB")
    if kind == "jpg":
        picture.save(path, "JPEG", quality=85)
    else:
        picture.save(path, "PNG", compress_level=9)


def _number(word, what):
    try:
        value = float(word)
    except ValueError:
        raise ScriptError(f"{what}: {word} is not a number") from None
    if not math.isfinite(value):
        raise ScriptError(f"{what}: {word} is not a finite number")
    return value


def _positive(word, what):
    value = _number(word, what)
    if value <= 0.0:
        raise ScriptError(f"{what}: the diameter must be > 0 (got {word})")
    return value
