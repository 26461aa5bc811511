"""Per-contact history (tangential spring of a frictional contact, a wall contact's state) that
survives neighbor list rebuilds and moves with its particles.

Each particle keeps up to ``capacity`` contacts in two per-atom arrays, so re-sorting and (later)
migration between ranks carry them along:

    {name}_partner   int64, capacity per particle: the partner's tag (or a wall element id), -1 = free
    {name}_history   float64, capacity * width per particle: the contact's values

A contact between particles i and j is stored on both, each in its own frame (a pair style stores
the tangential displacement on i and its negative on j), so whichever of the two computes the pair
after a rebuild finds the history. Numba kernels call ``find_slot``/``open_slot``/``close_slot``.

    history = ContactHistory(sim, "shear", width=3)        # in a style's init
    kernel(..., history.partner, history.values, ...)      # arrays of owned and ghost particles
"""

import numpy as np
from numba import njit

from .errors import SimulationError


@njit(cache=True)
def find_slot(partner, i, key):
    """Slot of contact ``key`` on particle i, or -1."""
    for k in range(partner.shape[1]):
        if partner[i, k] == key:
            return k
    return -1


@njit(cache=True)
def open_slot(partner, values, i, key, width):
    """Slot of contact ``key`` on particle i, made (zeroed) if new; -1 when i has no free slot."""
    free = -1
    for k in range(partner.shape[1]):
        if partner[i, k] == key:
            return k
        if free < 0 and partner[i, k] < 0:
            free = k
    if free >= 0:
        partner[i, free] = key
        for h in range(width):
            values[i, free * width + h] = 0.0
    return free


@njit(cache=True)
def close_slot(partner, i, key):
    for k in range(partner.shape[1]):
        if partner[i, k] == key:
            partner[i, k] = -1
            return


class ContactHistory:
    def __init__(self, sim, name, width, capacity=16):
        if capacity < 2:
            raise ValueError("a contact history holds at least 2 contacts per particle")
        self.sim, self.name, self.width, self.capacity = sim, name, width, capacity
        particles = sim.particles
        self._partner_name, self._values_name = f"{name}_partner", f"{name}_history"
        particles.request(self._partner_name, width=capacity, dtype=np.int64, default=-1, replicate="contacts")
        particles.request(self._values_name, width=capacity * width, replicate="copy")

    @property
    def partner(self):
        return self.sim.particles.arrays[self._partner_name]

    @property
    def values(self):
        return self.sim.particles.arrays[self._values_name]

    def overflowed(self, tag):
        raise SimulationError(f"particle {int(tag)} has more than {self.capacity} {self.name} contacts "
                              f"at step {self.sim.step}; raise the style's contact capacity")
