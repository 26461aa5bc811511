"""Dialects: a script is read as PDPS or as LAMMPS, and means in each what that manual says.

Where the two manuals disagree, the dialect decides; every such point is a field of ``Dialect`` and
a row of docs/lammps.md. Everything else (commands only one of them has, keywords only one of them
takes) is accepted in both, since it cannot change a meaning.

Which dialect a script is read in, in order:

1. ``pdps run --dialect lammps|liggghts|pdps`` (or ``Simulation(dialect=...)``);
2. a ``dialect lammps|liggghts|pdps`` line in the script (before any other command);
3. the first command only one of the two languages has (``atom_style``, ``create_atoms``,
   ``comm_modify``... read as LAMMPS; ``particle_style``, ``create_particle``, ``integrate``,
   ``analyze``... as PDPS), or a lattice by its spelling (``lattice spacing ...`` PDPS,
   ``lattice fcc 0.8442`` LAMMPS), the lines of a file the script includes counted where the
   ``include`` stands (a name with a ``$`` in it cannot be followed before the run);
4. PDPS, the project's own language, when nothing says otherwise.

A script read as LAMMPS by 3 or 4 is read as LIGGGHTS (a LAMMPS fork: the same meaning wherever
they share a command) when any of its lines has a spelling only LIGGGHTS has (``LIGGGHTS_ONLY``:
``atom_style granular``, ``pair_style gran``, ``fix ID G property/global``, ``fix ID G wall/gran
model``...), the first such line being the reason.

The run's first line names the dialect and why: ``read as LAMMPS: atom_style on line 4``.
"""

import os
from dataclasses import dataclass

from ..errors import ScriptError
from ..state import limits
from .lexer import logical_lines, read_text, strip_comment


@dataclass(frozen=True)
class Dialect:
    name: str
    label: str
    index_base: int            # first element of c_ID[i], f_ID[i]: PDPS 0, LAMMPS 1
    # default of the units keyword of region and fix move: PDPS box, LAMMPS lattice, LIGGGHTS 3.8.0
    # box (its source, measured; its manual says lattice)
    region_units: str
    velocity_units: str        # default of velocity's units keyword (set, ramp): as region_units
    velocity_numbers: str      # velocity create's generator: "counter" (pdps) or "park" (LAMMPS's)
    # set diameter on a sphere: "mass" keeps its mass (LAMMPS), "density" keeps its density, so the
    # mass follows the new size (LIGGGHTS)
    set_diameter_keeps: str = "mass"
    # what a sphere's density multiplies in 2d (create_atoms, read_data, set density and diameter):
    # "sphere" 4/3 pi r^3 (LAMMPS), "disc" pi r^2 (LIGGGHTS, PDPS)
    volume_2d: str = "disc"
    # what read_restart brings back besides the particles, box, groups and pair style: True, the
    # whole simulation (PDPS: fixes, computes, analyze styles, regions); False, LAMMPS's and LIGGGHTS's
    # rule: the script gives its fixes, computes and regions again, a fix given with the ID and style
    # it had takes up its saved state
    restart_styles: bool = True
    # fix adapt's rule: "lammps" (equal-style variables; scale multiplies the radius the run began
    # with; reset yes restores the radii of the fix's creation; the mass keyword) or "liggghts"
    # (equal- or atom-style; scale multiplies the current diameter; reset leaves particles alone)
    adapt_rule: str = "lammps"
    # thermo_modify lost when the script does not say: LAMMPS's error; LIGGGHTS 3.8.0 ignores lost
    # particles by default (its thermo.cpp), which pdps follows, saying so once
    lost_default: str = "error"
    # dump_modify format STRING, one C format for the whole line (LIGGGHTS's; LAMMPS's before 2016)
    dump_format_string: bool = False
    # default of the units keyword of LAMMPS's other commands that scale by the lattice (create_atoms
    # single, displace_atoms, fix deform, fix ave/spatial): lattice as LAMMPS's, also in the PDPS
    # dialect; box in LIGGGHTS 3.8.0 (its source, measured; its manual says lattice)
    command_units: str = "lattice"
    # every run's setup builds the neighbor lists afresh, as LAMMPS's and LIGGGHTS's do, instead of
    # going on with the last build's (Neighbor.can_resume): LIGGGHTS keeps the spring of a contact
    # that came apart until the list is next built, so when the lists are built is physics there
    rebuild_at_setup: bool = False
    # a run's setup wraps particles that crossed a periodic face since the last build, as LAMMPS's
    # setup does (region tests at a run's start see the wrapped positions); PDPS goes on with the
    # last build, so that run N + run M is run N+M to the last bit
    wrap_at_setup: bool = False
    # fix print prints at a run's first step when it is a multiple of N (LAMMPS since 2014); LIGGGHTS
    # 3.8.0's prints at the end of steps only (measured)
    print_at_setup: bool = True
    # compute rdf divides by the ordered pairs of distinct particles, N_I N_J - D (LAMMPS since
    # 2017); LIGGGHTS 3.8.0's by N_I N_J, as the LAMMPS it was forked from (its source, measured)
    rdf_distinct_pairs: bool = True
    # fix addforce's energy with a variable force and no energy keyword: -F . x of the values now
    # (LAMMPS), or 0 (LIGGGHTS 3.8.0, the LAMMPS it was forked from: its source)
    variable_force_energy: bool = True
    # None: quit takes [STATUS], 0 unless given (LAMMPS's); a number: quit takes no status and exits
    # with that one (LIGGGHTS 3.8.0's exits with 1: its Error::done, measured)
    quit_status: int | None = None
    # the thermo columns before any thermo_style: LAMMPS's thermo_style one, Volume added where the
    # box changes; LIGGGHTS 3.8.0's Step Atoms KinEng CPU (measured); the PDPS dialect's kinetic and
    # potential energy apart
    thermo_default: tuple = ("step", "temp", "epair", "emol", "etotal", "press")
    # thermo ke: LAMMPS's, 1/2 dof k_B T of the thermo temperature; or (LIGGGHTS 3.8.0, its
    # thermo.cpp) its compute thermo_kin_eng, the sum of 1/2 m v^2 over all particles, each rigid
    # clump one body
    thermo_ke_sum: bool = False


