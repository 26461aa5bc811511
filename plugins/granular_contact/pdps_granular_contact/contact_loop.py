"""The parts of the generated contact loops (composition.ContactModel.kernels) that do not depend on
the sub-models: filling a contact's quantities (contact_state) from the particle arrays, applying
its forces and torques, and the loop templates themselves. A generated module imports everything
here and from contact_block, then defines ``HISTORY`` (the values a contact keeps), ``contact(c,
coeff, ti, tj, hist)`` (the sub-models in order, inlined into the block loop), ``contact_one`` (the
same compiled once, which the scalar loops call) and the loops below. Pair loops go a block of
contacts at a time (contact_block's docstring): they gather each touching pair into the block's
columns (``gather_pair``), compute the block (``block_contacts``) and add its results to the
particles (``scatter_contacts``) in list order.
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import find_slot, open_slot

from .contact_models import contact_mass
from .contact_block import (BLOCK, HIST_IN, IN_DX, IN_DY, IN_DZ, IN_FROZEN_I, IN_FROZEN_J, IN_MASS_I, IN_MASS_J,
                            IN_RADIUS_I, IN_RADIUS_J, IN_TEMPERATURE_I, IN_TEMPERATURE_J, IN_VX, IN_VY, IN_VZ, IN_WIX,
                            IN_WIY, IN_WIZ, IN_WJX, IN_WJY, IN_WJZ, OUT_FX, OUT_FY, OUT_FZ, OUT_HEAT, OUT_TIX, OUT_TIY,
                            OUT_TIZ, OUT_TJX, OUT_TJY, OUT_TJZ, ROW_I, ROW_J, SLOT_I, SLOT_J, TYPE_I, TYPE_J, sqrt)
from .contact_models import contact_mass
from .contact_slots import load_history, wall_slots
from .contact_state import (DELTA, DIMENSION, DT, FN, FTX, FTY, FTZ, HEAT, LIQUID_FLUX_I, LIQUID_FLUX_J, LIQUID_I,
                            LIQUID_J, MASS_I, MASS_J, MRX, MRY, MRZ, MTX, MTY, MTZ, M_EFF, NX, NY, NZ, R, RADIUS_I,
                            RADIUS_J, R_EFF, UPDATE, VX, VY, VZ, WALL, WIX, WIY, WIZ, WJX, WJY, WJZ, ARM_I, ARM_J,
                            TEMPERATURE_I, TEMPERATURE_J)

__all__ = ["math", "find_slot", "open_slot", "load_history", "wall_slots", "set_run", "fill_pair", "fill_wall",
           "apply_wall", "tangential_torque", "gather_pair", "gather_temperatures", "fill_block", "block_result",
           "apply_block", "apply_block_heat", "log_block", "apply_close"]


@njit(cache=True)
def set_run(c, dt, update, dimension):
    """What every contact of this force computation shares (and no liquid, where none is read)."""
    c[DT] = dt
    c[UPDATE] = 1.0 if update else 0.0
    c[DIMENSION] = dimension
    c[LIQUID_I] = 0.0
    c[LIQUID_J] = 0.0


@njit(cache=True)
def fill_pair(c, x, v, omega, radius, rmass, body_mass, mask, freeze_bit, i, j, delx, dely, delz, rsq):
    """Spheres i and j at separation (delx, dely, delz) = x_i - x_j, rsq > 0, touching."""
    r = math.sqrt(rsq)
    c[R] = r
    c[RADIUS_I] = radius[i]
    c[RADIUS_J] = radius[j]
    c[DELTA] = radius[i] + radius[j] - r
    c[R_EFF] = radius[i] * radius[j] / (radius[i] + radius[j])
    c[WALL] = 0.0
    c[NX] = delx / r
    c[NY] = dely / r
    c[NZ] = delz / r
    m_i = contact_mass(rmass, body_mass, i)
    m_j = contact_mass(rmass, body_mass, j)
    c[MASS_I] = m_i
    c[MASS_J] = m_j
    m_eff = m_i * m_j / (m_i + m_j)
    # a particle held at rest (fix freeze) meets the other with the other's mass
    if mask[i] & freeze_bit:
        m_eff = m_j
    if mask[j] & freeze_bit:
        m_eff = m_i
    c[M_EFF] = m_eff
    c[VX] = v[i, 0] - v[j, 0]
    c[VY] = v[i, 1] - v[j, 1]
    c[VZ] = v[i, 2] - v[j, 2]
    c[WIX] = omega[i, 0]
    c[WIY] = omega[i, 1]
    c[WIZ] = omega[i, 2]
    c[WJX] = omega[j, 0]
    c[WJY] = omega[j, 1]
    c[WJZ] = omega[j, 2]


@njit(cache=True)
def fill_wall(c, v, omega, radius, rmass, body_mass, i, distance, normal, wall_velocity, curvature, k):
    """Particle i whose centre is ``distance[k]`` < R_i from a wall element, normal ``normal[k]`` from
    the surface to the centre, the wall moving at ``wall_velocity[k]`` at the contact point; its
    mass a rigid body's where it is in one (``body_mass``, else empty). A curved wall of radius
    ``curvature[k]`` (negative: concave; an empty array, or 0: flat) makes R* = R_i r_w / (R_i + r_w)
    (LAMMPS's fix wall/gran zcylinder); else R* = R_i."""
    c[R] = distance[k]
    c[RADIUS_I] = radius[i]
    c[RADIUS_J] = 0.0
    c[DELTA] = radius[i] - distance[k]
    wall_radius = curvature[k] if len(curvature) > 0 else 0.0
    c[R_EFF] = radius[i] if wall_radius == 0.0 else radius[i] * wall_radius / (radius[i] + wall_radius)
    c[WALL] = 1.0
    c[NX] = normal[k, 0]
    c[NY] = normal[k, 1]
    c[NZ] = normal[k, 2]
    m_i = contact_mass(rmass, body_mass, i)
    c[MASS_I] = m_i
    c[MASS_J] = 0.0
    c[M_EFF] = m_i
    c[VX] = v[i, 0] - wall_velocity[k, 0]
    c[VY] = v[i, 1] - wall_velocity[k, 1]
    c[VZ] = v[i, 2] - wall_velocity[k, 2]
    c[WIX] = omega[i, 0]
    c[WIY] = omega[i, 1]
    c[WIZ] = omega[i, 2]
    c[WJX] = 0.0
    c[WJY] = 0.0
    c[WJZ] = 0.0


@njit(cache=True)
def tangential_torque(c, arm, out):
    """-arm n x F_t into ``out`` (3)."""
    out[0] = -arm * (c[NY] * c[FTZ] - c[NZ] * c[FTY])
    out[1] = -arm * (c[NZ] * c[FTX] - c[NX] * c[FTZ])
    out[2] = -arm * (c[NX] * c[FTY] - c[NY] * c[FTX])


@njit(cache=True)
def apply_wall(c, f, torque, i, force, tangential):
    """Force and torque on particle i from a wall contact; the force into ``force`` (3), the torque
    of the tangential force alone into ``tangential`` (3)."""
    force[0] = c[FN] * c[NX] + c[FTX]
    force[1] = c[FN] * c[NY] + c[FTY]
    force[2] = c[FN] * c[NZ] + c[FTZ]
    tangential_torque(c, c[ARM_I], tangential)
    for d in range(3):
        f[i, d] += force[d]
    torque[i, 0] += tangential[0] - c[MRX] - c[MTX]
    torque[i, 1] += tangential[1] - c[MRY] - c[MTY]
    torque[i, 2] += tangential[2] - c[MRZ] - c[MTZ]


@njit(inline="always")
def gather_pair(block_in, block_index, b, v, omega, radius, rmass, body_mass, type_, mask, freeze_bit, i, j, delx, dely,
                delz, slot_i, slot_j):
    """Spheres i and j at separation (delx, dely, delz) = x_i - x_j, touching, into column b of the
    block (fill_block computes from them what fill_pair does)."""
    block_in[IN_DX * BLOCK + b] = delx
    block_in[IN_DY * BLOCK + b] = dely
    block_in[IN_DZ * BLOCK + b] = delz
    block_in[IN_RADIUS_I * BLOCK + b] = radius[i]
    block_in[IN_RADIUS_J * BLOCK + b] = radius[j]
    block_in[IN_MASS_I * BLOCK + b] = contact_mass(rmass, body_mass, i)
    block_in[IN_MASS_J * BLOCK + b] = contact_mass(rmass, body_mass, j)
    block_in[IN_FROZEN_I * BLOCK + b] = 1.0 if mask[i] & freeze_bit else 0.0
    block_in[IN_FROZEN_J * BLOCK + b] = 1.0 if mask[j] & freeze_bit else 0.0
    block_in[IN_VX * BLOCK + b] = v[i, 0] - v[j, 0]
    block_in[IN_VY * BLOCK + b] = v[i, 1] - v[j, 1]
    block_in[IN_VZ * BLOCK + b] = v[i, 2] - v[j, 2]
    block_in[IN_WIX * BLOCK + b] = omega[i, 0]
    block_in[IN_WIY * BLOCK + b] = omega[i, 1]
    block_in[IN_WIZ * BLOCK + b] = omega[i, 2]
    block_in[IN_WJX * BLOCK + b] = omega[j, 0]
    block_in[IN_WJY * BLOCK + b] = omega[j, 1]
    block_in[IN_WJZ * BLOCK + b] = omega[j, 2]
    block_index[ROW_I * BLOCK + b] = i
    block_index[ROW_J * BLOCK + b] = j
    block_index[SLOT_I * BLOCK + b] = slot_i
    block_index[SLOT_J * BLOCK + b] = slot_j
    block_index[TYPE_I * BLOCK + b] = type_[i]
    block_index[TYPE_J * BLOCK + b] = type_[j]


@njit(inline="always")
def gather_temperatures(block_in, b, temp, i, j):
    block_in[IN_TEMPERATURE_I * BLOCK + b] = temp[i]
    block_in[IN_TEMPERATURE_J * BLOCK + b] = temp[j]


@njit(inline="always", _nrt=False, error_model="numpy")
def fill_block(c, block_in, m, dt, update, dimension):
    """fill_pair and set_run for contact m of the block, from what gather_pair put there."""
    c[DT] = dt
    c[UPDATE] = update
    c[DIMENSION] = dimension
    delx = block_in[IN_DX * BLOCK + m]
    dely = block_in[IN_DY * BLOCK + m]
    delz = block_in[IN_DZ * BLOCK + m]
    r = sqrt(delx * delx + dely * dely + delz * delz)
    radius_i = block_in[IN_RADIUS_I * BLOCK + m]
    radius_j = block_in[IN_RADIUS_J * BLOCK + m]
    c[R] = r
    c[RADIUS_I] = radius_i
    c[RADIUS_J] = radius_j
    c[DELTA] = radius_i + radius_j - r
    c[R_EFF] = radius_i * radius_j / (radius_i + radius_j)
    c[WALL] = 0.0
    c[NX] = delx / r
    c[NY] = dely / r
    c[NZ] = delz / r
    m_i = block_in[IN_MASS_I * BLOCK + m]
    m_j = block_in[IN_MASS_J * BLOCK + m]
    c[MASS_I] = m_i
    c[MASS_J] = m_j
    m_eff = m_i * m_j / (m_i + m_j)
    # a particle held at rest (fix freeze) meets the other with the other's mass
    m_eff = m_j if block_in[IN_FROZEN_I * BLOCK + m] != 0.0 else m_eff
    m_eff = m_i if block_in[IN_FROZEN_J * BLOCK + m] != 0.0 else m_eff
    c[M_EFF] = m_eff
    c[VX] = block_in[IN_VX * BLOCK + m]
    c[VY] = block_in[IN_VY * BLOCK + m]
    c[VZ] = block_in[IN_VZ * BLOCK + m]
    c[WIX] = block_in[IN_WIX * BLOCK + m]
    c[WIY] = block_in[IN_WIY * BLOCK + m]
    c[WIZ] = block_in[IN_WIZ * BLOCK + m]
    c[WJX] = block_in[IN_WJX * BLOCK + m]
    c[WJY] = block_in[IN_WJY * BLOCK + m]
    c[WJZ] = block_in[IN_WJZ * BLOCK + m]


@njit(inline="always", _nrt=False, error_model="numpy")
def block_result(c, block_out, m):
    """Contact m's force F_n n + F_t on i, and the torques on i (-a_i n x F_t - M) and on j
    (-a_j n x F_t + M), into the block."""
    cx = c[NY] * c[FTZ] - c[NZ] * c[FTY]
    cy = c[NZ] * c[FTX] - c[NX] * c[FTZ]
    cz = c[NX] * c[FTY] - c[NY] * c[FTX]
    mx = c[MRX] + c[MTX]
    my = c[MRY] + c[MTY]
    mz = c[MRZ] + c[MTZ]
    block_out[OUT_FX * BLOCK + m] = c[FN] * c[NX] + c[FTX]
    block_out[OUT_FY * BLOCK + m] = c[FN] * c[NY] + c[FTY]
    block_out[OUT_FZ * BLOCK + m] = c[FN] * c[NZ] + c[FTZ]
    block_out[OUT_TIX * BLOCK + m] = -(c[ARM_I] * cx + mx)
    block_out[OUT_TIY * BLOCK + m] = -(c[ARM_I] * cy + my)
    block_out[OUT_TIZ * BLOCK + m] = -(c[ARM_I] * cz + mz)
    block_out[OUT_TJX * BLOCK + m] = mx - c[ARM_J] * cx
    block_out[OUT_TJY * BLOCK + m] = my - c[ARM_J] * cy
    block_out[OUT_TJZ * BLOCK + m] = mz - c[ARM_J] * cz


@njit(inline="always")
def apply_block(block_out, m, f, torque, i, j):
    """Contact m's force on i and its negative on j, and their torques."""
    for d in range(3):
        force = block_out[(OUT_FX + d) * BLOCK + m]
        f[i, d] += force
        f[j, d] -= force
        torque[i, d] += block_out[(OUT_TIX + d) * BLOCK + m]
        torque[j, d] += block_out[(OUT_TJX + d) * BLOCK + m]


@njit(inline="always")
def apply_block_heat(block_in, block_out, m, heat_flux, directional, i, j):
    """Contact m's heat Q into i and -Q into j; half of Q (x_i - x_j) to each one's directional flux."""
    q = block_out[OUT_HEAT * BLOCK + m]
    heat_flux[i] += q
    heat_flux[j] -= q
    half = 0.5 * q
    for d in range(3):
        directional[i, d] += half * block_in[(IN_DX + d) * BLOCK + m]
        directional[j, d] += half * block_in[(IN_DX + d) * BLOCK + m]


@njit(inline="always")
def apply_close(c, f, torque, liquid, liquid_flux, i, j):
    """A pair apart within reach (close_pair): its force F_n n + F_t on i and the negative on j,
    the torques -a n x F_t - M on i and -a n x F_t + M on j (the radii as arms), and where the
    model is wet the liquid contents and fluxes of both."""
    cx = c[NY] * c[FTZ] - c[NZ] * c[FTY]
    cy = c[NZ] * c[FTX] - c[NX] * c[FTZ]
    cz = c[NX] * c[FTY] - c[NY] * c[FTX]
    fx = c[FN] * c[NX] + c[FTX]
    fy = c[FN] * c[NY] + c[FTY]
    fz = c[FN] * c[NZ] + c[FTZ]
    f[i, 0] += fx
    f[i, 1] += fy
    f[i, 2] += fz
    f[j, 0] -= fx
    f[j, 1] -= fy
    f[j, 2] -= fz
    mx = c[MRX] + c[MTX]
    my = c[MRY] + c[MTY]
    mz = c[MRZ] + c[MTZ]
    torque[i, 0] -= c[ARM_I] * cx + mx
    torque[i, 1] -= c[ARM_I] * cy + my
    torque[i, 2] -= c[ARM_I] * cz + mz
    torque[j, 0] += mx - c[ARM_J] * cx
    torque[j, 1] += my - c[ARM_J] * cy
    torque[j, 2] += mz - c[ARM_J] * cz
    if len(liquid) > 0:
        liquid[i] = c[LIQUID_I]
        liquid[j] = c[LIQUID_J]
        liquid_flux[i] += c[LIQUID_FLUX_I]
        liquid_flux[j] += c[LIQUID_FLUX_J]


@njit(inline="always")
def log_block(block_out, m, log_pairs, log_force, logged, i, j):
    """Contact m (rows i, j) and its force on i, after ``logged[0]`` (a ContactTable style's log)."""
    row = logged[0]
    if row < log_pairs.shape[0]:
        log_pairs[row, 0] = i
        log_pairs[row, 1] = j
        for d in range(3):
            log_force[row, d] = block_out[(OUT_FX + d) * BLOCK + m]
        logged[0] = row + 1


@njit(cache=True)
def touching_pairs(x, radius, rows, neighbors, npairs, touching):
    """The list entries whose spheres overlap, in list order, into ``touching``; returns how many.
    Most listed pairs do not touch: one flat loop over the entries, without a branch, finds the few
    that do (a loop per particle mispredicts its exit for most particles, which have two or three
    entries)."""
    m = 0
    for k in range(npairs):
        # unsigned: no test for Python's negative indices at each read of rows i and j
        i = np.uint32(rows[k])
        j = np.uint32(neighbors[k])
        delx = x[i, 0] - x[j, 0]
        dely = x[i, 1] - x[j, 1]
        delz = x[i, 2] - x[j, 2]
        rsq = delx * delx + dely * dely + delz * delz
        radsum = radius[i] + radius[j]
        touching[m] = k
        # coincident centres have no normal (LAMMPS divides by zero): no force
        m += 0 if (rsq >= radsum * radsum) | (rsq == 0.0) else 1
    return m



# The contacts gathered into a block, each through the sub-models (inlined, on a stack copy of its
# quantities: contact_block), into the block's results; compiled vectorised (ContactModel.pair_kernels)
BLOCK_CONTACTS = '''

@njit(inline="always", _nrt=False, error_model="numpy")
def block_contact(c, hist, block_in, block_out, m, coeff, ti, tj, dt, update, dimension):
    fill_block(c, block_in, m, dt, update, dimension)
{heat_fill}{hist_in}    contact(c, coeff, ti, tj, hist)
    block_result(c, block_out, m)
{heat_out}{hist_out}

@njit(cache=True, _nrt=False, error_model="numpy")
def block_contacts(n, block_in, block_out, block_index, coeff, dt, update, dimension):
    """The n contacts gathered into block_in through the sub-models into block_out."""
    c = stack_array(SIZE)
    hist = stack_array(HIST_SIZE)
    flag = 1.0 if update else 0.0
    # one type: the coefficients are read once, not gathered per contact
    if coeff.shape[0] == 2:
        for m in range(n):
            block_contact(c, hist, block_in, block_out, m, coeff, 1, 1, dt, flag, dimension)
    else:
        for m in range(n):
            block_contact(c, hist, block_in, block_out, m, coeff, block_index[TYPE_I * BLOCK + m],
                          block_index[TYPE_J * BLOCK + m], dt, flag, dimension)
'''
HEAT_FILL_BLOCK = """    c[TEMPERATURE_I] = block_in[IN_TEMPERATURE_I * BLOCK + m]
    c[TEMPERATURE_J] = block_in[IN_TEMPERATURE_J * BLOCK + m]
"""
HEAT_OUT_BLOCK = """    block_out[OUT_HEAT * BLOCK + m] = c[HEAT]
"""

# The block's results added to the particles, in list order: forces, torques, the contacts' new
# history on both particles (i keeps it, j's owner its negative: the same spring seen from j)
SCATTER_CONTACTS = '''

@njit(cache=True, _nrt=False)
def scatter_contacts(n, block_in, block_out, block_index, f, torque, history, owner, update, heat_flux, directional,
                     liquid, liquid_flux, log_pairs, log_force, logged):
    for m in range(n):
        i = block_index[ROW_I * BLOCK + m]
        j = block_index[ROW_J * BLOCK + m]
        apply_block(block_out, m, f, torque, i, j)
{store}{heat_apply}{log}'''
STORE = """        slot_i = block_index[SLOT_I * BLOCK + m]
        slot_j = block_index[SLOT_J * BLOCK + m]
        if update or slot_i >= 0:
            jo = owner[j] if owner[j] >= 0 else j
{values}"""
# one history value of the contact: a tangential spring is seen negated from j (sign -), a rolling
# displacement or a twist angle the same (sign empty: a sub-model's history_transfer)
STORE_VALUE = """            value = block_out[(HIST_OUT + {h}) * BLOCK + m]
            history[i, HISTORY * slot_i + {h}] = value
            if slot_j >= 0:
                history[jo, HISTORY * slot_j + {h}] = {sign}value
"""
HEAT_APPLY = """        apply_block_heat(block_in, block_out, m, heat_flux, directional, i, j)
"""
# each contact and its force on i, for a style that lists its last force computation's contacts
LOG = """        log_block(block_out, m, log_pairs, log_force, logged, i, j)
"""

# a wet model's liquid (contact_state LIQUID_*): the particles' contents gathered, given to the
# contact, its contents (a cap may lower them) written back and its fluxes added
LIQUID_GATHER = """            block_in[IN_LIQUID_I * BLOCK + b] = liquid[i]
            block_in[IN_LIQUID_J * BLOCK + b] = liquid[j]
"""
LIQUID_FILL_BLOCK = """    c[LIQUID_I] = block_in[IN_LIQUID_I * BLOCK + m]
    c[LIQUID_J] = block_in[IN_LIQUID_J * BLOCK + m]
"""
LIQUID_OUT_BLOCK = """    block_out[OUT_LIQUID_I * BLOCK + m] = c[LIQUID_I]
    block_out[OUT_LIQUID_J * BLOCK + m] = c[LIQUID_J]
    block_out[OUT_LIQUID_FLUX_I * BLOCK + m] = c[LIQUID_FLUX_I]
    block_out[OUT_LIQUID_FLUX_J * BLOCK + m] = c[LIQUID_FLUX_J]
"""
LIQUID_APPLY = """        liquid[i] = block_out[OUT_LIQUID_I * BLOCK + m]
        liquid[j] = block_out[OUT_LIQUID_J * BLOCK + m]
        liquid_flux[i] += block_out[OUT_LIQUID_FLUX_I * BLOCK + m]
        liquid_flux[j] += block_out[OUT_LIQUID_FLUX_J * BLOCK + m]
"""
LIQUID_FILL_ONE = """            c[LIQUID_I] = liquid[i]
            c[LIQUID_J] = liquid[j]
"""

# the heat conduction of a contact, where a heat model is composed (fix heat/gran's): the fluxes of
# owned and ghost rows are zeroed first, ghosts' summed onto their owners by the fix afterwards
HEAT_ZERO = """    for i in range(len(heat_flux)):
        heat_flux[i] = 0.0
        for d in range(3):
            directional[i, d] = 0.0
"""
HEAT_GATHER = """            gather_temperatures(block_in, b, temp, i, j)
"""
HIST_GATHER = """            for h in range(HISTORY):
                block_in[(HIST_IN + h) * BLOCK + b] = hist[h]
"""
NO_SLOTS = """            slot_i = -1
            slot_j = -1
"""

# a full block computed and added; the calls after the pair loop, for the last, partial one
FLUSH = """block_contacts(b, block_in, block_out, block_index, coeff, dt, update, dimension)
scatter_contacts(b, block_in, block_out, block_index, f, torque, history, owner, update, heat_flux, directional,
                 liquid, liquid_flux, log_pairs, log_force, logged)"""


def flush(indent):
    return "".join(" " * indent + line + "\n" for line in FLUSH.splitlines())


# _nrt=False in the loops below: the contact helpers store into arrays under branches, where numba
# keeps an atomic, out-of-line reference count of every array they take around each call (numba
# issue #2350); nothing here allocates
PAIR_FORCES = '''

@njit(cache=True, _nrt=False)
def pair_forces(x, v, omega, radius, rmass, body_mass, type_, mask, f, torque, tag, owner, offsets, neighbors,
                nlocal, coeff, freeze_bit, dt, update, dimension, partner, history, touched, touching, ntouching,
                entry_slots, block_in, block_out, block_index, temp, heat_flux, directional, liquid, liquid_flux,
                log_pairs, log_force, logged):
    """Contact forces and torques of a half list; returns -1, or the tag of a particle whose contact
    slots are full. The list entries of the contacts, in list order, go into ``touching`` and their
    number into ``ntouching[0]`` (the end-of-step sweep of the history reads them); where the
    composition logs its contacts, (i, j) and the force on i into ``log_pairs``, ``log_force``
    after ``logged[0]``; where it keeps the slots of each list entry's contact (``entry_slots``, -1
    for none yet), they are read there instead of searched for; where a wet model is composed, the
    particles' surface liquid contents ``liquid`` (written back) and fluxes ``liquid_flux`` (added
    to). ``block_*``: ContactModel.block()."""
{heat_zero}    hist = stack_array(HIST_SIZE)
    m = 0
    b = 0
    for i in range(nlocal):
        xi0 = x[i, 0]
        xi1 = x[i, 1]
        xi2 = x[i, 2]
        radi = radius[i]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            # most listed pairs (within the skin) do not touch: only their distance is measured
            delx = xi0 - x[j, 0]
            dely = xi1 - x[j, 1]
            delz = xi2 - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            radsum = radi + radius[j]
{beyond}            # coincident centres have no normal: no force
            if rsq >= radsum * radsum or rsq == 0.0:
                continue
{load}            touching[m] = k
            m += 1
            gather_pair(block_in, block_index, b, v, omega, radius, rmass, body_mass, type_, mask, freeze_bit, i, j,
                        delx, dely, delz, slot_i, slot_j)
{heat_gather}{hist_gather}            b += 1
            if b == BLOCK:
{flush_full}                b = 0
{flush_last}    ntouching[0] = m
    return -1
'''

# a contact that, once made, lasts beyond touching (JKR's neck: a normal model with a ``pulloff``):
# spheres apart that hold a contact slot reach as far as the generated ``lasting`` says
BEYOND = """            if rsq >= radsum * radsum:
                radsum += lasting(coeff, type_[i], type_[j], radi, radius[j], partner, i, tag[j])
"""

# spheres apart but within the reach of a sub-model's ``close`` (a liquid bridge): one at a time
CLOSE = """            if rsq >= radsum * radsum:
                far = coeff[type_[i], type_[j], REACH] * radsum
                if rsq < far * far:
                    full = close_pair(x, v, omega, radius, rmass, body_mass, type_, mask, f, torque, tag, owner, coeff,
                                      freeze_bit, dt, update, dimension, partner, history, touched, liquid,
                                      liquid_flux, i, j, delx, dely, delz, rsq)
                    if full >= 0:
                        return full
                continue
"""

# The sub-models of a pair apart within reach (``apart``, generated), its history found where it
# has one and kept where it is not all zero (a contact made apart opens its slots then); the
# touched flags keep a held contact past the next build of the list
CLOSE_PAIR = '''

@njit(cache=True, _nrt=False)
def close_pair(x, v, omega, radius, rmass, body_mass, type_, mask, f, torque, tag, owner, coeff, freeze_bit, dt,
               update, dimension, partner, history, touched, liquid, liquid_flux, i, j, delx, dely, delz, rsq):
    """Spheres i and j apart, closer than the reach; returns -1, or the tag of a particle whose contact
    slots are full."""
    c = stack_array(SIZE)
    hist = stack_array(HIST_SIZE)
    set_run(c, dt, update, dimension)
    fill_pair(c, x, v, omega, radius, rmass, body_mass, mask, freeze_bit, i, j, delx, dely, delz, rsq)
    if len(liquid) > 0:
        c[LIQUID_I] = liquid[i]
        c[LIQUID_J] = liquid[j]
    jo = owner[j] if owner[j] >= 0 else j
    slot_i = find_slot(partner, i, tag[j]) if HISTORY > 0 else -1
    slot_j = find_slot(partner, jo, tag[i]) if slot_i >= 0 else -1
    for d in range(HISTORY):
        hist[d] = history[i, HISTORY * slot_i + d] if slot_i >= 0 else 0.0
    apart(c, coeff, type_[i], type_[j], hist)
    held = False
    for d in range(HISTORY):
        if hist[d] != 0.0:
            held = True
    if held and update and slot_i < 0:
        slot_i = open_slot(partner, history, i, tag[j], HISTORY)
        slot_j = open_slot(partner, history, jo, tag[i], HISTORY)
        if slot_i < 0 or slot_j < 0:
            return tag[i] if slot_i < 0 else tag[j]
{store}    apply_close(c, f, torque, liquid, liquid_flux, i, j)
    return -1
'''
CLOSE_STORE = """    if slot_i >= 0 and slot_j >= 0:
        if update and held:
            touched[i, slot_i] = True
            touched[jo, slot_j] = True
{values}"""
CLOSE_STORE_VALUE = """        history[i, HISTORY * slot_i + {h}] = hist[{h}]
        history[jo, HISTORY * slot_j + {h}] = {sign}hist[{h}]
"""

# The same over the touching entries of a list found first (``touching``: their entries, ``rows``:
# each entry's particle i): one flat, branch-free pass finds the few listed pairs that touch, which
# a loop per particle pays for with a mispredicted exit at most particles (gran_box)
PAIR_FORCES_TOUCHING = '''

@njit(cache=True, _nrt=False)
def pair_forces_touching(x, v, omega, radius, rmass, body_mass, type_, mask, f, torque, tag, owner, rows,
                         neighbors, touching, ntouching, coeff, freeze_bit, dt, update, dimension, partner, history,
                         touched, block_in, block_out, block_index, temp, heat_flux, directional, liquid,
                         liquid_flux, log_pairs, log_force, logged):
    """pair_forces over the list entries ``touching[:ntouching]`` (touching_pairs found them)."""
{heat_zero}    hist = stack_array(HIST_SIZE)
    b = 0
    for m in range(ntouching):
        i = rows[touching[m]]
        j = neighbors[touching[m]]
        delx = x[i, 0] - x[j, 0]
        dely = x[i, 1] - x[j, 1]
        delz = x[i, 2] - x[j, 2]
{load}        gather_pair(block_in, block_index, b, v, omega, radius, rmass, body_mass, type_, mask, freeze_bit, i, j,
                    delx, dely, delz, slot_i, slot_j)
{heat_gather}{hist_gather}        b += 1
        if b == BLOCK:
{flush_full}            b = 0
{flush_last}    return -1
'''

# the history of a contact (composed laws that keep some), found or made on both particles
LOAD = """            slot_i, slot_j = load_history(partner, history, touched, owner, tag, i, j, update, hist)
            if update and (slot_i < 0 or slot_j < 0):
                return tag[i] if slot_i < 0 else tag[j]
"""
# The same where each list entry's slots are kept between steps (a style whose slots stay put
# between two builds of the list: pair gran forgets contacts only at builds): a contact searches its
# slots among the particle's once, then reads them from ``entry_slots``
LOAD_CACHED = """            slot_i = entry_slots[k, 0]
            slot_j = entry_slots[k, 1]
            if slot_i >= 0 and update:
                for d in range(HISTORY):
                    hist[d] = history[i, HISTORY * slot_i + d]
                # seen this step: a mirror on another rank's ghost goes back to its owner (Mirrors)
                touched[i, slot_i] = True
                touched[owner[j] if owner[j] >= 0 else j, slot_j] = True
            else:
                slot_i, slot_j = load_history(partner, history, touched, owner, tag, i, j, update, hist)
                if update and (slot_i < 0 or slot_j < 0):
                    return tag[i] if slot_i < 0 else tag[j]
                if update:
                    entry_slots[k, 0] = slot_i
                    entry_slots[k, 1] = slot_j
"""

PAIR_CONTACTS = '''

@njit(cache=True, _nrt=False)
def pair_contacts(x, v, omega, radius, rmass, body_mass, type_, mask, tag, offsets, neighbors, nlocal, coeff,
                  freeze_bit, dt, dimension, partner, history, groupbit, liquid, rows, force_out, tangential_out,
                  hist_out):
    """Every contact of the half list whose two particles are in ``groupbit``, evaluated as the
    setup force computation does (nothing stored; ``liquid``: the surface liquid contents, for a
    wet model): returns how many; their rows (i, j), forces on i, tangential parts and history
    values (as i sees them) into the ``*_out`` arrays."""
    c = stack_array(SIZE)
    hist = stack_array(HIST_SIZE)
    set_run(c, dt, False, dimension)
    count = 0
    width = HISTORY
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & groupbit:
                continue
            delx = x[i, 0] - x[j, 0]
            dely = x[i, 1] - x[j, 1]
            delz = x[i, 2] - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            radsum = radius[i] + radius[j]
            if rsq >= radsum * radsum or rsq == 0.0:
                continue
            slot = find_slot(partner, i, tag[j]) if len(partner) > 0 else -1
            for d in range(width):
                hist[d] = history[i, width * slot + d] if slot >= 0 else 0.0
                hist_out[count, d] = hist[d]
            fill_pair(c, x, v, omega, radius, rmass, body_mass, mask, freeze_bit, i, j, delx, dely, delz, rsq)
{liquid_fill}            contact_one(c, coeff, type_[i], type_[j], hist)
            rows[count, 0] = i
            rows[count, 1] = j
            force_out[count, 0] = c[FN] * c[NX] + c[FTX]
            force_out[count, 1] = c[FN] * c[NY] + c[FTY]
            force_out[count, 2] = c[FN] * c[NZ] + c[FTZ]
            tangential_out[count, 0] = c[FTX]
            tangential_out[count, 1] = c[FTY]
            tangential_out[count, 2] = c[FTZ]
            count += 1
    return count
'''

# A wall contact's values: the sub-models' history, then the contact's last normal (for handing the
# contact on between the faces of a mesh: wall_slots)
WALL_FORCES = '''

@njit(cache=True, _nrt=False)
def wall_forces(rows, starts, nrows, distance, normal, key, touch, wall_velocity, curvature, v, omega, f, torque,
                radius, rmass, body_mass, ptype, wall_type, coeff, dt, update, dimension, partner, values, used, slots,
                force, tangential, contact_force, log, logged, transfer_cos):
    """Force and torque on each particle rows[k] (k < nrows) from its wall contacts starts[k] ..
    starts[k + 1] (distance of its centre from the element ``key``, normal from the surface to the
    centre, contact point ``touch``, the wall's velocity there), each contact's force into
    ``contact_force``; with a ``log`` of rows (particle row, element, contact point, wall velocity,
    force, torque of the tangential force, overlap, area, history), one row per touching contact
    after ``logged[0]`` (which counts them). Returns -1, or the row of a particle with no free history
    slot."""
    c = stack_array(SIZE)
    hist = stack_array(HIST_SIZE)
    set_run(c, dt, update, dimension)
    width = HISTORY
    stride = values.shape[1] // partner.shape[1]
    for q in range(nrows):
        i = rows[q]
        start = starts[q]
        end = starts[q + 1]
        r_i = radius[i]
        if not wall_slots(i, start, end, distance, normal, key, r_i, partner, values, width, update, used, slots,
                          transfer_cos):
            return i
        for k in range(start, end):
            for d in range(3):
                contact_force[k, d] = 0.0
            if distance[k] >= r_i:
                continue
            s = slots[k - start]
            for h in range(width):
                hist[h] = values[i, s * stride + h] if s >= 0 else 0.0
            fill_wall(c, v, omega, radius, rmass, body_mass, i, distance, normal, wall_velocity, curvature, k)
            contact_one(c, coeff, ptype[i], wall_type, hist)
            if s >= 0:
                for h in range(width):
                    values[i, s * stride + h] = hist[h]
                if update:
                    for d in range(3):
                        values[i, s * stride + width + d] = normal[k, d]
            apply_wall(c, f, torque, i, force, tangential)
            for d in range(3):
                contact_force[k, d] = force[d]
            row = logged[0]
            if row < log.shape[0]:
                log[row, 0] = i
                log[row, 1] = key[k]
                for d in range(3):
                    log[row, 2 + d] = touch[k, d]
                    log[row, 5 + d] = wall_velocity[k, d]
                    log[row, 8 + d] = force[d]
                    log[row, 11 + d] = tangential[d]
                log[row, 14] = c[DELTA]
                log[row, 15] = math.pi * (r_i * r_i - distance[k] * distance[k])
                for h in range(min(width, log.shape[1] - 16)):
                    log[row, 16 + h] = hist[h]
                logged[0] = row + 1
    return -1
'''
