"""pair dem on two ranks: contacts across the cut keep their springs on both sides (the mirror
written into a ghost goes back to its owner), and the slots forget a contact the step it ends."""

import numpy as np
import pytest

from pdps_core.testing import contacts_held_on_ranks


@pytest.mark.parametrize("pair, coeff", [("dem/lsd 0.3 1.0", "* * kn 200000 e 0.7 mu 0.3"),
                                         ("dem/hertz", "* * 5.0e7 0.3 0.7 0.3")])
def test_contact_slots_hold_exactly_the_contacts_of_each_step_on_2_ranks(tmp_path, pair, coeff):
    """100 spheres near the sites of a lattice of spacing 1.2 in a periodic box 6 wide, cut across x
    between two ranks, with Gaussian velocities of deviation 8: lists rebuilt every few steps, and
    between builds only the rows that held a contact, those this step's contacts touched and those
    the mirrors from the other rank came back to are swept. Contacts last about as long as that
    (stiff springs), and at every step the owned spheres' slots, over both ranks, hold exactly the
    pairs that touch."""
    rng = np.random.default_rng(6)
    sites = (np.stack(np.meshgrid(*[np.arange(5)] * 3, indexing="ij"), -1).reshape(-1, 3)[:100] * 1.2
             + 0.6 + rng.uniform(-0.02, 0.02, (100, 3)))
    spheres = "\n".join(f"create_particle 1 single {x!r} {y!r} {z!r} diameter 1.0 density 1.0"
                        for x, y, z in sites.tolist())
    script = f"""\
particle_style sphere
boundary p p p
processors 2 1 1
region box block 0 6 0 6 0 6
create_box 1 box
{spheres}
pair_style {pair}
pair_coeff {coeff}
timestep 0.0004
neighbor 0.1 bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
"""
    exact, builds, contacts, _, _ = contacts_held_on_ranks(script, rng.normal(0.0, 8.0, (100, 3)), 400, 2, tmp_path,
                                                     dialect="pdps")
    print(f"builds {builds}, touching pairs summed over the steps {contacts}")
    assert builds > 20 and contacts > 400
    assert exact
