"""Global observables every part of the code agrees on: kinetic energy, temperature, pressure.

Conventions are LAMMPS's ``compute temp`` and ``compute pressure``:

    KE = 1/2 sum_i m_i v_i^2                              (times mvv2e)
    T  = 2 KE / (N_dof k_B),   N_dof = d N - d - N_fix    (d = dimension; the centre of mass is fixed;
                                                          N_fix removed by fixes: Fix.dof_removed)
    P  = (N_dof k_B T + sum_i r_i . f_i) / (d V)          (times nktv2p; V is the area in 2-d)

The PDPS manual writes T = <v^2> / 3 k_B; for unit masses and large N the two agree, and the LAMMPS
form is what a LAMMPS user compares against. Sums run over owned particles and then over ranks.
"""

import numpy as np
from numba import njit

from ..errors import SimulationError

NO_RMASS = np.zeros(0)


@njit(cache=True)
def _kinetic_sum(v, type_, mass, rmass, mask, bit, n):
    """(sum of m v^2, count) over the first n particles whose mask has ``bit``, summed in particle
    order as LAMMPS's compute temp sums (no temporaries: thermo may read it at every step)."""
    total = 0.0
    members = 0
    with_rmass = len(rmass) > 0
    for i in range(n):
        if mask[i] & bit:
            m = rmass[i] if with_rmass else mass[type_[i]]
            total += (v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2]) * m
            members += 1
    return total, members


@njit(cache=True)
def _kinetic_tensor(v, type_, mass, rmass, mask, bit, n, out):
    """out = sum of m v_a v_b (xx yy zz xy xz yz) over the first n particles whose mask has ``bit``."""
    out[:] = 0.0
    with_rmass = len(rmass) > 0
    for i in range(n):
        if mask[i] & bit:
            m = rmass[i] if with_rmass else mass[type_[i]]
            out[0] += m * v[i, 0] * v[i, 0]
            out[1] += m * v[i, 1] * v[i, 1]
            out[2] += m * v[i, 2] * v[i, 2]
            out[3] += m * v[i, 0] * v[i, 1]
            out[4] += m * v[i, 0] * v[i, 2]
            out[5] += m * v[i, 1] * v[i, 2]


def masses(sim, selection=slice(None)):
    """Mass of each owned particle: per-particle ``rmass`` when present, else the type's mass."""
    p = sim.particles
    if p.has("rmass"):
        return p.rmass[: p.nlocal][selection]
    return sim.mass[p.type[: p.nlocal]][selection]


def _sums(sim, group):
    p = sim.particles
    return _kinetic_sum(p.v, p.type, sim.mass, p.rmass if p.has("rmass") else NO_RMASS, p.mask,
                        sim.groups.bit(group), p.nlocal)


def count(sim, group="all"):
    return int(sim.comm.sum(int(_sums(sim, group)[1])))


def kinetic_energy(sim, group="all"):
    return sim.comm.sum(0.5 * float(_sums(sim, group)[0])) * sim.units.mvv2e


def clump_rows(sim):
    """The owned particles that are spheres of rigid clumps (a fix offering ``extract("clump_body")``:
    LIGGGHTS's fix multisphere), or None without such a fix. LIGGGHTS's particle energies (compute
    ke, ke/atom, erotate/sphere, thermo ke) leave them out and count their bodies instead."""
    p = sim.particles
    names = [name for fix in sim.fixes.values() if (name := fix.extract("clump_body")) is not None]
    if not names:
        return None
    rows = np.zeros(p.nlocal, dtype=bool)
    for name in names:
        rows |= p.arrays[name][:p.nlocal] >= 0
    return rows


def outside_clumps(sim, chosen):
    """The owned particles of the boolean mask ``chosen`` that are not spheres of rigid clumps."""
    rows = clump_rows(sim)
    return chosen if rows is None else chosen & ~rows


def clump_energies(sim):
    """The rigid clumps' (translational, rotational) kinetic energies, summed over the fixes that
    move clumps (``extract("clump_energies")``); (0, 0) without one."""
    found = [e for fix in sim.fixes.values() if (e := fix.extract("clump_energies")) is not None]
    return (sum(e[0] for e in found), sum(e[1] for e in found))


def kinetic_energy_with_clumps(sim, group="all"):
    """LIGGGHTS's compute ke: the group's particles outside rigid clumps, plus every clump's body
    (the kinetic energy itself where there are none)."""
    rows = clump_rows(sim)
    if rows is None:
        return kinetic_energy(sim, group)
    p = sim.particles
    n = p.nlocal
    chosen = sim.groups.select(sim, group) & ~rows
    v = p.v[:n][chosen]
    own = 0.5 * float(np.sum(masses(sim)[chosen] * np.einsum("ij,ij->i", v, v)))
    return sim.comm.sum(own) * sim.units.mvv2e + clump_energies(sim)[0]


def degrees_of_freedom(sim, group="all", extra=None):
    """d N - d (``extra`` instead of d when given: compute_modify extra/dof), less what fixes remove
    (constraints, rigid bodies: ``Fix.dof_removed``). Fewer than
    0 for a group with particles is an error, as LAMMPS's compute temp ("Temperature compute degrees
    of freedom < 0"): the fixes remove more than the group has; an empty group has 0."""
    d = sim.dimension
    removing = _removing(sim, group)
    members = count(sim, group)
    removed = sum(n for _, n in removing)
    dof = d * members - (d if extra is None else extra) - removed
    if dof < 0 and members > 0:
        fixes = ", ".join(f"fix {fix.id} ({fix.name}) {n}" for fix, n in removing if n)
        error = SimulationError(f"temperature of group {group}: degrees of freedom < 0 ({d} x {members} particles "
                                f"- {d} - {removed} removed by {fixes or 'no fix'} = {dof})")
        # every rank counts the same global totals and stops here alike: one line, not one per rank
        error.agreed = True
        raise error
    return max(dof, 0)


