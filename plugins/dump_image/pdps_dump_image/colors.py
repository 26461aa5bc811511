"""Colors of dump image and movie: the named colors, the elements' colors and sizes, and color maps.

- ``COLORS``: the 140 color names LIGGGHTS 3.8.0 and LAMMPS know, with their 0-255 RGB values as
  those programs define them (mostly the X11/CSS ones; their ``blanchedalmond``, ``peachpuff`` and
  ``tomato`` differ from CSS's, and are kept as they are, for the same pictures). A color is the
  triple divided by 255.
- ``ELEMENTS``: each element's RGB (0-1) and diameter (distance units), the AtomEye table
  (Mendeleyev.c) LIGGGHTS and LAMMPS draw ``element`` atoms with.
- ``Palette``: the names a dump knows: ``dump_modify color NAME R G B`` adds or redefines one; the
  dump's names are searched first, then ``COLORS``.
- ``ColorMap``: ``dump_modify amap lo hi style delta N entries...`` (the dump_modify page): a per-atom
  value to a color, continuous (linear between entries), discrete (the first entry whose lo <= value
  <= hi) or sequential (bins of width delta, colors in turn), absolute or fractional.
"""

import numpy as np

from pdps_core.api import ScriptError

COLORS = {
    "aliceblue": (240, 248, 255), "antiquewhite": (250, 235, 215), "aqua": (0, 255, 255),
    "aquamarine": (127, 255, 212), "azure": (240, 255, 255), "beige": (245, 245, 220),
    "bisque": (255, 228, 196), "black": (0, 0, 0), "blanchedalmond": (255, 255, 205), "blue": (0, 0, 255),
    "blueviolet": (138, 43, 226), "brown": (165, 42, 42), "burlywood": (222, 184, 135),
    "cadetblue": (95, 158, 160), "chartreuse": (127, 255, 0), "chocolate": (210, 105, 30),
    "coral": (255, 127, 80), "cornflowerblue": (100, 149, 237), "cornsilk": (255, 248, 220),
    "crimson": (220, 20, 60), "cyan": (0, 255, 255), "darkblue": (0, 0, 139), "darkcyan": (0, 139, 139),
    "darkgoldenrod": (184, 134, 11), "darkgray": (169, 169, 169), "darkgreen": (0, 100, 0),
    "darkkhaki": (189, 183, 107), "darkmagenta": (139, 0, 139), "darkolivegreen": (85, 107, 47),
    "darkorange": (255, 140, 0), "darkorchid": (153, 50, 204), "darkred": (139, 0, 0),
    "darksalmon": (233, 150, 122), "darkseagreen": (143, 188, 143), "darkslateblue": (72, 61, 139),
    "darkslategray": (47, 79, 79), "darkturquoise": (0, 206, 209), "darkviolet": (148, 0, 211),
    "deeppink": (255, 20, 147), "deepskyblue": (0, 191, 255), "dimgray": (105, 105, 105),
    "dodgerblue": (30, 144, 255), "firebrick": (178, 34, 34), "floralwhite": (255, 250, 240),
    "forestgreen": (34, 139, 34), "fuchsia": (255, 0, 255), "gainsboro": (220, 220, 220),
    "ghostwhite": (248, 248, 255), "gold": (255, 215, 0), "goldenrod": (218, 165, 32),
    "gray": (128, 128, 128), "green": (0, 128, 0), "greenyellow": (173, 255, 47),
    "honeydew": (240, 255, 240), "hotpink": (255, 105, 180), "indianred": (205, 92, 92),
    "indigo": (75, 0, 130), "ivory": (255, 240, 240), "khaki": (240, 230, 140), "lavender": (230, 230, 250),
    "lavenderblush": (255, 240, 245), "lawngreen": (124, 252, 0), "lemonchiffon": (255, 250, 205),
    "lightblue": (173, 216, 230), "lightcoral": (240, 128, 128), "lightcyan": (224, 255, 255),
    "lightgoldenrodyellow": (250, 250, 210), "lightgreen": (144, 238, 144), "lightgrey": (211, 211, 211),
    "lightpink": (255, 182, 193), "lightsalmon": (255, 160, 122), "lightseagreen": (32, 178, 170),
    "lightskyblue": (135, 206, 250), "lightslategray": (119, 136, 153), "lightsteelblue": (176, 196, 222),
    "lightyellow": (255, 255, 224), "lime": (0, 255, 0), "limegreen": (50, 205, 50),
    "linen": (250, 240, 230), "magenta": (255, 0, 255), "maroon": (128, 0, 0),
    "mediumaquamarine": (102, 205, 170), "mediumblue": (0, 0, 205), "mediumorchid": (186, 85, 211),
    "mediumpurple": (147, 112, 219), "mediumseagreen": (60, 179, 113), "mediumslateblue": (123, 104, 238),
    "mediumspringgreen": (0, 250, 154), "mediumturquoise": (72, 209, 204), "mediumvioletred": (199, 21, 133),
    "midnightblue": (25, 25, 112), "mintcream": (245, 255, 250), "mistyrose": (255, 228, 225),
    "moccasin": (255, 228, 181), "navajowhite": (255, 222, 173), "navy": (0, 0, 128),
    "oldlace": (253, 245, 230), "olive": (128, 128, 0), "olivedrab": (107, 142, 35), "orange": (255, 165, 0),
    "orangered": (255, 69, 0), "orchid": (218, 112, 214), "palegoldenrod": (238, 232, 170),
    "palegreen": (152, 251, 152), "paleturquoise": (175, 238, 238), "palevioletred": (219, 112, 147),
    "papayawhip": (255, 239, 213), "peachpuff": (255, 239, 213), "peru": (205, 133, 63),
    "pink": (255, 192, 203), "plum": (221, 160, 221), "powderblue": (176, 224, 230), "purple": (128, 0, 128),
    "red": (255, 0, 0), "rosybrown": (188, 143, 143), "royalblue": (65, 105, 225),
    "saddlebrown": (139, 69, 19), "salmon": (250, 128, 114), "sandybrown": (244, 164, 96),
    "seagreen": (46, 139, 87), "seashell": (255, 245, 238), "sienna": (160, 82, 45),
    "silver": (192, 192, 192), "skyblue": (135, 206, 235), "slateblue": (106, 90, 205),
    "slategray": (112, 128, 144), "snow": (255, 250, 250), "springgreen": (0, 255, 127),
    "steelblue": (70, 130, 180), "tan": (210, 180, 140), "teal": (0, 128, 128), "thistle": (216, 191, 216),
    "tomato": (253, 99, 71), "turquoise": (64, 224, 208), "violet": (238, 130, 238),
    "wheat": (245, 222, 179), "white": (255, 255, 255), "whitesmoke": (245, 245, 245),
    "yellow": (255, 255, 0), "yellowgreen": (154, 205, 50),
}