DIALECTS = {
    "pdps": Dialect("pdps", "PDPS", index_base=0, region_units="box", velocity_units="box",
                    velocity_numbers="counter", thermo_default=("step", "temp", "pe", "ke", "etotal", "press")),
    "lammps": Dialect("lammps", "LAMMPS", index_base=1, region_units="lattice", velocity_units="lattice",
                      velocity_numbers="park", volume_2d="sphere", restart_styles=False, wrap_at_setup=True),
    # LIGGGHTS is a LAMMPS fork: LAMMPS's meaning wherever the two share a command, but for these
    "liggghts": Dialect("liggghts", "LIGGGHTS", index_base=1, region_units="box", velocity_units="box",
                        velocity_numbers="park", set_diameter_keeps="density", restart_styles=False,
                        adapt_rule="liggghts", lost_default="ignore", dump_format_string=True,
                        rebuild_at_setup=True, print_at_setup=False, command_units="box",
                        rdf_distinct_pairs=False, variable_force_energy=False, quit_status=1,
                        thermo_default=("step", "atoms", "ke", "cpu"), thermo_ke_sum=True),
}

# commands one language has and the other has not: the first one met names the dialect
LAMMPS_ONLY = frozenset({
    "atom_style", "atom_modify", "create_atoms", "comm_modify", "comm_style", "delete_atoms",
    "displace_atoms", "set", "write_data", "write_dump", "minimize", "min_style", "min_modify",
    "newton", "thermo_modify", "dump_modify", "label", "jump", "clear", "kspace_style",
    "bond_style", "angle_style", "pair_modify", "change_box", "replicate", "velocity_modify",
    "compute_modify", "fix_modify", "molecule", "special_bonds", "read_dump",
})
# (command, first word) pairs only LIGGGHTS has, for fixes and computes the style word after ID and
# group: in a LAMMPS-family script the first one met makes it a LIGGGHTS script
LIGGGHTS_ONLY = frozenset({
    ("atom_style", "granular"), ("pair_style", "gran"), ("fix", "property/global"), ("fix", "property/atom"),
    ("fix", "mesh/surface"), ("fix", "mesh/surface/stress"), ("fix", "mesh/surface/planar"),
    ("fix", "move/mesh"), ("fix", "insert/pack"), ("fix", "insert/stream"), ("fix", "insert/rate/region"),
    ("fix", "particletemplate/sphere"), ("fix", "particledistribution/discrete"), ("fix", "heat/gran"),
    ("fix", "heat/gran/conduction"), ("compute", "pair/gran/local"), ("compute", "wall/gran/local"),
})
PDPS_ONLY = frozenset({
    "particle_style", "create_particle", "integrate", "analyze", "unanalyze", "uncompute",
    "neighbor_modify", "thermo.style",
})


