"""fix heat/gran: two spheres in contact relax to one temperature at the conduction model's
exponential rate, through the same temperatures as LIGGGHTS 3.8.0 (recorded by
benchmarks/liggghts_references/contacts.py into data/liggghts_conduction.json), the total heat sum
m c T is conserved to round-off, and bad input is one line."""

import json
import math
from pathlib import Path

import meshio
import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_refused, liggghts_material, liggghts_one_particle

D1, D2, RHO = 0.01, 0.008, 2500.0
K1, K2, C1, C2 = 5.0, 2.0, 10.0, 30.0


def scene(delta=2e-4, area="", dt=1e-4, t1=400.0, t2=300.0):
    """Spheres of types 1 and 2 (different conductivities and capacities), overlapping by delta,
    held in place (no integrator)."""
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    x2 = 0.5 * (D1 + D2) - delta
    sim.command(f"""
atom_style granular
boundary f f f
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 reg
{liggghts_material((5.e6, 5.e6), (0.45, 0.45), [0.5] * 4, [0.5] * 4, thermalConductivity=(K1, K2),
                   thermalCapacity=(C1, C2))}
pair_style gran model hertz tangential history
pair_coeff * *
timestep {dt!r}
create_atoms 1 single 0 0 0 units box
create_atoms 2 single {x2!r} 0 0 units box
set type 1 diameter {D1} density {RHO}
set type 2 diameter {D2} density {RHO}
fix heat all heat/gran initial_temperature {t2} {area}
set atom 1 property/atom Temp {t1}
""")
    return sim


def temperatures(sim):
    order = np.argsort(sim.tag)
    return sim.particles.arrays["Temp"][: sim.nlocal][order]


def masses():
    return [RHO * math.pi / 6 * d ** 3 for d in (D1, D2)]


# the contact area of each contact_area setting, spheres of radii r1, r2 at distance r
AREA_OF = {
    "": lambda r, r1, r2: math.pi * (r1 ** 2 - ((r * r + r1 * r1 - r2 * r2) / (2 * r)) ** 2),
    "contact_area constant 1e-6": lambda r, r1, r2: 1e-6,
    "contact_area projection": lambda r, r1, r2: math.pi * max(r1, r2) ** 2,
}
RECORDED = json.loads((Path(__file__).parent / "data" / "liggghts_conduction.json").read_text())["cases"]


@pytest.mark.parametrize("area, area_of", AREA_OF.items())
def test_two_spheres_equilibrate_at_the_conduction_rate(area, area_of):
    """T1 - T2 decays as exp(-lambda t), lambda = h (1/m1c1 + 1/m2c2), h = 4 k1 k2/(k1+k2) sqrt(A);
    the explicit steps give (1 - lambda dt)^n, within 1e-3 of it at lambda dt = 2e-3."""
    delta = 2e-4
    r = 0.5 * (D1 + D2) - delta
    h = 4 * K1 * K2 / (K1 + K2) * math.sqrt(area_of(r, D1 / 2, D2 / 2))
    m1, m2 = masses()
    rate = h * (1 / (m1 * C1) + 1 / (m2 * C2))
    dt = 2e-3 / rate
    sim = scene(delta, area, dt)
    heat0 = m1 * C1 * 400.0 + m2 * C2 * 300.0
    steps = int(1.5 / (rate * dt))
    sim.command(f"run {steps}")
    t1, t2 = temperatures(sim)
    measured = -math.log((t1 - t2) / 100.0) / (steps * dt)
    assert measured == pytest.approx(rate, rel=0.01)
    assert measured == pytest.approx(-math.log(1 - rate * dt) / dt, rel=1e-9)
    assert m1 * C1 * t1 + m2 * C2 * t2 == pytest.approx(heat0, rel=1e-14)
    assert sim.fix_value("heat") == pytest.approx(heat0, rel=1e-14)


@pytest.mark.parametrize("case, area", [("overlap", ""), ("projection", "contact_area projection"),
                                        ("constant", "contact_area constant 1e-6")])
def test_two_spheres_cool_as_in_liggghts(case, area):
    """LIGGGHTS's two spheres (the scene's materials and sizes, overlapping by 2e-4, 400 and 300 K,
    lambda dt = 2e-3 by this area): pdps's temperatures every 100 steps equal LIGGGHTS's to 1e-8
    of the difference between them, and that difference decays at the rate lambda of the two
    lumped capacities within 1 %. LIGGGHTS's projection is the larger sphere's cross-section."""
    script, every = RECORDED[case]["script"], RECORDED[case]["every"]
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(script[:script.rindex("run ")])
    r = 0.5 * (D1 + D2) - 2e-4
    h = 4 * K1 * K2 / (K1 + K2) * math.sqrt(AREA_OF[area](r, D1 / 2, D2 / 2))
    m1, m2 = masses()
    rate = h * (1 / (m1 * C1) + 1 / (m2 * C2))
    assert rate * sim.dt == pytest.approx(2e-3, rel=1e-12)
    for n, want in enumerate(RECORDED[case]["temperatures"]):
        if n:
            sim.command(f"run {every}")
        t1, t2 = got = temperatures(sim)
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-8 * (want[0] - want[1]))
        if n:
            # explicit steps: -ln(1 - lambda dt)/dt = lambda (1 + lambda dt/2 + ...), 1e-3 above lambda
            measured = -math.log((t1 - t2) / 100.0) / (n * every * sim.dt)
            assert measured == pytest.approx(rate, rel=0.01)
            assert -math.log((want[0] - want[1]) / 100.0) / (n * every * sim.dt) == pytest.approx(rate, rel=0.01)


