"""Settings that take effect elsewhere or not at all in pdps, kept with the meaning their manuals
give: ``dielectric``, ``box``, ``partition``.

- ``dielectric EPS``: the dielectric constant Coulombic pair styles divide by (LAMMPS's and
  LIGGGHTS's; default 1). pdps has no Coulombic pair style, so, as in LIGGGHTS 3.8.0, which has
  none either, it changes no force: it is kept (``sim.system.dielectric``) for a style that reads it.
- ``box tilt small|large`` (LIGGGHTS's, before the box; LAMMPS removed the command): whether a
  triclinic box may be tilted beyond half its length. pdps's boxes are orthogonal, so either
  setting leaves them as they are (LIGGGHTS's does too for an orthogonal box).
- ``partition yes|no N COMMAND...``: run COMMAND only in the partitions N names (yes) or in all
  others (no); N is a number or an asterisk range (``*``, ``*n``, ``n*``, ``m*n``). pdps runs one
  partition, partition 1 (LAMMPS's and LIGGGHTS's without ``-partition``), so ``partition yes 1
  print hi`` prints and ``partition no 1 ...`` does nothing.
"""

from ..errors import ScriptError
from . import command
from .words import choice, count, number


@command("dielectric")
def dielectric(sim, args):
    count(args, 1, "dielectric EPS")
    sim.system.dielectric = number(args[0], "dielectric")


@command("box")
def box(sim, args):
    if sim.dialect.name != "liggghts":
        raise ScriptError("box is a LAMMPS command pdps does not support; instead: nothing: the command is "
                          "obsolete in LAMMPS too (docs/lammps.md)")
    if len(args) != 2 or args[0] != "tilt":
        raise ScriptError(f"usage: box tilt small|large (got {' '.join(args) or 'nothing'})")
    if sim.box is not None:
        raise ScriptError("box must come before the simulation box is created (as LIGGGHTS)")
    choice(args[1], "box tilt", ("small", "large"))


def _partitions(word):
    """(first, last) of a partition number or asterisk range, as LAMMPS's bounds with N = 1."""
    try:
        if "*" not in word:
            first = last = int(word)
        else:
            lo, hi = word.split("*", 1)
            first = int(lo) if lo else 1
            last = int(hi) if hi else 1
    except ValueError:
        raise ScriptError(f"partition N must be a number or an asterisk range such as *, *2, 2*, 1*3 (got {word})") \
            from None
    if first < 1 or last < 1:
        raise ScriptError(f"partition N must name partitions from 1 (got {word})")
    return first, last        # first > last names none (2* when there is one partition)


@command("partition")
def partition(sim, args):
    if len(args) < 3:
        raise ScriptError("usage: partition yes|no N COMMAND ...")
    style = choice(args[0], "partition style", ("yes", "no"))
    first, last = _partitions(args[1])
    inside = first <= 1 <= last
    if inside == (style == "yes"):
        sim.execute(list(args[2:]))
