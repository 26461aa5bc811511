"""pair_style gran (LIGGGHTS's hertz and hooke with tangential history, rolling friction cdt, cohesion
sjkr) gives LIGGGHTS's collision: two spheres of two materials, already overlapping, meeting off-centre
with spin, 6000 steps of 1 us; every coordinate, velocity and spin of both equals LIGGGHTS's at the end.
The sjkr case fails if the cohesion lowers the tangential Coulomb limit (LIGGGHTS's tangential_reduce
is off by default): pdps did so before 11-28 and parted from LIGGGHTS by 6e-4 m/s and 0.37 rad/s."""

from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import liggghts_material

SCRIPT = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + liggghts_material((5.e6, 1.e7), (0.45, 0.3), (0.9, 0.8, 0.8, 0.7), (0.3, 0.4, 0.4, 0.5),
                         characteristicVelocity=1.0, coefficientRollingFriction=[0.1] * 4,
                         cohesionEnergyDensity=[3.e4] * 4) + """\
pair_style gran model MODEL
pair_coeff * *
timestep 0.000001
create_atoms 1 single 0.0 0.0 0.0
create_atoms 2 single 0.0085 0.002 0.001
set atom 1 diameter 0.01 density 2500
set atom 2 diameter 0.008 density 1500
velocity all set 0 0 0
set atom 1 vx 0.4 vy 0.05 vz 0.0
set atom 2 vx -0.3 vy 0.0 vz 0.1
set atom 1 omegaz 30
set atom 2 omegax 10 omegay -20
fix integr all nve/sphere
run 6000
"""
# LIGGGHTS 3.8.0 (Debian's liggghts), recorded on this machine: x y z vx vy vz omegax omegay omegaz
# of particles 1 and 2 at step 6000 (dump custom, %.16e), the script above with
# dump_modify's whole-line format.
LIGGGHTS = {
    "hertz tangential history": [
        [4.3973093572554630e-04, -1.8595971052696414e-04, -1.8635345683563911e-04, 6.0840070899738571e-02,
         -3.4040447607513145e-02, -3.2458694776444572e-02, 1.1647710321467415e+00, -4.1703289234859753e+00,
         2.8515286661283195e+01],
        [1.3081084193603152e-02, 3.5819000993721701e-03, 2.2066193256371036e-03, 8.0403622753991244e-01,
         2.7356916538904053e-01, 2.0565981372540570e-01, 1.4702422081358284e+01, -3.6836057961200765e+01,
         -5.9962620746300130e+00]],
    "hooke tangential history": [
        [4.0294459800196015e-04, -1.9516480867520647e-04, -1.9504665445433167e-04, 5.2241684862591301e-02,
         -3.6179551725425758e-02, -3.4251708284459774e-02, 1.1011710067693072e+00, -3.9287642298099499e+00,
         2.8564323010129630e+01],
        [1.3200831386716514e-02, 3.6118646115722167e-03, 2.2349174949686853e-03, 8.3202576542125350e-01,
         2.8053239493953652e-01, 2.1149644623847627e-01, 1.4443072670230777e+01, -3.5851294396559169e+01,
         -5.7962217681019323e+00]],
    "hertz tangential history rolling_friction cdt": [
        [4.4490528388007049e-04, -2.2772108664497978e-04, -1.4704382051826956e-04, 6.1751806595871608e-02,
         -4.1416758327660640e-02, -2.5497144527211003e-02, 4.4010525807496714e+00, -1.2885790345141357e+01,
         1.9166852889320459e+01],
        [1.3064240612372923e-02, 3.7178420789222106e-03, 2.0786582699160827e-03, 8.0106833790406340e-01,
         2.9758059351451993e-01, 1.8299851734118103e-01, 9.3545788263946719e+00, -2.1924969996764737e+01,
         8.9733535746996616e+00]],
    "hertz tangential history cohesion sjkr": [
        [4.9434282848351372e-04, -1.7179630485210013e-04, -1.8447836510028019e-04, 6.9658546635105262e-02,
         -3.1724686271239491e-02, -3.2270609733465766e-02, 1.0519091437292778e+00, -3.7762953768189700e+00,
         2.8643949256514237e+01],
        [1.2903311105200155e-02, 3.5357952631906693e-03, 2.2005155113938085e-03, 7.7533025183885196e-01,
         2.6603087978919077e-01, 2.0504755772612587e-01, 1.4243975623793538e+01, -3.5235313153450434e+01,
         -5.4737852372989941e+00]],
}


@pytest.mark.parametrize("model", sorted(LIGGGHTS))
def test_collision_as_liggghts(model):
    sim = Simulation(screen=False, log=None)
    sim.command(SCRIPT.replace("MODEL", model))
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    got = np.hstack([p.x[order], p.v[order], p.omega[order]])
    want = np.array(LIGGGHTS[model])
    # round-off of 6000 steps: LIGGGHTS's and pdps's sums differ in order (measured 1e-16 of each scale)
    np.testing.assert_allclose(got[:, :3], want[:, :3], rtol=0, atol=1e-15)
    np.testing.assert_allclose(got[:, 3:6], want[:, 3:6], rtol=0, atol=1e-13)
    np.testing.assert_allclose(got[:, 6:], want[:, 6:], rtol=0, atol=1e-11)
    assert np.abs(want[:, 3:6] - want[0, 3:6]).max() > 0.1      # the spheres did collide


CLUSTER = Path(__file__).parent / "data" / "liggghts_cohesive_cluster"


def test_cohesive_cluster_in_the_tutorials_box_as_liggghts():
    """36 cohesive spheres (sjkr, the cohesion tutorial's material) thrown onto the floor of the
    tutorials' cylinder (primitive walls), 1500 steps: every coordinate, velocity and spin equals
    LIGGGHTS's (data/liggghts_cohesive_cluster.ref, benchmarks/liggghts_references/gran_cluster.py).
    Spheres part and touch again before the next list build, and take up their old spring then, as
    in LIGGGHTS 3.8: pdps, which forgot it when they parted, left LIGGGHTS at step 747 and was
    6e-10 m, 7e-7 m/s and 9e-4 rad/s off at the end (now 7e-16 m, 1e-12 m/s, 1e-9 rad/s)."""
    sim = Simulation(screen=False, log=None)
    sim.file(str(CLUSTER.with_suffix(".in")))
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    got = np.hstack([p.tag[order, None], p.x[order], p.v[order], p.omega[order]])
    want = np.loadtxt(CLUSTER.with_suffix(".ref"))
    assert len(want) == 36 and np.array_equal(got[:, 0], want[:, 0])
    # round-off grown over 1500 steps of many contacts (the measured differences above, 100x)
    np.testing.assert_allclose(got[:, 1:4], want[:, 1:4], rtol=0, atol=1e-13)
    np.testing.assert_allclose(got[:, 4:7], want[:, 4:7], rtol=0, atol=1e-10)
    np.testing.assert_allclose(got[:, 7:], want[:, 7:], rtol=0, atol=1e-7)
    assert np.abs(want[:, 7:]).max() > 10.0                 # the spheres spin from their contacts
