"""cohesion vdw, installed from this distribution, in a LIGGGHTS script: the force is Hertz's less
A R* / 6 z0^2, a sphere resting on another sticks with that pull-off force, and a bad property is
told at the run."""

import math

import pytest

from pdps_core.api import Simulation, registry
from pdps_core.testing import assert_refused, liggghts_material

D, RHO, A, Z0 = 1e-4, 2500.0, 6.5e-20, 4e-10
YOUNGS, POISSON = 5.e6, 0.45


def setup(overlap, *, hamaker=A):
    return f"""atom_style granular
units si
boundary f f f
region reg block -0.001 0.001 -0.001 0.001 -0.001 0.001 units box
create_box 1 reg
{liggghts_material(YOUNGS, POISSON, 0.5, 0.5)}fix m5 all property/global hamakerConstant peratomtypepair 1 {hamaker!r}
fix m6 all property/global surfaceSeparation peratomtypepair 1 {Z0!r}
pair_style gran model hertz tangential history cohesion vdw
pair_coeff * *
timestep 1e-9
create_atoms 1 single {-(D - overlap) / 2!r} 0 0 units box
create_atoms 1 single {(D - overlap) / 2!r} 0 0 units box
set type 1 diameter {D!r} density {RHO!r}
"""


def test_the_sub_model_comes_from_its_own_distribution():
    (entry,) = [e for e in registry.entries() if (e.kind, e.name) == ("gran.cohesion", "vdw")]
    assert entry.dist == "pdps-contact-vdw"


def test_force_is_hertz_less_the_van_der_waals_pull():
    overlap = 1e-8
    sim = Simulation(screen=False, log=None)
    sim.command(setup(overlap) + "run 0")
    p = sim.particles
    r_star = D / 4
    y_star = YOUNGS / (2 * (1 - POISSON ** 2))
    hertz = 4 / 3 * y_star * math.sqrt(r_star * overlap) * overlap
    assert p.f[p.index_of_tag(2), 0] == pytest.approx(hertz - A * r_star / (6 * Z0 ** 2), rel=1e-12)


def test_touching_spheres_pulled_apart_gently_stay_together():
    """The pull-off force is A R* / 6 z0^2: pulled with 0.9 of it two spheres stay in contact; with 1.1
    of it they part."""
    pull_off = A * (D / 4) / (6 * Z0 ** 2)
    for share, parts in ((0.9, False), (1.1, True)):
        sim = Simulation(screen=False, log=None)
        sim.command(setup(1e-8) + f"""fix integr all nve/sphere
group one id 1
group two id 2
fix pull1 one addforce {-share * pull_off!r} 0 0
fix pull2 two addforce {share * pull_off!r} 0 0
run 20000""")
        p = sim.particles
        gap = p.x[p.index_of_tag(2), 0] - p.x[p.index_of_tag(1), 0] - D
        assert (gap > 0) == parts, (share, gap)


def test_a_missing_property_is_told_at_the_run(pdps_cli):
    script = setup(0.0).replace(f"fix m6 all property/global surfaceSeparation peratomtypepair 1 {Z0!r}\n", "") + "run 0\n"
    assert "surfaceSeparation" not in script
    assert_refused(pdps_cli(script), script.count("\n"),
                   "run: pair gran needs surfaceSeparation: fix ID all property/global surfaceSeparation "
                   "peratomtypepair 1 V11 ... V11")


def test_a_negative_hamaker_constant_is_told_at_the_run(pdps_cli):
    script = setup(0.0, hamaker=-1e-20) + "run 0\n"
    assert_refused(pdps_cli(script), script.count("\n"),
                   "run: hamakerConstant (fix m5) must be > 0 (got -1e-20)")
