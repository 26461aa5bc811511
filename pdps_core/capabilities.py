"""What one style may offer another, declared once (issue 31): a style that needs another's
service tests for the capability, never for a style name or an attribute's presence.

    from pdps_core.api import ContactTable
    if isinstance(sim.pair, ContactTable):
        found = sim.pair.contacts(sim, self.group)
"""

from typing import Protocol, runtime_checkable

import numpy as np


@runtime_checkable
class ContactTable(Protocol):
    """A pair style that lists its contacts (the granular ones: pair gran, dem/lsd, dem/hertz).

    ``contacts(sim, group="all")`` returns a dict of arrays over the contacts of this rank's owned
    particles with both particles in ``group``: "i" and "j" (particle rows; j may be a ghost),
    "force" (n, 3), the contact force on i from j (force); a style may add columns ("tangential",
    "history"). Each style's docstring says whether they are its last force computation's or are
    worked out afresh. compute pair/contact and pair/gran/local read it."""

    def contacts(self, sim, group="all") -> dict: ...


@runtime_checkable
class ContactTimes(Protocol):
    """A pair style whose contacts set the time step (the granular ones): ``timestep_limits(sim,
    at_least=0.0)`` gives {"contact": the shortest contact time, "hertz": the Hertz time,
    "rayleigh": the Rayleigh time} (time; None where a time does not apply), which fix
    check/timestep/gran compares with the time step; a time that depends on the particles' largest
    speed takes ``at_least`` where that is larger (LIGGGHTS's vmax)."""

    def timestep_limits(self, sim, at_least=0.0) -> dict: ...


@runtime_checkable
class HeatTransport(Protocol):
    """A fix carrying heat through the contacts (fix heat/gran, as LIGGGHTS's): at most one per
    simulation. ``contact_heat_flux(sim, i, j, r)`` gives, for contacts between particle rows i and
    j at distances r (n each), the heat flowing into i from j (power: energy/time), by the fix's
    own conduction law and the current temperatures; valid once a run has started (compute
    pair/gran/local's heatFlux reads it). ``contact_heat_model(sim)`` is that law as the contact part
    a ContactConduction pair style composes into its contacts at a run's start (its own family's
    object; its material read then). ``wall_conduction(sim)`` gives what a wall's contacts conduct by:
    (contact area model, constant area, conductivity per type), once a run has started."""

    def contact_heat_flux(self, sim, i, j, r): ...

    def contact_heat_model(self, sim): ...

    def wall_conduction(self, sim): ...


@runtime_checkable
class ContactConduction(Protocol):
    """A pair style whose contacts conduct the heat of the HeatTransport fix (pair gran): at each
    force computation, ``conducts_heat(sim)`` true, it composes the fix's ``contact_heat_model(sim)``
    into its contact law and fills the per-atom ``heatFlux`` and ``directionalHeatFlux`` of owned and
    ghost rows, which the fix sums onto the owners and integrates."""

    def conducts_heat(self, sim) -> bool: ...


@runtime_checkable
class GlobalProperty(Protocol):
    """A fix holding one named global property, as LIGGGHTS's fix property/global: the material
    constants the granular models read (youngsModulus, coefficientFriction, k_finnie, ...)."""

    variable: str           # the property's name
    style: str              # "scalar", "vector", "per_type" or "per_type_pair"
    columns: int            # per_type_pair: the table's side; else 1
    values: np.ndarray      # the numbers, in the order given (a table row by row)


@runtime_checkable
class TriangleSurface(Protocol):
    """A fix holding a triangulated surface (fix wall/mesh, mesh/surface): what mesh dumps write and
    an insertion face (fix insert/stream) is."""

    vertices: np.ndarray    # (n, 3) corner positions now (distance)
    triangles: np.ndarray   # (m, 3) corner rows of each triangle
    face_normal: np.ndarray  # (m, 3) unit normals, right-hand rule over each triangle's corners
    moving: bool            # whether the corners move during a run


@runtime_checkable
class MeshSurface(TriangleSurface, Protocol):
    """A surface other fixes share and move, as LIGGGHTS's fix mesh/surface: walls (wall/gran mesh)
    act on it and ``add_mover(fix)`` gives it a motion (fix move/mesh)."""

    def add_mover(self, mover) -> None: ...


@runtime_checkable
class SurfaceValues(Protocol):
    """A surface with values per triangle (fix mesh/surface/stress): ``face_data(sim)`` gives
    {name: (m,) or (m, k) array}, written by the mesh dumps as cell data."""

    def face_data(self, sim) -> dict: ...


@runtime_checkable
class ContactRows(Protocol):
    """A compute of one row per granular contact (compute pair/gran/local, wall/gran/local):
    ``contact_columns(sim)`` gives [(keyword, width), ...], the blocks of its ``local(sim)`` rows in
    order, named by LIGGGHTS's keywords ("pos", "vel", "id", "force", "torque", "history",
    "contactArea", "delta", "heatFlux"); ``keywords`` lists those keywords it was given, in that
    order. dump local/gran/vtk writes the rows as lines."""

    keywords: list

    def contact_columns(self, sim) -> list: ...


@runtime_checkable
class MoleculeBodies(Protocol):
    """A fix that makes a rigid body of each copy of a molecule template another style inserts
    during a run (fix rigid/small ``mol``, for fix pour ``mol ... rigid``): ``body_template`` is the
    template (``sim.molecule_template(ID)``), and ``add_molecule_bodies(sim, rows, centres,
    velocities, quats)``, called on every rank right after the copies were added (``pre_exchange``),
    makes the bodies: ``rows`` (k, natoms) the owned rows of k new copies, atom by atom in the
    template's order (none on the other ranks); ``centres`` (k, 3) where each copy's geometric
    centre was put (distance), ``velocities`` (k, 3) their centre-of-mass velocities, ``quats``
    (k, 4) the unit quaternions (w, x, y, z) that turned the template into each copy."""

    body_template: object

    def add_molecule_bodies(self, sim, rows, centres, velocities, quats) -> None: ...
