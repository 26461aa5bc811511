"""The system part of a simulation: the particles, their types and masses, the box and its
boundaries, groups and regions, in the units chosen (LAMMPS's Atom and Domain), and the services
that change them: change_box, add_particles, delete_particles."""

import numpy as np

from ..errors import ScriptError
from .groups import Groups
from .topology import Topology
from .particles import Particles, substyles
from .units import UNITS


class System:
    __slots__ = ("sim", "units", "dimension", "periodicity", "box", "shrink_faces", "ntypes", "mass",
                 "particle_style", "lattice", "particles", "groups", "regions", "processors",
                 "ghost_velocity", "stiffness_checks", "dielectric", "topology", "molecules")

    def __init__(self, sim):
        self.sim = sim                  # for group selections (regions, variables)
        self.units = UNITS["lj"]
        self.dimension = 3
        self.periodicity = ("p", "p", "p")
        self.box = None
        self.shrink_faces = ()          # the shrink-wrapped faces and their margins (run/shrink_wrap.py)
        self.ntypes = 0
        self.mass = np.zeros(1)         # per type, index 0 unused; NaN where not yet set
        self.particle_style = "atomic"
        self.lattice = None
        self.particles = Particles()
        self.groups = Groups()
        self.regions = {}
        self.molecules = {}             # molecule templates by ID (the molecule command)
        self.processors = None          # the processors command's grid, or None
        self.ghost_velocity = False     # comm_modify vel yes: ghosts carry velocities
        # LIGGGHTS's bounds on youngsModulus, lifted by soft_particles yes / hard_particles yes
        self.stiffness_checks = {"soft": True, "hard": True}
        self.topology = Topology()      # bonds: their types, special_bonds, the bond list
        self.dielectric = 1.0           # the dielectric command's, for Coulombic styles (pdps has none yet)

    @property
    def particle_styles(self):
        """The particle styles in effect: (particle_style,), or the sub-styles of hybrid, so that
        ``"sphere" in sim.particle_styles`` holds for ``hybrid sphere molecular`` too."""
        return substyles(self.particle_style)

    def require_box(self, what):
        if self.box is None:
            raise ScriptError(f"{what} before the simulation box exists (use create_box or read_data first)")

    def region(self, id):
        """A defined region."""
        try:
            return self.regions[id]
        except KeyError:
            raise ScriptError(f"region {id} is not defined (defined: {', '.join(self.regions) or 'none'})") from None

    def molecule_template(self, id):
        """A molecule template (pdps_core/state/molecule.py's MoleculeTemplate) by its ID."""
        try:
            return self.molecules[id]
        except KeyError:
            raise ScriptError(f"molecule template {id} is not defined (defined: "
                              f"{', '.join(self.molecules) or 'none'})") from None

    def require_group(self, name):
        self.groups.bit(name)
        return name

    def check_masses(self):
        p = self.particles
        if p.has("rmass") or p.nlocal == 0:
            return
        used = np.unique(p.type[: p.nlocal])
        unset = [int(t) for t in used if not (self.mass[t] > 0)]
        if unset:
            raise ScriptError(f"mass is not set for type {unset[0]} (use the mass command)")

    # ---- a box that changes during a run -----------------------------------------------------------
    def change_box(self, lo, hi, remap=None):
        """Give the box new bounds ``lo``, ``hi`` (3 each) now, as LAMMPS's ``set_global_box``.
        ``remap``: a group name whose owned particles keep their fractional position in the box
        (LAMMPS's x2lamda / lamda2x: x' = lo' + (hi' - lo') (x - lo) / (hi - lo)); None moves none.
        The next neighbor decision rebuilds the lists (wrap, migrate, ghosts with the new image
        shifts), so every step the box changes is a rebuild step. Collective under MPI: every rank
        passes the same bounds."""
        box = self.box
        if remap is None:
            box.set_bounds(lo, hi)
        else:
            chosen = self.groups.select(self.sim, remap)
            x = self.particles.x[: self.particles.nlocal]
            lamda = (x[chosen] - box.lo) * (1.0 / box.length)
            box.set_bounds(lo, hi)
            x[chosen] = box.length * lamda + box.lo
        self.sim.run_state.box_changed = True

    # ---- particles inserted and deleted by styles ------------------------------------------------
    def add_particles(self, x, type, v=None, **per_atom):
        """Insert owned particles at positions ``x`` (n x 3) of ``type`` (one or n), velocities ``v``
        and other per-atom values (``radius=...``, ``rmass=...``, ``mask=...``); returns their row
        indices. Collective under MPI: every rank calls it (with n = 0 where it inserts nothing);
        ids continue after the largest id on any rank, rank by rank, so they stay globally unique.
        Call it from ``pre_exchange`` on a step the fix asked a rebuild for (``next_reneighbor``):
        the particles are then wrapped, migrated to their owners and listed on that very step."""
        comm = self.sim.comm
        x = np.atleast_2d(np.asarray(x, dtype=np.float64)).reshape(-1, 3)
        counts = comm.allgather_rows(np.array([[len(x)]], dtype=np.int64)).ravel()
        p = self.particles
        largest = int(comm.max(int(p.tag[: p.nlocal].max()) if p.nlocal else 0))
        first = largest + 1 + int(counts[: comm.rank].sum())
        tags = np.arange(first, first + len(x), dtype=np.int64)
        if v is not None:
            per_atom["v"] = v
        rows = p.add(x, type, tags=tags, **per_atom)
        p.next_tag = max(p.next_tag, largest + 1 + int(counts.sum()))
        return rows

    def delete_particles(self, rows):
        """Remove the owned particles at ``rows`` (indices or a boolean mask over owned particles),
        from ``pre_exchange`` on a rebuild step as for insertion. Ids are not reused."""
        p = self.particles
        keep = np.ones(p.nlocal, dtype=bool)
        keep[rows] = False
        p.keep(np.flatnonzero(keep))