ELEMENTS = {
    "H": ((0.8, 0.8, 0.8), 0.35), "He": ((0.6431372549, 0.6666666667, 0.6784313725), 1.785),
    "Li": ((0.7, 0.7, 0.7), 1.45), "Be": ((0.6431372549, 0.6666666667, 0.6784313725), 1.05),
    "B": ((0.9, 0.4, 0), 0.85), "C": ((0.35, 0.35, 0.35), 0.72), "N": ((0.2, 0.2, 0.8), 0.65),
    "O": ((0.8, 0.2, 0.2), 0.6), "F": ((0.7, 0.85, 0.45), 0.5),
    "Ne": ((0.6431372549, 0.6666666667, 0.6784313725), 1.5662), "Na": ((0.6, 0.6, 0.6), 1.8),
    "Mg": ((0.6, 0.6, 0.7), 1.5), "Al": ((0.6431372549, 0.6666666667, 0.6784313725), 1.4255),
    "Si": ((0.6901960784, 0.768627451, 0.8705882353), 1.07), "P": ((0.1, 0.7, 0.3), 1),
    "S": ((0.95, 0.9, 0.2), 1), "Cl": ((0.15, 0.5, 0.1), 1),
    "Ar": ((0.6431372549, 0.6666666667, 0.6784313725), 1.8597), "K": ((0.5, 0.5, 0.5), 2.2),
    "Ca": ((0.8, 0.8, 0.7), 1.8), "Sc": ((0.6431372549, 0.6666666667, 0.6784313725), 1.6),
    "Ti": ((0.6431372549, 0.6666666667, 0.6784313725), 1.4),
    "V": ((0.6431372549, 0.6666666667, 0.6784313725), 1.51995), "Cr": ((0, 0.8, 0), 1.44225),
    "Mn": ((0.6431372549, 0.6666666667, 0.6784313725), 1.4),
    "Fe": ((0.5176470588, 0.5764705882, 0.6529411765), 1.43325),
    "Co": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35),
    "Ni": ((0.257254902, 0.2666666667, 0.271372549), 1.35),
    "Cu": ((0.95, 0.7900735294, 0.01385869565), 1.278),
    "Zn": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35), "Ga": ((0.9, 0, 1), 1.3),
    "Ge": ((0.6431372549, 0.6666666667, 0.6784313725), 1.25), "As": ((1, 1, 0.3), 1.15),
    "Se": ((0.6431372549, 0.6666666667, 0.6784313725), 1.15), "Br": ((0.5, 0.08, 0.12), 1.15),
    "Kr": ((0.6431372549, 0.6666666667, 0.6784313725), 2.0223),
    "Rb": ((0.6431372549, 0.6666666667, 0.6784313725), 2.35),
    "Sr": ((0.6431372549, 0.6666666667, 0.6784313725), 2),
    "Y": ((0.6431372549, 0.6666666667, 0.6784313725), 1.8),
    "Zr": ((0.6431372549, 0.6666666667, 0.6784313725), 1.55),
    "Nb": ((0.6431372549, 0.6666666667, 0.6784313725), 1.6504),
    "Mo": ((0.6431372549, 0.6666666667, 0.6784313725), 1.3872),
    "Tc": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35),
    "Ru": ((0.6431372549, 0.6666666667, 0.6784313725), 1.3),
    "Rh": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35),
    "Pd": ((0.6431372549, 0.6666666667, 0.6784313725), 1.4),
    "Ag": ((0.6431372549, 0.6666666667, 0.6784313725), 1.6),
    "Cd": ((0.6431372549, 0.6666666667, 0.6784313725), 1.55),
    "In": ((0.6431372549, 0.6666666667, 0.6784313725), 1.55),
    "Sn": ((0.6431372549, 0.6666666667, 0.6784313725), 1.45),
    "Sb": ((0.6431372549, 0.6666666667, 0.6784313725), 1.45),
    "Te": ((0.6431372549, 0.6666666667, 0.6784313725), 1.4), "I": ((0.5, 0.1, 0.5), 1.4),
    "Xe": ((0.6431372549, 0.6666666667, 0.6784313725), 2.192),
    "Cs": ((0.6431372549, 0.6666666667, 0.6784313725), 2.6),
    "Ba": ((0.6431372549, 0.6666666667, 0.6784313725), 2.15),
    "La": ((0.6431372549, 0.6666666667, 0.6784313725), 1.95), "Ce": ((0.8, 0.8, 0), 1.85),
    "Pr": ((0.6431372549, 0.6666666667, 0.6784313725), 1.85),
    "Nd": ((0.6431372549, 0.6666666667, 0.6784313725), 1.85),
    "Pm": ((0.6431372549, 0.6666666667, 0.6784313725), 1.85),
    "Sm": ((0.6431372549, 0.6666666667, 0.6784313725), 1.85),
    "Eu": ((0.6431372549, 0.6666666667, 0.6784313725), 1.85), "Gd": ((1, 0.8431372549, 0), 1.8),
    "Tb": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Dy": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Ho": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Er": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Tm": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Yb": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Lu": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Hf": ((0.6431372549, 0.6666666667, 0.6784313725), 1.55),
    "Ta": ((0.6431372549, 0.6666666667, 0.6784313725), 1.6529),
    "W": ((0.6431372549, 0.6666666667, 0.6784313725), 1.5826),
    "Re": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35),
    "Os": ((0.6431372549, 0.6666666667, 0.6784313725), 1.3),
    "Ir": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35),
    "Pt": ((0.6431372549, 0.6666666667, 0.6784313725), 1.35), "Au": ((0.9, 0.8, 0), 1.35),
    "Hg": ((0.6431372549, 0.6666666667, 0.6784313725), 1.5),
    "Tl": ((0.6431372549, 0.6666666667, 0.6784313725), 1.9),
    "Pb": ((0.6431372549, 0.6666666667, 0.6784313725), 1.8),
    "Bi": ((0.6431372549, 0.6666666667, 0.6784313725), 1.6),
    "Po": ((0.6431372549, 0.6666666667, 0.6784313725), 1.9), "At": ((0.8, 0.2, 0.2), 1.6),
    "Rn": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Fr": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Ra": ((0.6431372549, 0.6666666667, 0.6784313725), 2.15),
    "Ac": ((0.6431372549, 0.6666666667, 0.6784313725), 1.95),
    "Th": ((0.6431372549, 0.6666666667, 0.6784313725), 1.8),
    "Pa": ((0.6431372549, 0.6666666667, 0.6784313725), 1.8),
    "U": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Np": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Pu": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Am": ((0.6431372549, 0.6666666667, 0.6784313725), 1.75),
    "Cm": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Bk": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0), "Cf": ((0.1, 0.7, 0.3), 1.6),
    "Es": ((0.1, 0.3, 0.7), 1.6), "Fm": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Md": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "No": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Lr": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Rf": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0), "Db": ((0.9, 0.8, 0), 1.6),
    "Sg": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Bh": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Hs": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
    "Mt": ((0.6431372549, 0.6666666667, 0.6784313725), 1.0),
}