def _removing(sim, group):
    return [(fix, int(fix.dof_removed(sim, group))) for fix in sim.fixes.values() if hasattr(fix, "dof_removed")]


def dof_removed(sim, group="all"):
    """The degrees of freedom the fixes remove from ``group`` (``Fix.dof_removed``; global count)."""
    return sum(n for _, n in _removing(sim, group))


def compute_dof(sim, compute):
    """The degrees of freedom of a temperature compute: its own count where it has one (temp/partial
    counts only its components, LAMMPS's dof_compute), else its group's with its extra/dof."""
    if hasattr(compute, "dof"):
        return compute.dof(sim)
    return degrees_of_freedom(sim, compute.group, getattr(compute, "extra_dof", None))


def temperature(sim, group="all", extra=None):
    dof = degrees_of_freedom(sim, group, extra)
    if dof <= 0:
        return 0.0
    return 2.0 * kinetic_energy(sim, group) / (dof * sim.units.boltz)


def tail_corrections(sim):
    """The pair style's long-range corrections (``pair_modify tail yes``) at the current volume:
    energy, and what each diagonal virial component gains (LAMMPS's etail / V, ptail / V)."""
    pair = sim.pair
    if pair is None or not pair.tail:
        return 0.0, 0.0
    return pair.etail / sim.box.volume, pair.ptail / sim.box.volume


def virial_trace(sim):
    """sum_i r_i . f_i over the box's dimensions (x, y and, in 3-d, z), with the tail correction."""
    sim.run_state.require_virial()
    return float(sim.comm.sum(float(sum(sim.virial[: sim.dimension])))) + sim.dimension * tail_corrections(sim)[1]


def pressure(sim, temp=None, temp_group="all", extra=None, dof=None):
    """Pressure of the whole system from the virial theorem. The kinetic part is N_dof k_B T of
    ``temp_group`` (LAMMPS: the temperature compute's own degrees of freedom, ``dof`` where given,
    else ``extra`` as degrees_of_freedom's); T defaults to its temperature."""
    if temp is None:
        temp = temperature(sim, temp_group, extra)
    if dof is None:
        dof = degrees_of_freedom(sim, temp_group, extra)
    return (dof * sim.units.boltz * temp + virial_trace(sim)) / (sim.dimension * sim.box.volume) \
        * sim.units.nktv2p


def pressure_tensor(sim, temp_group="all"):
    """The pressure tensor (xx yy zz xy xz yz), as LAMMPS's compute pressure vector: the kinetic tensor
    sum m v_a v_b of ``temp_group`` plus the virial tensor, over the volume (the tail correction on
    the diagonal)."""
    sim.run_state.require_virial()
    p = sim.particles
    kinetic = np.zeros(6)
    _kinetic_tensor(p.v, p.type, sim.mass, p.rmass if p.has("rmass") else NO_RMASS, p.mask,
                    sim.groups.bit(temp_group), p.nlocal, kinetic)
    total = np.asarray(sim.comm.sum(kinetic * sim.units.mvv2e + np.asarray(sim.virial, dtype=np.float64)))
    total[:3] += tail_corrections(sim)[1]
    return total / sim.box.volume * sim.units.nktv2p


def virial_parts(sim):
    """(the pair style's virial tensor, the fixes' share), xx yy zz xy xz yz summed over ranks, the
    tail correction with the pair's: what LAMMPS's compute pressure keywords pair and fix select."""
    sim.run_state.require_virial()
    pair = np.asarray(sim.comm.sum(np.asarray(sim.run_state.pair_virial, dtype=np.float64)))
    total = np.asarray(sim.comm.sum(np.asarray(sim.virial, dtype=np.float64)))
    fixes = total - pair
    pair = pair.copy()
    pair[:3] += tail_corrections(sim)[1]
    return pair, fixes


def kinetic_tensor(sim, group="all"):
    """sum m v_a v_b (xx yy zz xy xz yz) of the group, times mvv2e: LAMMPS's compute temp vector."""
    p = sim.particles
    tensor = np.zeros(6)
    _kinetic_tensor(p.v, p.type, sim.mass, p.rmass if p.has("rmass") else NO_RMASS, p.mask,
                    sim.groups.bit(group), p.nlocal, tensor)
    return np.asarray(sim.comm.sum(tensor * sim.units.mvv2e), dtype=np.float64)


def potential_energy(sim):
    sim.run_state.require_energy()
    return float(sim.comm.sum(sim.pe)) + tail_corrections(sim)[0]


def bond_energy(sim):
    """The bond styles' energy (LAMMPS's ebond; emol, as pdps has no angle styles)."""
    sim.run_state.require_energy()
    return float(sim.comm.sum(sim.run_state.ebond))


def pair_energy(sim):
    """The pair style's energy (LAMMPS's evdwl, with the tail correction), without fixes'."""
    sim.run_state.require_energy()
    return float(sim.comm.sum(sim.run_state.evdwl)) + tail_corrections(sim)[0]
