"""pair_style formula: Lennard-Jones from its formula equals lj/cut to 1e-12; other formulas against
their derivatives; several formulas in one run; errors name the offending part."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import build, energy_gradient, fluid, forces_by_tag

LJ = '"4*eps*((sig/r)^12 - (sig/r)^6)"'


def liquid(tmp_path, setup):
    x, length = fluid(400, 0.8, seed=11, min_distance=0.85)
    return build(tmp_path, x, hi=(length,) * 3, setup=setup + "\nrun 0")


@pytest.mark.parametrize("shift", ["no", "yes"])
def test_lennard_jones_formula_gives_lj_cut_forces_and_energy(tmp_path, shift):
    ref = liquid(tmp_path, f"pair_style lj/cut 2.5\npair_coeff * * 1.3 0.95\npair_modify shift {shift}")
    sim = liquid(tmp_path, f"pair_style formula 2.5\npair_coeff * * {LJ} eps 1.3 sig 0.95\n"
                           f"pair_modify shift {shift}")
    assert forces_by_tag(sim) == pytest.approx(forces_by_tag(ref), rel=1e-12, abs=1e-12 * np.abs(ref.f).max())
    assert sim.pe == pytest.approx(ref.pe, rel=1e-12)
    assert np.allclose(sim.virial, ref.virial, rtol=1e-12, atol=0)


def test_exponential_formula_with_a_square_root_against_the_energy_gradient(tmp_path):
    """Buckingham-like: exp(-r/rho) needs r itself (no rewriting in r^2), C/r^6 does not."""
    x = [[5.0, 5.0, 5.0], [5.9, 5.4, 4.7], [4.3, 5.6, 5.5]]
    sim = build(tmp_path, x, types=[1, 1, 2], setup="""
        pair_style formula 3.0
        pair_coeff 1 1 "A*exp(-r/rho) - C/r^6" A 800.0 rho 0.3 C 2.0
        pair_coeff 2 2 "eps*(1 - r/rc)^2" eps 5.0 rc 2.0 cutoff 2.0
        pair_coeff 1 2 "D*(exp(-2*a*(r - r0)) - 2*exp(-a*(r - r0)))" D 1.5 a 2.0 r0 1.1
    """)
    analytic, numeric = energy_gradient(sim, h=1e-6)
    assert np.abs(analytic).max() > 1.0
    assert numeric == pytest.approx(analytic, rel=1e-6, abs=1e-6)


def test_pair_energy_equals_the_formula(tmp_path):
    r = 1.37
    sim = build(tmp_path, [[4.0, 5.0, 5.0], [4.0 + r, 5.0, 5.0]], setup="""
        pair_style formula 3.0
        pair_coeff * * "D*(exp(-2*a*(r - r0)) - 2*exp(-a*(r - r0)))" D 1.5 a 2.0 r0 1.1
        run 0
    """)
    energy = 1.5 * (math.exp(-4.0 * (r - 1.1)) - 2 * math.exp(-2.0 * (r - 1.1)))
    force = 1.5 * (4.0 * math.exp(-4.0 * (r - 1.1)) - 4.0 * math.exp(-2.0 * (r - 1.1)))   # -dE/dr
    assert sim.pe == pytest.approx(energy, rel=1e-13)
    assert forces_by_tag(sim)[1, 0] == pytest.approx(force, rel=1e-12)


@pytest.mark.parametrize("coeff, message", [
    ('"4*eps*(sig/r)^12" eps 1.0', "formula '4*eps*(sig/r)^12': unknown name sig (give it as a parameter: NAME VALUE)"),
    ('"__import__(1)" a 1', "formula '__import__(1)': unknown function __import__ (known: exp, log, sqrt, sin, cos, tan, sinh, cosh, tanh, erf, erfc, abs, min, max)"),
    ('"r.real" a 1', "formula 'r.real': attribute is not allowed"),
    ('"eps*" eps 1', "cannot read formula 'eps*'"),
    ('"eps" eps 1', "formula 'eps' does not depend on r: it has no force"),
    ('"eps/r" eps', "parameters eps needs value (got nothing)"),
    ('"eps/r" eps nan', "parameters eps: value must be a finite number (got nan)"),
    ('"eps/r" eps 1 eps 2', "parameter eps is given twice"),
    ('"eps/r" eps 1 cutoff -2', "cutoff must be > 0 (got -2)"),
])
def test_bad_formulas_are_one_line_errors(tmp_path, coeff, message):
    sim = build(tmp_path, [[5.0, 5.0, 5.0]], setup="pair_style formula 2.5")
    with pytest.raises(ScriptError) as caught:
        sim.command(f"pair_coeff * * {coeff}")
    assert str(caught.value) == f"<command>:1: pair_coeff: {message}"


def test_parameters_that_make_the_formula_singular_are_refused_at_the_run(tmp_path):
    sim = build(tmp_path, [[5.0, 5.0, 5.0]], setup='pair_style formula 2.5\npair_coeff * * "a/(b*r)" a 1 b 0')
    with pytest.raises(ScriptError, match=r"pair_coeff 1 1: formula 'a/\(b\*r\)' cannot be evaluated"):
        sim.command("run 0")