# the colors of types 1, 2, 3, ... in turn (types 7, 8, ... start again)
TYPE_COLORS = ("red", "green", "blue", "yellow", "aqua", "cyan")


class Palette:
    """The color names one dump knows."""

    def __init__(self):
        self.user = {}

    def add(self, name, r, g, b):
        for value in (r, g, b):
            if not 0.0 <= value <= 1.0:
                raise ScriptError(f"color {name}: R, G and B must be from 0.0 to 1.0 (got {r} {g} {b})")
        self.user[name] = (r, g, b)

    def rgb(self, name, what="color"):
        """The (r, g, b) of a name, each 0..1."""
        if name in self.user:
            return self.user[name]
        if name in COLORS:
            return tuple(c / 255.0 for c in COLORS[name])
        raise ScriptError(f"{what} {name} is not a color name (dump_modify color NAME R G B defines one)")


def element(name):
    """(rgb, diameter) of an element symbol, as AtomEye's table."""
    if name not in ELEMENTS:
        raise ScriptError(f"dump image: {name} is not an element symbol this dump knows (H to Mt)")
    return ELEMENTS[name]


def _bound(word, allowed):
    """A map's lo/hi/value: a number, or min/max. LIGGGHTS reads a word not starting with a lowercase
    letter as a number."""
    if word in allowed:
        return word
    if word[:1].islower():
        raise ScriptError(f"amap: {word} is neither a number nor {' or '.join(allowed)}")
    try:
        value = float(word)
    except ValueError:
        raise ScriptError(f"amap: {word} is not a number") from None
    if not np.isfinite(value):
        raise ScriptError(f"amap: {word} is not a finite number")
    return value


