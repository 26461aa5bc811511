"""A time step that resolves a collision with few steps is named before the run (issue 4: hard cases
stay visible; docs/accuracy-dem.md gives the restitution error against dt / t_c)."""

import pytest

from pdps_core.testing import make_box
from pdps_granular_contact import contact_models


def two_spheres(dt):
    return make_box(f"""
        create_particle 1 single 2.0 3.0 3.0 diameter 1.0 density 1.9098593
        create_particle 1 single 3.5 3.0 3.0 diameter 1.0 density 1.9098593
        pair_style dem/lsd 0.5 1.0
        pair_coeff * * 200000.0 25.0 57142.857 12.5 0.5
        timestep {dt}
        run 0
    """, box="0 6 0 6 0 6", particle_style="sphere")


CONTACT = contact_models.lsd_contact_time(200000.0, 25.0, 0.5)     # two unit spheres: m* = 1/2


@pytest.mark.parametrize("fraction", [5, 8])
def test_a_coarse_timestep_is_named_with_a_safe_one(fraction):
    sim = two_spheres(CONTACT / fraction)
    assert len(sim.warnings) == 1
    warning = sim.warnings[0]
    assert warning.startswith(f"pair dem/lsd: timestep {CONTACT / fraction:g} is more than the shortest "
                              f"contact ({CONTACT:.3g}) / 10: collisions lose restitution")
    assert warning.endswith(f"use timestep <= {CONTACT / 10:.3g}")


def test_a_fine_timestep_runs_silently():
    assert two_spheres(CONTACT / 50).warnings == []
