"""The style contract: everything a plugin (or a Python user) may import and touch.

Plugins import from here only, and of the objects the core hands them (``sim`` and what hangs off
it) they read only the names in ``CONTRACT`` below; anything else in pdps_core may change without
notice. tests/test_contract.py holds every plugin under plugins/ to it, and docs/plugin-guide.md
shows every name with an example. The contract has a version, ``API_VERSION``; a plugin states the
range it supports as ``PDPS_API = ">=1.0,<2"`` in its package's ``__init__.py`` and is refused,
by name, outside it.
"""

from .capabilities import (ContactConduction, ContactRows, ContactTable, ContactTimes, GlobalProperty, HeatTransport, MeshSurface, MoleculeBodies, SurfaceValues,
                           TriangleSurface)
from .commands.words import choice, integer, number, type_range, yes_no
from .contact import ContactHistory, close_slot, find_slot, open_slot
from .errors import ScriptError, SimulationError
from .named_temperature import NamedTemperature
from .neighbor.neighbor import NeighborList
from .pair_loop import generated_module
from .random import pair_gaussian, pair_uniform, particle_gaussians, particle_uniforms, philox4x32
from .random_park import park_gaussian, park_state, park_uniform
from .run.hookspec import HOOKS
from .simulation import Simulation
from .state import observables
from .state.limits import check_bins, check_images
from .styles import (API_VERSION, Analyze, Bond, Compute, Dump, Fix, FloatOrVariable, Pair, PairLaw, Region, RegionArgs,
                     StyleArgs, StyleName, SubModel, SurfaceContacts, Variable, VariableRef, keyword, param, parse_args,
                     PERATOM_REFERENCE, PeratomReference, peratom_column, registry)

__all__ = ["API_VERSION", "Analyze", "Bond", "CONTRACT", "Compute", "ContactConduction", "ContactHistory", "ContactRows", "ContactTable", "ContactTimes",
           "GlobalProperty", "HeatTransport", "MeshSurface", "MoleculeBodies", "SurfaceValues", "TriangleSurface", "Dump", "Fix",
           "FloatOrVariable", "HOOKS", "NamedTemperature", "NeighborList", "Pair", "PairLaw", "Region", "RegionArgs", "ScriptError",
           "Simulation", "SimulationError", "StyleArgs", "StyleName", "SubModel", "SurfaceContacts", "Variable", "VariableRef", "check_bins", "check_images", "choice", "close_slot", "find_slot", "generated_module", "integer",
           "keyword", "number", "observables", "open_slot", "pair_gaussian", "park_gaussian", "park_state", "park_uniform", "pair_uniform", "param", "parse_args",
           "particle_gaussians", "particle_uniforms", "PERATOM_REFERENCE", "PeratomReference", "peratom_column", "philox4x32", "registry",
           "type_range", "yes_no"]