class ColorMap:
    """A color map; the default is LIGGGHTS's: min blue to max red, continuous, fractional."""

    def __init__(self, palette):
        self.lo, self.hi = "min", "max"
        self.style, self.fractional = "c", True
        self.binsize = 1.0
        self.entries = [["min", palette.rgb("blue")], ["max", palette.rgb("red")]]
        self.current = (0.0, 1.0)

    @property
    def dynamic(self):
        return self.lo == "min" or self.hi == "max"

    def reset(self, words, palette):
        """``lo hi style delta N entry...``: the words of one amap keyword."""
        lo, hi = _bound(words[0], ("min",)), _bound(words[1], ("max",))
        if not isinstance(lo, str) and not isinstance(hi, str) and lo >= hi:
            raise ScriptError(f"amap: lo {words[0]} must be below hi {words[1]}")
        style = words[2]
        if len(style) != 2 or style[0] not in "cds" or style[1] not in "af":
            raise ScriptError(f"amap: style must be c, d or s followed by a or f (got {style})")
        binsize = 1.0
        if style[0] == "s":
            binsize = _number(words[3], "delta")
            if binsize <= 0.0:
                raise ScriptError(f"amap: delta must be > 0 for a sequential map (got {words[3]})")
        n = int(words[4])
        per = {"c": 2, "d": 3, "s": 1}[style[0]]
        entries, k = [], 5
        for _ in range(n):
            if style[0] == "c":
                entries.append([_bound(words[k], ("min", "max")), palette.rgb(words[k + 1], "amap color")])
            elif style[0] == "d":
                entries.append([_bound(words[k], ("min",)), _bound(words[k + 1], ("max",)),
                                palette.rgb(words[k + 2], "amap color")])
            else:
                entries.append([palette.rgb(words[k], "amap color")])
            k += per
        if style[0] == "c":
            if n < 2 or entries[0][0] != "min" or entries[-1][0] != "max":
                raise ScriptError("amap: a continuous map has 2 entries or more, the first min, the last max")
            inner = [entry[0] for entry in entries[1:-1]]
            if any(isinstance(value, str) for value in inner) or any(b <= a for a, b in zip(inner, inner[1:])):
                raise ScriptError("amap: the values between min and max must be numbers, increasing")
        elif style[0] == "d" and (entries[-1][0] != "min" or entries[-1][1] != "max"):
            raise ScriptError("amap: the last entry of a discrete map must be min max COLOR")
        self.lo, self.hi, self.style, self.fractional = lo, hi, style[0], style[1] == "f"
        self.binsize, self.entries = binsize, entries
        if not self.dynamic:
            self.minmax(lo, hi)

    def minmax(self, lowest, highest):
        """The range of this image: the map's bounds, min and max taken from the values drawn."""
        lo = lowest if self.lo == "min" else self.lo
        hi = highest if self.hi == "max" else self.hi
        if lo > hi:
            raise ScriptError(f"dump image: the color map's range is empty (lo {lo:g} > hi {hi:g})")
        self.current = (lo, hi)
        if self.style == "c" and not self.fractional:
            values = [lo] + [entry[0] for entry in self.entries[1:-1]] + [hi]
            if values[0] > values[1] or values[-2] > values[-1]:
                raise ScriptError(f"dump image: the color map's values leave its range {lo:g} to {hi:g}")

    def table(self):
        """The map as arrays for the kernel: (kind, fractional, lo, hi, binsize, values (n, 2), colors (n, 3)).
        ``values`` holds each entry's value (continuous: its value, min/max at the range's ends;
        discrete: its lo and hi)."""
        lo, hi = self.current
        low, high = (0.0, 1.0) if self.fractional else (lo, hi)
        n = len(self.entries)
        values, colors = np.zeros((n, 2)), np.zeros((n, 3))
        for i, entry in enumerate(self.entries):
            colors[i] = entry[-1]
            if self.style == "c":
                value = entry[0]
                values[i, 0] = low if value == "min" else high if value == "max" else value
            elif self.style == "d":
                values[i, 0] = low if entry[0] == "min" else entry[0]
                values[i, 1] = high if entry[1] == "max" else entry[1]
        return "cds".index(self.style), self.fractional, lo, hi, self.binsize, values, colors


def _number(word, what):
    try:
        value = float(word)
    except ValueError:
        raise ScriptError(f"amap: {what} {word} is not a number") from None
    if not np.isfinite(value):
        raise ScriptError(f"amap: {what} {word} is not a finite number")
    return value
