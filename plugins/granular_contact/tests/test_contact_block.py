"""The pair loops compute their contacts a block at a time in vectorised code (contact_block): the
forces are those of the same sub-models evaluated one contact at a time, to the last bit, across
block boundaries and with the coefficients of two types; the block loop is compiled once, for the
one signature the pair loops call it with; the pieces that make it vectorisable compute as numba's
own functions do."""

import math

import numpy as np
import pytest
from numba import njit

from pdps_core.api import Simulation
from pdps_core.testing import liggghts_material
from pdps_granular_contact import contact_block
from pdps_granular_contact.composition import BLOCK_SIGNATURE

N_SIDE = 8               # 512 spheres on a lattice closer than a diameter: about 1,400 contacts


def packed_spheres(model, *, two_types=True):
    """Spheres of diameter 1 mm on a cubic lattice of spacing 0.97 mm, every second one of type 2
    (another material), with random velocities and spins, run 30 steps so that the springs grow;
    LIGGGHTS words, a periodic box (nothing but the pair style acts), contacts across it with ghosts."""
    spacing, d = 0.97e-3, 1e-3
    side = N_SIDE * spacing
    ntypes = 2 if two_types else 1
    material = liggghts_material((5e6, 8e6)[:ntypes], (0.45, 0.3)[:ntypes],
                                 ((0.5, 0.6, 0.6, 0.7) if two_types else 0.5),
                                 ((0.5, 0.3, 0.3, 0.4) if two_types else 0.5),
                                 coefficientRollingFriction=((0.1, 0.05, 0.05, 0.2) if two_types else 0.1),
                                 cohesionEnergyDensity=((3e4, 1e4, 1e4, 2e4) if two_types else 3e4))
    if "hooke" in model:
        material += "\nfix m7 all property/global characteristicVelocity scalar 0.1"
    sim = Simulation(screen=False, log=None)
    sim.command(f"""atom_style granular
units si
boundary p p p
region reg block 0 {side!r} 0 {side!r} 0 {side!r} units box
create_box {ntypes} reg
{material}
pair_style gran {model}
pair_coeff * *
timestep 1e-7
fix integrate all nve/sphere""")
    rng = np.random.default_rng(5)
    for k in range(N_SIDE ** 3):
        i, j, m = k % N_SIDE, (k // N_SIDE) % N_SIDE, k // N_SIDE ** 2
        t = 1 + (k % 2 if two_types else 0)
        sim.command(f"create_atoms {t} single {(i + 0.5) * spacing!r} {(j + 0.5) * spacing!r} "
                    f"{(m + 0.5) * spacing!r} units box")
    sim.command(f"set type 1 diameter {d!r} density 2500")
    if two_types:
        sim.command(f"set type 2 diameter {0.9 * d!r} density 3000")
    p = sim.particles
    n = p.nlocal
    p.v[:n] = rng.uniform(-0.05, 0.05, (n, 3))
    p.arrays["omega"][:n] = rng.uniform(-50.0, 50.0, (n, 3))
    sim.command("run 30")
    return sim


def contact_by_contact(sim):
    """The pair forces from the contacts pair gran lists one at a time (its scalar
    ``pair_contacts``), added up in list order as the pair loop adds them, then the ghosts' summed
    onto their owners as the reverse communication does."""
    p = sim.particles
    contacts = sim.pair.contacts(sim)
    f = np.zeros_like(p.f)
    for i, j, force in zip(contacts["i"], contacts["j"], contacts["force"]):
        f[i] += force
        f[j] -= force
    owner = sim.comm.owners(p)
    for ghost in range(p.nlocal, p.nall):
        f[owner[ghost]] += f[ghost]
    return f, len(contacts["i"])


@pytest.mark.parametrize("model,two_types", [
    ("model hertz tangential history rolling_friction cdt", False),
    ("model hertz tangential history rolling_friction epsd2 cohesion sjkr", True),
    ("model hooke tangential no_history cohesion sjkr2", True),
])
def test_block_loop_gives_the_forces_of_one_contact_at_a_time_to_the_bit(model, two_types):
    sim = packed_spheres(model, two_types=two_types)
    p = sim.particles
    # run 0: the setup force computation reads the springs without growing them, as pair_contacts does
    sim.command("run 0")
    n = p.nlocal
    expected, count = contact_by_contact(sim)
    assert count > 3 * contact_block.BLOCK
    assert np.array_equal(p.f[:n], expected[:n])
    assert np.abs(p.f[:n]).max() > 0.0


def test_the_block_loop_has_one_compiled_signature():
    sim = packed_spheres("model hertz tangential history", two_types=False)
    assert sim.pair.kernels.block_contacts.signatures == [BLOCK_SIGNATURE]


@njit(cache=True)
def _roots(values, out):
    for k in range(len(values)):
        out[k] = contact_block.sqrt(values[k])


def test_sqrt_is_the_correctly_rounded_root():
    values = np.array([0.0, 1e-300, 2.0, 3.0, 1e300, np.inf, -1.0, np.nan])
    out = np.empty_like(values)
    _roots(values, out)
    assert np.array_equal(out[:6], np.array([math.sqrt(v) for v in values[:6]]))
    assert np.isnan(out[6]) and np.isnan(out[7])


def _part(c, k, hist, h):
    c[0] = math.sqrt(c[1]) / k[0]
    hist[h] += c[0]


_compiled_part = njit(_part)
_inlined_part = contact_block.inline_part(_compiled_part)


@njit(error_model="numpy")
def _call_part(inlined, c, hist):
    if inlined:
        _inlined_part(c, (4.0,), hist, 1)
    else:
        _compiled_part(c, (4.0,), hist, 1)


def test_an_inlined_part_computes_as_the_numba_function_it_copies():
    for root in (2.0, 3.0, 1e-300, 0.0):
        ca, cb = np.array([0.0, root]), np.array([0.0, root])
        ha, hb = np.full(2, 0.5), np.full(2, 0.5)
        _call_part(True, ca, ha)
        _call_part(False, cb, hb)
        assert np.array_equal(ca, cb) and np.array_equal(ha, hb)
