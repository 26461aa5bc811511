r"""Fix ``wall/gran ... granular``: LAMMPS's frictional granular walls (planes, a cylinder about z)
with the contact models of its pair granular (LAMMPS's fix wall/gran with the ``granular``
keyword; the models, their coefficients and formulas: ``pdps doc pair granular``, ``pdps doc
granular.PART NAME``).

A wall is body j of infinite mass, no spin and (planes) infinite radius: particle i (radius
:math:`R_i`, mass :math:`m_i`) at distance :math:`d < R_i` from it overlaps it by :math:`\delta =
R_i - d`, with :math:`R^* = R_i` (planes; a cylinder of radius :math:`R_c`: :math:`R^* =
R_iR_w/(R_i + R_w)`, :math:`R_w = \mp 2R_c` inside/outside, as LAMMPS), :math:`m^* = m_i`, normal
from the wall to the centre; the contact point slides at :math:`\mathbf{v}_{tr} = \mathbf{v}_t -
R_i\boldsymbol\omega_i\times\mathbf{n}`, the tangential force turns i with arm :math:`R_i`, rolling
and twisting torques as between spheres. The law's coefficients are those of the particle's
material against itself (LAMMPS's wall mixing: :math:`E^* = E/2(1-\nu^2)`, Mindlin's :math:`8G^* =
2E/(2-\nu)(1+\nu)`). Each particle keeps its wall contact's history (one contact: the nearer plane,
or the cylinder), forgotten when it leaves the wall; the setup force computation of a run does not
advance it. Wall styles, ``wiggle`` and ``shear`` as fix wall/gran's classic spelling
(``pdps doc fix wall/gran``).

Syntax::

    fix ID GROUP wall/gran granular NORMAL coefficients [damping DAMPING] tangential TANGENTIAL
        coefficients [rolling sds ...] [twisting marshall|sds ...] [limit_damping]
        xplane|yplane|zplane LO HI | zcylinder RADIUS [wiggle dim A T] [shear dim V]

Not built: jkr on a wall (its contact would have to outlast touching the wall), the ``region`` wall
style (fix wall/gran/region), the ``contacts`` and ``temperature`` keywords, the heat models.

Example (the LAMMPS bench scene in.granular_settle)::

    fix floor all wall/gran granular hertz/material 5.e6 0.5 0.45 tangential mindlin NULL 1.0 0.5 &
        rolling sds 100.0 0.05 0.05 damping coeff_restitution zplane 0.0 NULL
"""

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param, parse_args
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.granular.base import WALL, Laws
from pdps_granular_contact.granular.words import read_law

from .wall_contact import WallLaw
from .wall_gran import WALL_STYLES, Axis, FixWallGran, WallWords

STARTS = tuple(WALL_STYLES) + ("region",)


class WallArgs(StyleArgs):
    """The words after the model's: the wall and its motion."""
    wallstyle: WallWords = param(unit={"xplane|yplane|zplane LO HI": ("1", "distance", "distance"),
                                       "zcylinder RADIUS": ("1", "distance")})
    wiggle: tuple[Axis, float, float] | None = keyword(None, unit=("1", "distance", "time"))
    shear: tuple[Axis, float] | None = keyword(None, unit=("1", "velocity"))


class WallGranularArgs(WallArgs):
    """The model words (read by pdps_granular_contact.granular.words, not by the keyword parser) and
    the wall's."""
    law_words: tuple[str, ...] = param((), names="pair granular's model words and coefficients "
                                               "(pdps doc granular.PART NAME)")


class FixWallGranGranular(FixWallGran):
    name = "wall/gran"
    usage = ("fix ID GROUP wall/gran granular NORMAL coefficients [damping DAMPING] tangential TANGENTIAL "
             "coefficients [rolling ...] [twisting ...] [limit_damping] xplane|yplane|zplane LO HI | zcylinder "
             "RADIUS [wiggle dim A T] [shear dim V]")
    Args = WallGranularArgs

    @classmethod
    def spellings(cls):
        return ()

    @classmethod
    def respell(cls, dialect, words):
        return None

    @classmethod
    def parse(cls, words):
        at = next((k for k, word in enumerate(words) if word in STARTS), None)
        if at is None:
            raise ScriptError(f"a wall style is needed after the model words: xplane|yplane|zplane LO HI or zcylinder "
                              f"RADIUS (got none); usage: {cls.usage}")
        if words[at] == "region":
            raise ScriptError("the region wall style is not built (fix wall/gran/region neither) (got region)")
        cls.wall_law(words[:at])
        wall = parse_args(WallArgs, list(words[at:]), cls.usage)
        args = cls.Args(law_words=tuple(words[:at]), **dict(wall))
        cls.check_args(args)
        return args

    @staticmethod
    def wall_law(words):
        law = read_law(list(words))
        if law.name("normal") == "jkr":
            raise ScriptError("jkr on a wall is not built: its contact would outlast touching the wall (got jkr)")
        return law

    def __init__(self, sim, id, group, args):
        Fix.__init__(self, sim, id, group, args)
        if "sphere" not in sim.particle_styles:
            raise ScriptError("fix wall/gran needs atom_style sphere (per-particle radius, mass and rotation)")
        self.granular_law = self.wall_law(args.law_words)
        self.place_wall(sim, args)
        self.keep_contacts(sim, id, WallLaw(ContactModel("granular", {part: cls.name for part, (cls, _)
                                                                      in self.granular_law.parts.items()})))

    def setup(self, sim):
        # the wall is type 0: every particle type meets it with its own law
        self.law.bind(Laws(sim.ntypes, {(0, t): self.granular_law for t in range(1, sim.ntypes + 1)}, WALL))
        self.pre_neighbor(sim)
        self.forces(sim, update=False)
