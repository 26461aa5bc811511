r"""Fix styles ``wall/gran/hertz/history``, ``wall/gran/hooke/history``, ``wall/gran/hooke``: LIGGGHTS
2.x's names of its granular walls, still in its own tutorials (conveyor), read in the LIGGGHTS
dialect as today's ``wall/gran model MODEL tangential TANGENTIAL ...`` (the physics, parameters and
units are that style's: ``pdps doc fix wall/gran``).

Syntax (LIGGGHTS dialect)::

    fix ID GROUP wall/gran/hertz/history mesh n_meshes N meshes ID... | primitive type T WALL ARGS [SETTING VALUE ...]
    fix ID GROUP wall/gran/hooke/history type T WALL ARGS                  (primitive understood)

Model settings (``rolling_friction cdt`` ...) may stand after the style or after the geometry, as
2.x wrote them. Example (the conveyor tutorial's)::

    fix floor all wall/gran/hertz/history primitive type 1 zplane 0.0

In the LAMMPS and PDPS dialects these names are refused at their line: LAMMPS has no such fix.
"""

from pdps_core.api import Fix, ScriptError
from pdps_granular_contact import liggghts2


class LiggghtsWallSpelling(Fix):
    """A LIGGGHTS 2.x wall name: only ever respelled, never made."""

    @classmethod
    def spellings(cls):
        from .wall_gran_model import FixWallGranModel
        return (FixWallGranModel,)

    @classmethod
    def respell(cls, dialect, words):
        today = liggghts2.MODELS[cls.name[len("wall/"):]]
        if dialect != "liggghts":
            raise ScriptError(f"fix style {cls.name} is LIGGGHTS 2.x's spelling of wall/gran "
                              f"{' '.join(today)}; read the script as LIGGGHTS (--dialect liggghts)")
        respelled = liggghts2.wall_words(cls.name, words)
        if respelled is None:
            raise ScriptError(f"fix {cls.name} needs a mesh or primitive wall (got {' '.join(words[:1]) or 'nothing'})")
        from .wall_gran_model import FixWallGranModel
        return FixWallGranModel, respelled


class FixWallGranHertzHistory(LiggghtsWallSpelling):
    name = "wall/gran/hertz/history"


class FixWallGranHookeHistory(LiggghtsWallSpelling):
    name = "wall/gran/hooke/history"


class FixWallGranHooke(LiggghtsWallSpelling):
    name = "wall/gran/hooke"
