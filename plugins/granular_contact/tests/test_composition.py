"""Contacts composed of sub-models: a sub-model registered in the process joins LIGGGHTS's words with
no change to pair gran; only the parts a script names keep history; the sub-model kinds are styles
pdps doc shows."""

import math

import numpy as np
import pytest
from numba import njit

from pdps_core.api import Simulation
from pdps_core.styledoc import document
from pdps_core.styles import StyleEntry, registry
from pdps_core.testing import assert_refused, liggghts_material, liggghts_one_particle, register_styles
from pdps_granular_contact.composition import ContactModel, ContactSubModel
from pdps_granular_contact.contact_state import FN

D, RHO = 0.01, 2500.0


@njit(cache=True)
def constant_pull(c, k, hist, h):
    """A pull of k[0] newtons while the spheres touch, counted in steps in hist[h]."""
    c[FN] -= k[0]
    hist[h] += 1.0


class ConstantPull(ContactSubModel):
    """A cohesion of constant force, its size the cohesionEnergyDensity property read as newtons:
    only a test of the plumbing."""
    kind = "gran.cohesion"
    name = "test/constant"
    history_width = 1
    compute = constant_pull

    def coefficients(self, material):
        return material.columns(material.property("cohesionEnergyDensity"))


register_styles(ConstantPull)


def two_spheres(model, overlap, *, more=""):
    """Two spheres of diameter D overlapping by ``overlap`` on the x axis, at rest; LIGGGHTS words."""
    sim = Simulation(screen=False, log=None)
    x = 0.5 * (D - overlap)
    sim.command(f"""atom_style granular
units si
boundary f f f
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 1 reg
{liggghts_material(5.e6, 0.45, 0.5, 0.5, cohesionEnergyDensity=2.0, coefficientRollingFriction=0.1)}
pair_style gran {model}
pair_coeff * *
timestep 1e-6
create_atoms 1 single {-x!r} 0 0 units box
create_atoms 1 single {x!r} 0 0 units box
set type 1 diameter {D!r} density {RHO!r}
{more}""")
    return sim


def hertz_force(overlap, youngs=5.e6, poisson=0.45):
    y_star = youngs / (2 * (1 - poisson ** 2))
    return 4 / 3 * y_star * math.sqrt(D / 4 * overlap) * overlap


def test_a_cohesion_model_registered_in_the_process_joins_liggghts_words():
    """The force on sphere 2 is Hertz's less the model's 2 N, and its history counts the steps of
    the contact on both spheres (i's count, j's its negative)."""
    overlap = 2e-5
    sim = two_spheres("model hertz tangential history cohesion test/constant", overlap,
                      more="fix integr all nve/sphere\nrun 0")
    p = sim.particles
    two = p.index_of_tag(2)
    assert p.f[two, 0] == pytest.approx(hertz_force(overlap) - 2.0, rel=1e-12)
    # a run's setup reads the history and keeps nothing; three steps count three
    sim.command("run 3")
    p = sim.particles
    values = p.arrays["gran_model_history_history"]
    model = sim.pair.contact_model
    assert model.history_width == 3 + 1 and model.history_at("cohesion") == 0
    steps = sorted(values[[p.index_of_tag(1), p.index_of_tag(2)], 0].tolist())
    assert steps == [-3.0, 3.0]


def test_only_the_parts_a_script_names_keep_history():
    """hertz with no_history keeps nothing per contact: no contact history arrays at all; history
    alone keeps the spring (3); with epsd2 the rolling spring follows it (6); cdt keeps none."""
    for model, width in (("model hertz tangential no_history", 0), ("model hertz tangential history", 3),
                         ("model hertz tangential history rolling_friction epsd2", 6),
                         ("model hertz tangential history rolling_friction cdt", 3)):
        sim = two_spheres(model, 1e-5, more="run 0")
        assert sim.pair.contact_model.history_width == width, model
        assert sim.particles.has("gran_model_history_partner") == (width > 0), model


def test_the_parts_are_called_in_liggghts_order_whatever_the_order_of_the_words():
    a = ContactModel("gran", {"rolling": "epsd2", "cohesion": "sjkr", "tangential": "history", "normal": "hertz"})
    assert [m.part for m in a.sub_models] == ["surface", "normal", "cohesion", "tangential", "rolling"]
    # history in that order too: sjkr keeps none
    assert a.history_at("tangential") == 0 and a.history_at("rolling") == 3


def test_an_unknown_sub_model_is_refused_at_its_line_with_the_installed_ones(pdps_cli):
    script = liggghts_one_particle() + "pair_style gran model hertz tangential history cohesion jkr\n"
    done = pdps_cli(script)
    installed = registry.names("gran.cohesion")
    assert "sjkr" in installed and "sjkr2" in installed
    quoted = ", ".join(f"'{name}'" for name in ["off", *installed][:-1]) + f" or '{installed[-1]}'"
    assert_refused(done, 6, f"pair_style: cohesion must be one of {quoted} (got jkr)")


@pytest.mark.parametrize("kind, name, words", [
    ("gran.cohesion", "sjkr", ["cohesionEnergyDensity", "energy/volume"]),
    ("gran.normal", "hertz", ["youngsModulus", "coefficientRestitution", "limitForce"]),
    ("gran.rolling", "epsd", ["coefficientRollingViscousDamping", "2.25"]),
])
def test_pdps_doc_shows_a_sub_model_with_its_formula_and_properties(kind, name, words):
    assert kind in registry.kinds()
    page = document(StyleEntry(kind, name, "pdps-granular-contact", "0.1.0", ""), registry.lookup(kind, name))
    for word in words:
        assert word in page, (kind, name, word)


def test_the_generated_loop_moves_nothing_for_spheres_apart():
    """Spheres a hair apart feel nothing (the composed loop's distance test)."""
    sim = two_spheres("model hertz tangential history cohesion sjkr rolling_friction cdt", -1e-9, more="run 0")
    assert np.abs(sim.particles.f[:2]).max() == 0.0
