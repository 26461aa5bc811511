r"""Fix ``wall/gran/region``: LAMMPS's frictional granular walls made of a region's surface, with the
contact models of its pair granular (LAMMPS's fix wall/gran/region with ``granular``; the models,
their coefficients and formulas: ``pdps doc pair granular``, ``pdps doc granular.PART NAME``).

The region's surface is LAMMPS's: with ``side in`` (the default) its inside is a container and only
particles inside it touch it, each face closer than the particle's radius once (a sphere in a corner
touches two or three faces); with ``side out`` it is an obstacle and only particles outside touch it,
once, at its closest point (face, edge or corner). Each contact is a wall of
infinite mass and radius as fix wall/gran's planes: overlap :math:`\delta = R_i - d`, :math:`R^* =
R_i`, :math:`m^* = m_i`, the tangential force turning i with arm :math:`R_i`. Each contact keeps its
own history, keyed by the face it touches, forgotten when the particle leaves it; the setup force
computation of a run does not advance it. The region stands still.

Syntax::

    fix ID GROUP wall/gran/region granular NORMAL coefficients [damping DAMPING] tangential TANGENTIAL
        coefficients [rolling sds ...] [twisting marshall|sds ...] [limit_damping] region REGION-ID

Regions: ``block``. Not built: other flat regions (pdps's plane and polygon surfaces are two-sided,
LAMMPS's one-sided), curved region
surfaces (sphere, cylinder: LAMMPS's effective radius needs the surface's curvature at the contact,
which pdps's regions do not give), the classic styles (hooke, hooke/history, hertz/history: use
``granular`` with their models), moving regions, the ``contacts`` and ``temperature`` keywords, jkr.

Example::

    region cup block 0.0 10.0 0.0 10.0 0.0 20.0
    fix cup all wall/gran/region granular hertz/material 1e5 0.5 0.3 tangential mindlin NULL 1.0 0.5 &
        region cup
"""

from typing import Literal

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.granular.base import WALL, Laws

from .dem import FixWallDEM
from .wall_contact import WallLaw, forget_far
from .wall_gran_granular import FixWallGranGranular

FLAT = ("block",)


class WallGranRegionArgs(StyleArgs):
    """``granular``, pair granular's model words (read by pdps_granular_contact.granular.words) and
    the region."""
    style: Literal["granular", "hooke", "hooke/history", "hertz/history"] = param()
    law_words: list[str] = param(names="pair granular's model words and coefficients (pdps doc granular.PART NAME)")
    region: str = keyword(..., names="region ID")


class FixWallGranRegion(FixWallDEM):
    name = "wall/gran/region"
    usage = ("fix ID GROUP wall/gran/region granular NORMAL coefficients [damping DAMPING] tangential TANGENTIAL "
             "coefficients [rolling ...] [twisting ...] [limit_damping] region REGION-ID")
    Args = WallGranRegionArgs

    @classmethod
    def check_args(cls, args):
        if args.style != "granular":
            raise ScriptError(f"the classic styles of fix wall/gran/region are not built: give granular and pair "
                              f"granular's models (hooke ... damping mass_velocity tangential ...) (got {args.style})")
        FixWallGranGranular.wall_law(args.law_words)

    def __init__(self, sim, id, group, args):
        Fix.__init__(self, sim, id, group, args)
        if "sphere" not in sim.particle_styles:
            raise ScriptError("fix wall/gran/region needs atom_style sphere (per-particle radius, mass and rotation)")
        region = sim.region(args.region)
        if region.name not in FLAT:
            raise ScriptError(f"region {region.id} ({region.name}) is curved: its effective radius needs the "
                              f"surface's curvature, which pdps's regions do not give (flat ones: {', '.join(FLAT)})")
        self.granular_law = FixWallGranGranular.wall_law(args.law_words)
        self.cutoff = None
        model = ContactModel("granular", {part: cls.name for part, (cls, _) in self.granular_law.parts.items()})
        # each contact's history, then its normal (handing a contact on: wall_slots)
        self.use_regions(sim, id, [args.region], WallLaw(model), model.history_width + 3)

    def pre_neighbor(self, sim):
        """fix wall/dem's near particles, less those on the side of the surface the region does not
        select (LAMMPS's surface_interior or surface_exterior): a sphere's centre cannot cross the
        surface before the next rebuild without going a radius into the wall."""
        super().pre_neighbor(sim)
        selected = self.regions[0].match(sim.particles.x[self._near])
        forget_far(self.history.partner, self._near, selected)
        self._near = self._near[selected]
        n = len(self._near)
        self._x_near, self._offsets = self._x_near_rows[:n], self._offset_rows[:n + 1]

    def setup(self, sim):
        # the wall is type 0: every particle type meets it with its own law
        self.wall_law.bind(Laws(sim.ntypes, {(0, t): self.granular_law for t in range(1, sim.ntypes + 1)}, WALL))
        self.pre_neighbor(sim)
        self._forces(sim, update=False)
