"""What the per-atom computes of this pack share: the named particle attributes (LAMMPS's compute
property/atom and dump custom names), unwrapped positions, and references to the per-atom values of
other computes and fixes (``c_ID``, ``c_ID[k]``, ``f_ID``, ``f_ID[k]``, k 0-based).

Every function returns values of this rank's owned particles, in their order.
"""

import re

import numpy as np

from pdps_core.api import Compute, ScriptError, observables

# attribute -> (per-atom array, component or None); the arrays beyond x v f image exist only when a
# particle style or a pair style asked for them
COMPONENTS = {"x": ("x", 0), "y": ("x", 1), "z": ("x", 2), "vx": ("v", 0), "vy": ("v", 1),
              "vz": ("v", 2), "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2), "ix": ("image", 0),
              "iy": ("image", 1), "iz": ("image", 2), "omegax": ("omega", 0),
              "omegay": ("omega", 1), "omegaz": ("omega", 2), "tqx": ("torque", 0),
              "tqy": ("torque", 1), "tqz": ("torque", 2), "radius": ("radius", None),
              "diameter": ("radius", None)}
DERIVED = ("id", "type", "mass", "xu", "yu", "zu")
ATTRIBUTES = (*DERIVED, *COMPONENTS)
REFERENCE = re.compile(r"^(c|f)_([A-Za-z0-9_]+)(?:\[(\d+)\])?$")


def unwrapped(sim):
    """Positions of the owned particles through periodic images: x + image * L."""
    p = sim.particles
    n = p.nlocal
    return p.x[:n] + p.image[:n] * sim.box.length


def check_attribute(sim, name, what):
    """A one-line error for an unknown attribute or one whose per-atom array does not exist."""
    if name not in ATTRIBUTES:
        raise ScriptError(f"{what}: unknown attribute {name} (known: {', '.join(ATTRIBUTES)})")
    array = COMPONENTS.get(name, (None,))[0]
    if array is not None and not sim.particles.has(array):
        raise ScriptError(f"{what}: attribute {name} needs per-particle {array} (particle_style sphere)")


def attribute(sim, name):
    """Attribute ``name`` of every owned particle as a float64 (nlocal,) array."""
    p = sim.particles
    n = p.nlocal
    if name in COMPONENTS:
        array, d = COMPONENTS[name]
        values = p.arrays[array][:n] if d is None else p.arrays[array][:n, d]
        return 2.0 * values if name == "diameter" else values.astype(np.float64)
    if name == "id":
        return p.tag[:n].astype(np.float64)
    if name == "type":
        return p.type[:n].astype(np.float64)
    if name == "mass":
        return np.asarray(observables.masses(sim), dtype=np.float64)
    return unwrapped(sim)[:, "xyz".index(name[0])]


def provides_peratom(style):
    """Whether a compute or fix offers per-atom values (computes: overriding the base method)."""
    if isinstance(style, Compute):
        return type(style).peratom is not Compute.peratom
    return callable(getattr(style, "peratom", None))


def find_peratom(sim, word, what):
    """The compute or fix a ``c_ID[k]``/``f_ID[k]`` reference names, and k (None for c_ID); a
    one-line error when it does not exist or has no per-atom values."""
    match = REFERENCE.match(word)
    if not match:
        raise ScriptError(f"{what}: {word} is not c_ID, c_ID[k], f_ID or f_ID[k]")
    prefix, ident, column = match.group(1), match.group(2), match.group(3)
    if prefix == "c":
        style, kind = sim.computes.get(ident), "compute"
    else:
        style, kind = sim.fixes.get(ident) or sim.analyzes.get(ident), "fix"
    if style is None:
        raise ScriptError(f"{what}: {kind} {ident} is not defined ({word})")
    if not provides_peratom(style):
        raise ScriptError(f"{what}: {kind} {ident} ({style.name}) has no per-atom values ({word})")
    return style, (None if column is None else int(column))
