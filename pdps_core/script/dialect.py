"""Dialects: a script is read as PDPS or as LAMMPS, and means in each what that manual says.

Where the two manuals disagree, the dialect decides; every such point is a field of ``Dialect`` and
a row of docs/lammps.md. Everything else (commands only one of them has, keywords only one of them
takes) is accepted in both, since it cannot change a meaning.

Which dialect a script is read in, in order:

1. ``pdps run --dialect lammps|pdps`` (or ``Simulation(dialect=...)``);
2. a ``dialect lammps|pdps`` line in the script (before any other command);
3. the first command only one of the two languages has (``atom_style``, ``create_atoms``,
   ``comm_modify``... read as LAMMPS; ``particle_style``, ``create_particle``, ``integrate``,
   ``analyze``... as PDPS), or a lattice by its spelling (``lattice spacing ...`` PDPS,
   ``lattice fcc 0.8442`` LAMMPS);
4. PDPS, the project's own language, when nothing says otherwise.

The run's first line names the dialect and why: ``read as LAMMPS: atom_style on line 4``.
"""

from dataclasses import dataclass

from ..errors import ScriptError
from .lexer import logical_lines, strip_comment


@dataclass(frozen=True)
class Dialect:
    name: str
    label: str
    index_base: int            # first element of c_ID[i], f_ID[i]: PDPS 0, LAMMPS 1
    region_units: str          # default of region's units keyword: PDPS box, LAMMPS lattice
    velocity_units: str        # default of velocity's units keyword (set, ramp): PDPS box, LAMMPS lattice
    velocity_numbers: str      # velocity create's generator: "counter" (pdps) or "park" (LAMMPS's)


DIALECTS = {
    "pdps": Dialect("pdps", "PDPS", index_base=0, region_units="box", velocity_units="box",
                    velocity_numbers="counter"),
    "lammps": Dialect("lammps", "LAMMPS", index_base=1, region_units="lattice", velocity_units="lattice",
                      velocity_numbers="park"),
}

# commands one language has and the other has not: the first one met names the dialect
LAMMPS_ONLY = frozenset({
    "atom_style", "atom_modify", "create_atoms", "comm_modify", "comm_style", "delete_atoms",
    "displace_atoms", "set", "write_data", "write_dump", "minimize", "min_style", "min_modify",
    "newton", "thermo_modify", "dump_modify", "label", "jump", "clear", "kspace_style",
    "bond_style", "angle_style", "pair_modify", "change_box", "replicate", "velocity_modify",
    "compute_modify", "fix_modify", "molecule", "special_bonds", "read_dump",
})
PDPS_ONLY = frozenset({
    "particle_style", "create_particle", "integrate", "analyze", "unanalyze", "uncompute",
    "neighbor_modify", "thermo.style",
})


def dialect_named(word, where="dialect"):
    try:
        return DIALECTS[word]
    except KeyError:
        raise ScriptError(f"{where} must be lammps or pdps (got {word})") from None


def _lattice_dialect(words):
    # PDPS spells a lattice by its spacings, LAMMPS by its style and scale
    if len(words) > 1:
        return "pdps" if words[1] == "spacing" else "lammps"
    return None


def detect(text, source):
    """(Dialect, reason) for a script that was not told its dialect."""
    first_command = None
    for number, raw in logical_lines(text):
        try:
            words = strip_comment(raw).split()
        except ScriptError:
            words = raw.split()     # a broken line: the run reports it, located, when it gets there
        if not words:
            continue
        name = words[0]
        if name == "dialect":
            try:
                if first_command is not None:
                    raise ScriptError(f"dialect must come before any other command (line "
                                      f"{first_command[1]} has {first_command[0]})")
                if len(words) != 2:
                    raise ScriptError("expected one word; usage: dialect lammps|pdps")
                return dialect_named(words[1]), f"dialect on line {number}"
            except ScriptError as exc:
                raise exc.locate(source, number, "dialect") from None
        if first_command is None:
            first_command = (name, number)
        if name in LAMMPS_ONLY:
            return DIALECTS["lammps"], f"{name} on line {number}"
        if name in PDPS_ONLY:
            return DIALECTS["pdps"], f"{name} on line {number}"
        if name == "lattice" and _lattice_dialect(words):
            return DIALECTS[_lattice_dialect(words)], f"lattice {words[1]} on line {number}"
    return DIALECTS["pdps"], "no command names a dialect (PDPS is the default)"
