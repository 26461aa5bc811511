"""Per-contact history: slots by partner key, kept with the particle when particles are re-sorted."""

import numpy as np
import pytest

from pdps_core.api import ContactHistory, Simulation, close_slot, find_slot, open_slot


@pytest.fixture
def sim():
    sim = Simulation(screen=False, log=None)
    sim.command("particle_style sphere\nregion b block 0 6 0 6 0 6\ncreate_box 1 b\n"
                "create_particle 1 single 1 1 1\ncreate_particle 1 single 5 5 5\ncreate_particle 1 single 3 3 3")
    return sim


def test_slots_open_find_and_close(sim):
    history = ContactHistory(sim, "shear", width=3, capacity=2)
    partner, values = history.partner, history.values
    assert partner.shape == (3, 2) and values.shape == (3, 6) and (partner == -1).all()
    slot = open_slot(partner, values, 0, 42, 3)
    values[0, 3 * slot:3 * slot + 3] = [1.0, 2.0, 3.0]
    assert find_slot(partner, 0, 42) == slot
    assert open_slot(partner, values, 0, 42, 3) == slot                 # an existing contact is found
    assert list(values[0, 3 * slot:3 * slot + 3]) == [1.0, 2.0, 3.0]
    other = open_slot(partner, values, 0, 7, 3)
    assert other != slot and open_slot(partner, values, 0, 8, 3) == -1   # full
    close_slot(partner, 0, 42)
    assert find_slot(partner, 0, 42) == -1
    assert open_slot(partner, values, 0, 8, 3) == slot                  # the freed slot is reused, zeroed
    assert list(values[0, 3 * slot:3 * slot + 3]) == [0.0, 0.0, 0.0]


def test_history_moves_with_its_particle_when_particles_are_reordered(sim):
    history = ContactHistory(sim, "shear", width=1, capacity=4)
    tags = sim.tag.copy()
    for i in range(3):
        slot = open_slot(history.partner, history.values, i, 100 + int(tags[i]), 1)
        history.values[i, slot] = 10.0 * tags[i]
    sim.particles.keep(np.array([2, 0, 1]))
    for i in range(3):
        slot = find_slot(history.partner, i, 100 + int(sim.tag[i]))
        assert history.values[i, slot] == 10.0 * sim.tag[i]


def test_capacity_below_two_is_refused(sim):
    with pytest.raises(ValueError):
        ContactHistory(sim, "tiny", width=3, capacity=1)