# What a style may read of the objects the core hands it: object -> {name: what it is}.
CONTRACT = {
    "Simulation": {
        # particles and the box
        "particles": "the per-atom arrays (Particles): owned rows 0..nlocal, ghosts after",
        "nlocal": "number of owned particles on this rank",
        "x": "positions of owned particles, (nlocal, 3) view (distance)",
        "v": "velocities of owned particles, (nlocal, 3) view (velocity)",
        "f": "forces on owned particles, (nlocal, 3) view (force)",
        "tag": "global ids of owned particles (int64, from 1)",
        "type": "types of owned particles (int32, from 1)",
        "mass": "mass per type, index 0 unused (NaN where not set); rmass per particle when present",
        "ntypes": "number of particle types",
        "particle_style": "'atomic', 'sphere' (radius, rmass, omega, torque exist), 'charge' (q), 'molecular', 'bond', 'angle' (molecule), 'full' (molecule, q), or 'hybrid S1 S2 ...' (all its sub-styles' arrays)",
        "particle_styles": "the particle styles in effect: (particle_style,) or hybrid's sub-styles; test 'sphere' in sim.particle_styles, not particle_style == 'sphere'",
        "box": "the simulation box (Box)",
        "periodicity": "the boundary command's word per axis: 'p', 'f', 's', 'm' or two letters ('fm')",
        "change_box": "change_box(lo, hi, remap=GROUP or None): new box bounds now, a group's particles carried (barostats, deform)",
        "dimension": "2 or 3",
        "lattice": "the lattice command's Lattice (spacing (3,): what units lattice multiplies by; basis, cell, offset, style), or None",
        "units": "the unit system (Units): boltz, mvv2e, nktv2p",
        "stiffness_checks": "{'soft': bool, 'hard': bool}: whether LIGGGHTS's bounds on youngsModulus hold "
                            "(soft_particles yes / hard_particles yes lift them)",
        # the run
        "step": "the current timestep",
        "time": "simulated time (time units)",
        "dt": "the timestep (time units)",
        "run_first_step": "first step of the current (or last) run",
        "run_last_step": "last step of the current (or last) run",
        "ramp": "ramp(start, stop): linear from the run's first to its last step (LAMMPS's ramp)",
        "eflag": "True while the current step computes energies",
        "vflag": "True while the current step computes the virial",
        "virial": "this rank's virial (xx, yy, zz, xy, xz, yz; energy) of the step's forces, where vflag was set",
        "in_setup": "True while a run computes its setup forces (styles with history do not advance it)",
        # the other styles and script objects
        "pair": "the pair style, or None",
        "bonds": "bonds(): this rank's bonds as rows (i, j, type), i owned, j the nearest copy of its partner, turned-off ones (type < 0) included",
        "nbondtypes": "number of bond types of the box (0 without bonds)",
        "fix_with": "fix_with(capability): the first fix having a capability (HeatTransport, MeshSurface, ...), or None",
        "create_bonds": "create_bonds(pairs, bond_type): new bonds between id pairs (k, 2), the same on every rank; special lists made again",
        "break_bonds": "break_bonds(pairs): delete the bonds between id pairs (k, 2), the same on every rank; special lists made again",
        "bond_single": "bond_single(type, rsq): (F/r, energy) of one bond of that type at r^2 = rsq under the run's bond styles",
        "interaction_energy": "interaction_energy(): in a run, the pair and bond energy of the particles where they stand now (all ranks), forces recomputed into f (save and restore them)",
        "pair_list": "the pair style's neighbor list (NeighborList), once a run set it up",
        "fixes": "{id: fix} in script order",
        "substitute": "substitute(text): $x, ${name} and $(formula) replaced now (fix print)",
        "computes": "{id: compute}",
        "analyzes": "{id: analyze style}",
        "groups": "the groups (Groups): bit(name), select(sim, name)",
        "region": "region(id): a defined region (Region), or a one-line error",
        "variables": "the script's variables (Variables): value(name), name in variables",
        "evaluate": "evaluate(arg): a style argument's value now (v_NAME evaluated)",
        "compute_value": "compute_value(id, indices): c_ID, c_ID[i], c_ID[i][j]",
        "fix_value": "fix_value(id, indices): f_ID, f_ID[i], f_ID[i][j]",
        "dialect_index": "dialect_index(i, what): a script's index (c_ID[i], a column) counted from the dialect's first, as 0-based",
        "dialect": "the dialect the script is read in: .name is pdps, lammps or liggghts (docs/lammps.md); its "
                   "other fields say where the dialects' meanings part (.adapt_rule: fix adapt's)",
        "compute_needs": "compute_needs(id): {'energy', 'virial'} a compute reads",
        "require_group": "require_group(name): the name, or a one-line error",
        "require_box": "require_box(what): a one-line error when no box exists yet",
        "resolve": "resolve(path): a file named in a script, relative to the script's folder",
        "molecule_template": "molecule_template(id): the molecule command's template (MoleculeTemplate) of that ID, or a one-line error",
        # services
        "comm": "communication (Comm): reductions, gathers, agreement on errors",
        "neighbor": "neighbor settings (Neighbor): skin",
        "request_neighbor_list": "request_neighbor_list(kind, cutoff, occasional=, group=) in init_run",
        "build_neighbor_list": "build_neighbor_list(nlist): an occasional list, from current positions",
        "add_particles": "add_particles(x, type, v=, **per_atom): insert particles (pre_exchange)",
        "delete_particles": "delete_particles(rows): remove owned particles (pre_exchange)",
        "random_key": "random_key(seed): the key random numbers use (new after reset_timestep goes back)",
        "info": "info(message): a line on screen and in the log",
        "warn": "warn(message): a warning on screen and in the log; the run goes on",
        "change_timestep": "change_timestep(dt): a new time step mid-run; styles redo their constants of it in reset_dt(sim)",
    },
    "Particles": {
        "nlocal": "owned particles", "nghost": "ghost particles", "nall": "nlocal + nghost",
        "x": "(nall, 3)", "v": "(nall, 3)", "f": "(nall, 3)", "tag": "(nall,) int64",
        "type": "(nall,) int32", "mask": "(nall,) uint32 group bits", "image": "(nall, 3) int32",
        "radius": "(nall,) when requested", "rmass": "(nall,) when requested",
        "omega": "(nall, 3) when requested", "torque": "(nall, 3) when requested",
        "molecule": "(nall,) int64 molecule ids (0: none), with particle_style molecular, bond, angle, full (or hybrid with one)",
        "q": "(nall,) charges, with particle_style charge, full",
        "body_mass": "(nall,) when a fix of rigid bodies provides it (sphere styles): the mass of each particle's body, 0 for particles in none; granular contacts take it for the effective mass (LAMMPS's mass_rigid)",
        "arrays": "{name: array} of every per-atom array, custom ones included",
        "request": "request(name, width=, dtype=, default=, ghost=, replicate=): allocate a per-atom array (ghost=False: ghosts do not carry it; replicate=\"copy\": the replicate command copies it, \"refuse\" (default): replicate refuses while it exists)",
        "has": "has(name): whether a per-atom array exists",
        "index_of_tag": "index_of_tag(tag): the owned row of a global id, or -1",
        "owned_rows": "owned_rows(tags): the owned row of each global id of an array, -1 for those not owned here",
        "num_bond": "(nall,) int32 bonds stored on each particle (on a bond's first particle only), in a scene with bonds",
        "bond_type": "(nall, B) int32 their types (> 0 computed, < 0 turned off, 0 broken)",
        "bond_atom": "(nall, B) int64 the id of each bond's other particle",
        "nspecial": "(nall, 3) int32 per owned particle: n12, n12 + n13, n12 + n13 + n14 (ghosts do not carry it)",
        "special": "(nall, S) int64 per owned particle: the ids of its 1-2, then 1-3, then 1-4 neighbors",
    },
    "Box": {
        "lo": "lower corner (3,)", "hi": "upper corner (3,)", "length": "hi - lo (3,)",
        "volume": "volume (area in 2-d)", "periodic": "(bool, bool, bool)", "dimension": "2 or 3",
        "inside": "inside(x): which positions lie in the box",
        "bounds_label": "the boundary label of a dump header ('pp pp ff'; given sim.periodicity, 'pp ff mm')",
    },
    "Comm": {
        "rank": "this rank", "nprocs": "number of ranks", "is_root": "rank 0",
        "sum": "sum over ranks", "max": "max over ranks", "min": "min over ranks",
        "agree": "agree(message): the same one-line error on every rank when any rank has one",
        "gather_rows": "all ranks' rows on rank 0", "allgather_rows": "all ranks' rows everywhere",
        "bcast": "rank 0's value everywhere",
        "forward_comm": "forward_comm(particles, names): owners' values onto their ghosts",
        "reverse_comm": "reverse_comm(particles, names): ghosts' values summed onto their owners",
        "reverse_rows": "reverse_rows(rows, ghosts=None): ghost rows (of every ghost, or of those named) back to "
                        "their owners, merged by the style (with ghosts named: valid until the next such call)",
        "owners": "owners(particles): owned row of every local particle, -1 for remote ghosts",
        "send_rows": "send_rows(rows, ranks, kept=False): each row to the rank named; returns (rows received, the rank each came from) (kept=True: in buffers valid until the next such call; on one rank the rows given)",
        "rank_of": "rank_of(points): the rank whose sub-domain holds each point (points inside the box)",
    },
    "MoleculeTemplate": {
        "id": "the template's ID", "natoms": "its number of atoms", "ntypes": "its largest type",
        "coords": "(natoms, 3) coordinates as the file gives them (distance)",
        "types": "(natoms,) int64 types, offsets to an inserting style's type",
        "radius": "(natoms,) radii (half the Diameters), or None without that section",
        "rmass": "(natoms,) masses (the Masses section), or None without it",
        "center": "(3,) the geometric centre, the mean of the coordinates",
        "dx": "(natoms, 3) the coordinates less the centre",
        "molradius": "the largest |dx_i| + radius_i (radius 0 without Diameters)",
        "masses": "masses(type_mass): per-atom masses, Masses or type_mass[types] (an array indexed by type)",
        "mass_properties": "mass_properties(type_mass): (total mass, centre of mass (3,), inertia tensor about it "
                           "as xx yy zz yz xz xy), the header's mass, com and inertia where given",
    },
    "Groups": {"bit": "bit(name): the group's mask bit", "select": "select(sim, name): owned mask"},
    "Units": {"name": "lj, real, metal, si, cgs, micro or nano", "boltz": "k_B", "mvv2e": "m v^2 to energy",
              "nktv2p": "energy density to pressure", "ftm2v": "f dt / m to velocity (integrators)",
              "qe2f": "charge * electric field to force (fix efield)",
              "mv2d": "mass/volume to the density thermo reports"},
    "Neighbor": {"skin": "the neighbor skin (distance)",
                 "exclude_molecules": "exclude_molecules(group, kind='intra'): no pairs of the group within one molecule "
                                      "(or between two: 'inter'; or within one of id > 0: 'body'), as neigh_modify "
                                      "exclude molecule/intra",
                 "xhold": "the owned particles' positions at the last build of the lists (nlocal, 3), or None before one",
                 "radii_vary": "True in a run where a fix changes radii (Fix.varies_radius): a style keeping "
                               "its own candidate lists counts radius growth as a move"},
    "NeighborList": {"kind": "half or full", "half_list": "kind == 'half'",
                     "cutoff": "(ntypes+1)^2 cutoffs", "offsets": "CSR offsets (nlocal+1,)",
                     "neighbors": "CSR neighbor rows", "occasional": "built on demand",
                     "version": "one more at every build: what a style made from the list is stale"},
    "Variables": {"value": "value(name): v_NAME as a number",
                  "style": "style(name): the variable's style (equal, atom, vector, index, ...)",
                  "atom_values": "atom_values(name): an atom-style v_NAME, one float per owned particle (nlocal,)"},
    "Pair": {"name": "the style name", "per_atom": "per-atom arrays it needs",
             "timestep_limits": "timestep_limits(sim) of a ContactTimes style (granular): contact, Hertz and Rayleigh times",
             "contacts": "contacts(sim, group): the contacts of a ContactTable style (granular pair styles): rows i, j, force on i",
             "virial": "six values a style on a full list sets on vflag steps (sum r.f misses its ghosts)",
             "single": "single(sim, i, j, delta): (F/r, energy) of chosen pairs, rows i, j, separations x_i - x_j (LAMMPS's Pair::single)",
             "extract": "extract(name): a coefficient as a type-pair table, or a pair_style value (LAMMPS's Pair::extract)",
             "cutsq": "squared cutoffs per type pair, (ntypes+1, ntypes+1), set when a run starts"},
}
