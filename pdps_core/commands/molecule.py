"""``molecule ID FILE``: a molecule template read from LAMMPS's molecule file format
(pdps_core/state/molecule.py), kept by ID for the styles that insert it or make bodies of it (fix
pour ``mol``, fix rigid/small ``mol``), which find it through ``sim.molecule_template(ID)``.

LAMMPS's keywords (offset, toff, boff, aoff, doff, ioff, scale) and several files under one ID are
refused by name.
"""

import re

from ..errors import ScriptError
from ..state.molecule import read_molecule_file
from . import command

KEYWORDS = ("offset", "toff", "boff", "aoff", "doff", "ioff", "scale", "json")
IDENT = re.compile(r"^[A-Za-z0-9_]+$")


@command("molecule")
def molecule(sim, args):
    if len(args) < 2:
        raise ScriptError("expected: molecule ID FILE")
    ident, path = args[0], args[1]
    if not IDENT.match(ident):
        raise ScriptError(f"molecule ID must be letters, digits and underscores (got {ident})")
    if ident in sim.system.molecules:
        raise ScriptError(f"molecule {ident} is already defined")
    for word in args[2:]:
        if word in KEYWORDS:
            raise ScriptError(f"molecule keyword {word} is not supported in pdps (templates are read as their "
                              "file gives them)")
        raise ScriptError(f"molecule {ident}: one file per template in pdps (got a second word: {word})")
    template = read_molecule_file(ident, sim.resolve(path), label=path)
    sim.system.molecules[ident] = template
    sim.info(template.summary())
