r"""Fix ``property/atom``: a named per-atom value (or vector of values) every particle carries,
moved with it between ranks and written to restart files (LIGGGHTS's fix property/atom).

Syntax::

    fix ID GROUP property/atom NAME scalar|vector RESTART GHOST REVERSE V1 [V2 ...]

- ``NAME``: the property's name; ``set ... property/atom NAME V`` gives a scalar property values,
  ``dump custom`` writes it as ``f_NAME[0]`` (``f_NAME[k]``, k from 0, for a vector) in the
  LIGGGHTS dialect; ``f_ID`` (``f_ID[k]``, from the dialect's first index) reads it as any fix's
  per-atom values (compute reduce, dump custom).
- ``scalar``: one value per particle (give one default); ``vector``: as many as defaults given.
- ``RESTART``, ``GHOST``, ``REVERSE`` (yes|no): LIGGGHTS's restart and ghost communication flags,
  read and checked; pdps always keeps per-atom values in restart files and copies them to ghosts
  (the style that reads them sums them back when it needs to).
- ``V1 ...``: the value every particle starts with (particles created later too; a vector's
  particles created later start at V1 in every column when the defaults differ).
- ``GROUP`` is ignored (every particle has the property), as in LIGGGHTS.

Example (LIGGGHTS)::

    fix uf all property/atom uf vector yes no no 0. 0. 0.
    fix cnt all property/atom contactCount scalar yes yes no 0.
"""

from typing import Literal

from pdps_core.api import Fix, ScriptError, StyleArgs, param

CORE = ("x", "v", "f", "tag", "type", "mask", "image", "radius", "rmass", "omega", "torque", "q", "molecule")


class FixPropertyAtom(Fix):
    name = "property/atom"
    usage = "fix ID GROUP property/atom NAME scalar|vector yes|no yes|no yes|no V1 [V2 ...]"

    class Args(StyleArgs):
        variable: str = param(description="the property's name")
        style: Literal["scalar", "vector"]
        restart: Literal["yes", "no"]
        ghost: Literal["yes", "no"]
        reverse: Literal["yes", "no"]
        defaults: list[float] = param([], unit="as the property")

    @classmethod
    def respell(cls, dialect, words):
        # LAMMPS's own fix property/atom (i_NAME, d_NAME, ...): a name, then no scalar|vector
        if dialect != "liggghts" and words[1:2] not in (["scalar"], ["vector"]):
            from .property_atom_lammps import FixPropertyAtomLammps
            return FixPropertyAtomLammps, words
        return None

    @classmethod
    def spellings(cls):
        from .property_atom_lammps import FixPropertyAtomLammps
        return (FixPropertyAtomLammps,)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        name, values = args.variable, list(args.defaults)
        if name in CORE:
            raise ScriptError(f"{name} is a core per-atom array, not a property a fix can make")
        if not values:
            raise ScriptError(f"{name} {args.style}: expected the default value(s); usage: {self.usage}")
        if args.style == "scalar" and len(values) != 1:
            raise ScriptError(f"{name} scalar takes one default value (got {len(values)})")
        self.variable = name
        p = sim.particles
        # a replicated particle's copies share its values, as LIGGGHTS's replicate copies them
        array = p.request(name, len(values) if args.style == "vector" else None, default=values[0],
                          replicate="copy")
        if args.style == "vector":
            array[: p.nlocal] = values

    def peratom(self, sim):
        """The property of the owned particles, for ``f_ID`` (``f_ID[k]`` of a vector) as LAMMPS's
        output commands read a fix's per-atom values."""
        p = sim.particles
        return p.arrays[self.variable][: p.nlocal]