def test_per_atom_temperature_and_flux_in_a_dump(tmp_path):
    sim = scene()
    path = tmp_path / "heat.dump"
    sim.command(f"dump d all custom 1 {path} id f_heat[1] f_heat[2]\nrun 0")
    rows = [line.split() for line in path.read_text().splitlines()[-2:]]
    (_, t1, q1), (_, t2, q2) = sorted(rows)
    assert (float(t1), float(t2)) == (400.0, 300.0)
    assert float(q1) == pytest.approx(-float(q2), rel=1e-12)
    assert float(q1) < 0


def test_particles_outside_the_group_keep_their_temperature():
    sim = scene()
    sim.command("unfix heat\ngroup one id 1\nfix heat one heat/gran initial_temperature 300\n"
                "set atom 1 property/atom Temp 400\nrun 100")
    t1, t2 = temperatures(sim)
    assert t2 == 300.0 and t1 < 400.0


SETUP = liggghts_one_particle()


@pytest.mark.parametrize("line, message", [
    ("fix h all heat/gran", "fix: missing keyword initial_temperature; usage: fix ID GROUP heat/gran "
     "initial_temperature T0 [contact_area overlap|projection|constant A] [area_correction no] "
     "[store_contact_data yes|no]"),
    ("fix h all heat/gran initial_temperature 300 contact_area constant",
     "fix: contact_area constant takes 1 value(s): number (got nothing)"),
    ("fix h all heat/gran initial_temperature 300 area_correction yes",
     "fix: area_correction yes is not supported (it needs youngsModulusOriginal); use area_correction no"),
    ("set atom 1 property/atom Temp 400", "set: set property/atom: Temp is not a per-atom property of one value a "
     "fix made (heat/gran makes Temp and heatSource)"),
])
def test_bad_lines(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 6, message)


def test_missing_conductivity_stops_the_run(pdps_cli):
    done = pdps_cli(SETUP + liggghts_material(5.e6, 0.45, 0.5, 0.5)
                    + "pair_style gran model hertz tangential history\npair_coeff * *\n"
                    "fix h all heat/gran initial_temperature 300\nrun 0\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:13: run: fix h (heat/gran) needs thermalConductivity: "
                                   "fix ID all property/global thermalConductivity peratomtype V1 ... V1")


def test_liggghts_dump_spelling_of_the_per_atom_properties(tmp_path):
    """LIGGGHTS writes f_Temp[0] and f_heatFlux[0] for its scalar per-atom properties (index 0 is
    no index) and f_directionalHeatFlux[1] for the first column of a vector one (recorded with LIGGGHTS
    3.8.0: heat_flux_columns)."""
    sim = scene()
    path = tmp_path / "heat.dump"
    sim.command(f"dump d all custom 1 {path} id f_Temp[0] f_heatFlux[0] f_directionalHeatFlux[1] f_heat[1]\nrun 0")
    rows = sorted(line.split() for line in path.read_text().splitlines()[-2:])
    assert [float(r[1]) for r in rows] == [400.0, 300.0]
    assert [float(r[1]) for r in rows] == [float(r[4]) for r in rows]
    assert float(rows[0][2]) == pytest.approx(-float(rows[1][2]), rel=1e-12)
    assert float(rows[0][3]) == pytest.approx(float(rows[1][3]), rel=1e-12)


def test_liggghts_heat_tutorials_custom_vtk_columns(tmp_path):
    """The heatTransfer tutorials' dump custom/vtk ... f_Temp[0] f_heatFlux[0]: each a point scalar
    named as written, the values dump custom writes."""
    sim = scene()
    sim.command(f"dump d all custom/vtk 1 {tmp_path}/heat_*.vtk id radius f_Temp[0] f_heatFlux[0]\n"
                f"dump t all custom 1 {tmp_path}/heat.dump id f_Temp[0] f_heatFlux[0]\nrun 0")
    mesh = meshio.read(tmp_path / "heat_0.vtk")
    rows = sorted((int(r[0]), float(r[1]), float(r[2])) for r in
                  (line.split() for line in (tmp_path / "heat.dump").read_text().splitlines()[-2:]))
    np.testing.assert_array_equal(np.ravel(mesh.point_data["id"]), [r[0] for r in rows])
    np.testing.assert_array_equal(np.ravel(mesh.point_data["f_Temp[0]"]), [r[1] for r in rows])
    np.testing.assert_allclose(np.ravel(mesh.point_data["f_heatFlux[0]"]), [r[2] for r in rows], rtol=1e-9)
    assert sorted(np.ravel(mesh.point_data["f_Temp[0]"])) == [300.0, 400.0]


def test_liggghts_dump_spelling_out_of_range(pdps_cli):
    done = pdps_cli(SETUP + "fix h all heat/gran initial_temperature 300\n"
                    "dump d all custom 1 d.txt id f_Temp[1]\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:7: dump: dump column f_Temp[1]: per-atom property Temp has one "
                                   "value per particle: f_Temp or f_Temp[0] (got [1])")
    done = pdps_cli(SETUP + "fix h all heat/gran initial_temperature 300\n"
                    "dump d all custom 1 d.txt id f_directionalHeatFlux[0]\n")
    assert done.stderr.strip() == ("ERROR: in.test:7: dump: dump column f_directionalHeatFlux[0]: per-atom property "
                                   "directionalHeatFlux has 3 values per particle, f_directionalHeatFlux[1] to [3] "
                                   "(got f_directionalHeatFlux[0])")
