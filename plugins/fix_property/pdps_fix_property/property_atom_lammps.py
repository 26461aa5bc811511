r"""Fix ``property/atom`` as LAMMPS spells it: new named per-atom values every particle carries,
moved with it between ranks, copied to ghosts and written to restart files, which read_data can fill
from a section of its data file (LAMMPS's fix property/atom).

Syntax (LAMMPS)::

    fix ID GROUP property/atom NAME1 [NAME2 ...] [ghost yes|no]
    read_data FILE fix ID NULL SECTION

- ``i_NAME``: an integer per particle; ``d_NAME``: a floating-point number per particle; both 0 to
  start with, read elsewhere as ``i_NAME``/``d_NAME`` (fix rigid custom i_NAME, compute property/atom,
  dump custom). ``mol``: a molecule id per particle (0 to start with), as atom_style molecular has
  (fix rigid/small molecule, fix pour mol, group molecule read it). LAMMPS's ``q``, ``rmass``,
  ``i2_NAME N`` and ``d2_NAME N`` are refused: choose an atom_style that has them.
- ``ghost``: LAMMPS's ghost communication flag, read; pdps always copies the values to ghosts.
- The fix may stand before the box exists, so that read_data reads its section: each line of
  SECTION is ``ID value1 [value2 ...]``, one value for each NAME in order.

LIGGGHTS's fix property/atom (``NAME scalar|vector ...``) is the other spelling of this style
(property_atom.py).

Example (LAMMPS's examples/rigid)::

    fix 0 all property/atom i_bodies
    read_data data.rigid-property fix 0 NULL Bodies
    fix 1 all rigid custom i_bodies
"""

import re
from typing import Literal

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param

NAME = re.compile(r"^(i|d)_([A-Za-z_][A-Za-z0-9_]*)$")


class FixPropertyAtomLammps(Fix):
    name = "property/atom"
    usage = "fix ID GROUP property/atom i_NAME|d_NAME ... [ghost yes|no]"
    before_box = True

    class Args(StyleArgs):
        names: list[str] = param(min_length=1, names="i_NAME or d_NAME")
        ghost: Literal["yes", "no"] = keyword("no")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.columns = []
        for word in args.names:
            if word == "mol":
                self._molecule_ids(sim, word)
                continue
            if word in ("q", "rmass", "temperature", "heatflow") or word.startswith(("i2_", "d2_")):
                raise ScriptError(f"{word}: pdps's fix property/atom makes i_NAME and d_NAME values; for {word} "
                                  "choose an atom_style that has it")
            match = NAME.match(word)
            if match is None:
                raise ScriptError(f"{word}: expected i_NAME or d_NAME")
            kind, name = match.groups()
            if name in [column[1] for column in self.columns]:
                raise ScriptError(f"{word}: named twice")
            if sim.particles.has(name):
                raise ScriptError(f"{word}: the particles already have a value named {name}")
            dtype = np.int64 if kind == "i" else np.float64
            sim.particles.request(name, dtype=dtype, default=0, replicate="copy")
            self.columns.append((kind, name))

    def _molecule_ids(self, sim, word):
        """``mol``: a molecule id per particle (0: none), as the molecular styles have."""
        if "molecule" in [column[1] for column in self.columns]:
            raise ScriptError(f"{word}: named twice")
        if sim.particles.has("molecule"):
            raise ScriptError("mol: the particles already have molecule ids (LAMMPS: Fix property/atom mol when "
                              "atom_style already has molecule attribute)")
        sim.particles.request("molecule", dtype=np.int64, default=0, replicate="copy")
        self.columns.append(("mol", "molecule"))

    def read_data_section(self, sim, section, lines, rows):
        """Fill the values from read_data's SECTION: ``lines`` (line number, words), ``rows`` maps a
        particle id to its row."""
        p = sim.particles
        for number, words in lines:
            if len(words) != 1 + len(self.columns):
                raise ScriptError(f"line {number} of section {section}: expected ID and {len(self.columns)} "
                                  f"value(s) (got {' '.join(words)})")
            try:
                tag = int(words[0])
            except ValueError:
                raise ScriptError(f"line {number} of section {section}: {words[0]} is not a particle id") from None
            row = rows.get(tag)
            if row is None:
                raise ScriptError(f"line {number} of section {section}: no particle has id {tag}")
            for (kind, name), word in zip(self.columns, words[1:]):
                try:
                    p.arrays[name][row] = float(word) if kind == "d" else int(word)
                except ValueError:
                    raise ScriptError(f"line {number} of section {section}: {word} is not "
                                      f"{'a number' if kind == 'd' else 'an integer'}") from None