def dialect_named(word, where="dialect"):
    try:
        return DIALECTS[word]
    except KeyError:
        raise ScriptError(f"{where} must be lammps, liggghts or pdps (got {word})") from None


def _lattice_dialect(words):
    # PDPS spells a lattice by its spacings, LAMMPS by its style and scale
    if len(words) > 1:
        return "pdps" if words[1] == "spacing" else "lammps"
    return None


def _liggghts_marker(words):
    """The LIGGGHTS-only spelling on a line (``pair_style gran``, ``fix ID G mesh/surface``), or None."""
    name = words[0]
    style = words[3] if name in ("fix", "compute") and len(words) > 3 else (words[1] if len(words) > 1 else None)
    # the word respell looks for: LIGGGHTS's keywords stand in any order
    if name == "fix" and style == "wall/gran" and "model" in words[4:]:
        return "fix wall/gran model"
    # LAMMPS has a fix property/atom of its own (i_NAME, d_NAME, mol ...): LIGGGHTS's names a
    # property and then scalar or vector
    if name == "fix" and style == "property/atom" and words[5:6] not in (["scalar"], ["vector"]):
        return None
    return f"{name} {style}" if (name, style) in LIGGGHTS_ONLY else None


def _commands(text, source, directory=None, included_at=None, depth=0):
    """(words, line number, where) of each command of a script in reading order, the lines of a file
    it includes in place of the include (``where``: ``line 4``, or ``line 2 of in.settings (included
    on line 5)``). An include the reader cannot follow here (a $ in its name, a file that cannot be
    read) is passed over: the run reports it, located, when it gets there."""
    for number, raw in logical_lines(text):
        try:
            words = strip_comment(raw).split()
        except ScriptError:
            words = raw.split()     # a broken line: the run reports it, located, when it gets there
        if not words:
            continue
        where = f"line {number}" if included_at is None else f"line {number} of {source} ({included_at})"
        yield words, number, where
        if (words[0] == "include" and len(words) == 2 and "$" not in words[1] and directory is not None
                and depth < limits.MAX_INCLUDE_DEPTH):
            path = _included(words[1], directory)
            try:
                inner = read_text(path, "input script", path)
            except ScriptError:
                continue
            yield from _commands(inner, words[1], os.path.dirname(os.path.abspath(path)), f"included on {where}",
                                 depth + 1)


def _included(path, directory):
    # as Simulation.resolve: relative to the including script's folder, else to the working folder
    if os.path.isabs(path):
        return path
    candidate = os.path.join(directory, path)
    return candidate if os.path.exists(candidate) or not os.path.exists(path) else path


def detect(text, source, directory=None):
    """(Dialect, reason) for a script that was not told its dialect, read with the files it
    includes (``directory``: the script's folder, where they are looked for). A LAMMPS-family
    script (one a LAMMPS-only command, or no command, names) is LIGGGHTS's when any line has a
    LIGGGHTS-only spelling: the first one is the reason."""
    found = _detect_family(text, source, directory)
    if found[0].name == "pdps" and not found[1].startswith("no command"):
        return found
    for words, number, where in _commands(text, source, directory):
        if words[0] == "dialect" and where == f"line {number}":
            return found
        marker = _liggghts_marker(words)
        if marker:
            return DIALECTS["liggghts"], f"{marker} on {where}"
    return found


def _detect_family(text, source, directory=None):
    first_command = None
    for words, number, where in _commands(text, source, directory):
        name = words[0]
        if name == "dialect" and where == f"line {number}":
            try:
                if first_command is not None:
                    raise ScriptError(f"dialect must come before any other command (line "
                                      f"{first_command[1]} has {first_command[0]})")
                if len(words) != 2:
                    raise ScriptError("expected one word; usage: dialect lammps|liggghts|pdps")
                return dialect_named(words[1]), f"dialect on line {number}"
            except ScriptError as exc:
                raise exc.locate(source, number, "dialect") from None
        if first_command is None:
            first_command = (name, number)
        if name in LAMMPS_ONLY:
            return DIALECTS["lammps"], f"{name} on {where}"
        if name in PDPS_ONLY:
            return DIALECTS["pdps"], f"{name} on {where}"
        if name == "lattice" and _lattice_dialect(words):
            return DIALECTS[_lattice_dialect(words)], f"lattice {words[1]} on {where}"
    return DIALECTS["pdps"], "no command names a dialect (PDPS is the default)"
