"""Particle templates and distributions: each size distribution reproduces its mean and spread
over 10^4 draws (closed forms written out here, independently of the module's numeric moments),
and a discrete distribution gives each template its share of the mass."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_fix_insert.size_distribution import Distribution

DRAWS = 10_000


def phi(z):
    return 0.5 * (1.0 + math.erf(z / math.sqrt(2.0)))


def normal_moment(k, mu, sigma, lo, hi):
    """E[exp(k Y)] for Y normal (mu, sigma) cut to [lo, hi]."""
    a, b = (lo - mu) / sigma, (hi - mu) / sigma
    return math.exp(k * mu + 0.5 * (k * sigma) ** 2) * (phi(b - k * sigma) - phi(a - k * sigma)) / (phi(b) - phi(a))


def uniform_mass_moments(a, b):
    z = 0.5 * (a ** -2 - b ** -2)          # pdf r^-3 / z on [a, b]
    return (1.0 / a - 1.0 / b) / z, math.log(b / a) / z, (b - a) / z


def truncated_normal(mu, sigma):
    """Mean and variance of a normal cut at +-3 sigma."""
    pdf3 = math.exp(-4.5) / math.sqrt(2 * math.pi)
    return mu, sigma ** 2 * (1.0 - 6.0 * pdf3 / (2.0 * phi(3.0) - 1.0))


def lognormal_moments(mu_number, sigma, lo, hi):
    """E[r], E[r^2], E[r^3] of r = exp(Y), Y normal (mu_number, sigma) cut to [lo, hi]."""
    return tuple(normal_moment(k, mu_number, sigma, lo, hi) for k in (1, 2, 3))


CASES = {
    "uniform number": (["uniform", "number", "0.001", "0.003"],
                       lambda: (0.002, 0.002 ** 2 + (0.002 ** 2) / 12.0, (0.003 ** 4 - 0.001 ** 4) / (4 * 0.002))),
    "uniform mass": (["uniform", "mass", "0.001", "0.003"], lambda: uniform_mass_moments(0.001, 0.003)),
    "gaussian number": (["gaussian", "number", "0.002", "0.0002"], None),
    "lognormal number": (["lognormal", "number", "-6.0", "0.2"],
                         lambda: lognormal_moments(-6.0, 0.2, -6.6, -5.4)),
    "lognormal mass": (["lognormal", "mass", "-6.0", "0.2"],
                       lambda: lognormal_moments(-6.0 - 3 * 0.04, 0.2, -6.6, -5.4)),
}


@pytest.mark.parametrize("name", list(CASES))
def test_radius_distribution_mean_and_spread(name):
    words, moments = CASES[name]
    if name == "gaussian number":
        mean, variance = truncated_normal(0.002, 0.0002)
        second, third = variance + mean ** 2, None
    else:
        mean, second, third = moments()
        variance = second - mean ** 2
    dist = Distribution.read(words, "radius", radius=True)
    draws = dist.draw(np.random.default_rng(11), DRAWS)
    lo, hi = dist.support()
    assert lo <= draws.min() and draws.max() <= hi
    # the sample mean within 4 standard errors; the sample variance within 4 of its standard errors
    assert abs(draws.mean() - mean) < 4.0 * math.sqrt(variance / DRAWS)
    fourth = np.mean((draws - mean) ** 4)
    assert abs(draws.var() - variance) < 4.0 * math.sqrt((fourth - variance ** 2) / DRAWS)
    # the module's numeric moments (what expected masses are made of) against the closed forms
    assert dist.mean_of(1) == pytest.approx(mean, rel=1e-9)
    if third is not None:
        assert dist.mean_of(3) == pytest.approx(third, rel=1e-9)


def test_constant_and_density_styles():
    assert Distribution.read(["constant", "0.5"], "radius", radius=True).draw(np.random.default_rng(1), 3).tolist() == [0.5] * 3
    dist = Distribution.read(["uniform", "2000", "3000"], "density", radius=False)
    draws = dist.draw(np.random.default_rng(2), DRAWS)
    assert abs(draws.mean() - 2500.0) < 4 * (1000 / math.sqrt(12)) / math.sqrt(DRAWS)


@pytest.mark.parametrize("words, message", [
    (["uniform", "volume", "1", "2"], "radius uniform: expected number or mass (got volume)"),
    (["uniform", "number", "2", "1"], "radius uniform needs 0 < low < high (got 2 1)"),
    (["gaussian", "mass", "1", "0.1"], "radius gaussian mass is not defined (LIGGGHTS neither): use gaussian number, or lognormal mass"),
    (["gaussian", "number", "1", "0.5"], "radius gaussian: mu - 3 sigma must be > 0 (got 1 - 3 x 0.5)"),
    (["cubic", "1"], "radius style must be constant, uniform, gaussian or lognormal (got cubic)"),
    (["constant", "-1"], "radius constant must be > 0 (got -1)"),
    (["lognormal", "mass", "0", "1.5"], "radius lognormal mass: sigma must be <= 1 (got 1.5): beyond, the number distribution's peak lies more than 3 sigma below the cut"),
])
def test_bad_distributions_are_refused(words, message):
    with pytest.raises(ScriptError) as error:
        Distribution.read(words, "radius", radius=True)
    assert str(error.value) == message


def test_discrete_distribution_gives_each_template_its_mass_share(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command("""
        atom_style sphere
        region box block 0 1 0 1 0 1 units box
        create_box 2 box
        fix small all particletemplate/sphere 3 atom_type 1 density constant 1000 radius constant 0.01
        fix large all particletemplate/sphere 5 atom_type 2 density constant 2000 radius uniform number 0.02 0.03
        fix mix all particledistribution/discrete 7 2 small 0.3 large 0.7
    """)
    mix = sim.fixes["mix"]
    radius, density, types, which = mix.draw(np.random.default_rng(3), DRAWS)
    assert (np.diff(radius) <= 0).all()                      # largest first
    assert set(types[which == 0]) == {1} and set(types[which == 1]) == {2}
    mass = density * 4.0 / 3.0 * math.pi * radius ** 3
    share = mass[which == 0].sum() / mass.sum()
    # the small template's share of the mass: 0.3, within the sampling error of the template counts
    m_small = 1000 * 4 / 3 * math.pi * 0.01 ** 3
    m_large = 2000 * 4 / 3 * math.pi * (0.03 ** 4 - 0.02 ** 4) / (4 * 0.01)
    p_small = (0.3 / m_small) / (0.3 / m_small + 0.7 / m_large)
    count_error = math.sqrt(p_small * (1 - p_small) / DRAWS)
    assert abs((which == 0).mean() - p_small) < 4 * count_error
    # the share is a ratio of sums: its standard error by the delta method
    small_mass = np.where(which == 0, mass, 0.0)
    share_error = np.std(small_mass - share * mass) / (mass.mean() * math.sqrt(DRAWS))
    assert abs(share - 0.3) < 4 * share_error
    assert mix.mass_expected == pytest.approx(p_small * m_small + (1 - p_small) * m_large, rel=1e-9)


# LIGGGHTS 3.8.0 on this machine (2026-12-02), templates of radius 5 and 8 mm (density 2500) with
# weights 0.3 and 0.7: the number shares it prints ("distribution based on number%")
LIGGGHTS_NUMBER_SHARES = {"particledistribution/discrete": (0.63708005, 0.36291995),
                          "particledistribution/discrete/massbased": (0.63708005, 0.36291995),
                          "particledistribution/discrete/numberbased": (0.30, 0.70)}


@pytest.mark.parametrize("style", list(LIGGGHTS_NUMBER_SHARES))
def test_weights_by_mass_or_by_number_as_liggghts(make_sim, style):
    sim = make_sim(dialect="liggghts")
    sim.command(f"""
        atom_style granular
        region box block 0 1 0 1 0 1 units box
        create_box 1 box
        fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.005
        fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.008
        fix pdd1 all {style} 32452843 2 pts1 0.3 pts2 0.7
    """)
    mix = sim.fixes["pdd1"]
    np.testing.assert_allclose(mix.number_fraction, LIGGGHTS_NUMBER_SHARES[style], atol=5e-9)
    # the mass shares follow from the number shares and the masses (radius^3: 125 and 512)
    carried = mix.number_fraction * np.array([125.0, 512.0])
    np.testing.assert_allclose(mix.mass_fraction, carried / carried.sum(), rtol=1e-12)
    assert mix.mass_expected == pytest.approx(float(mix.number_fraction @ [t.mass_expected for t in mix.templates]))


def test_an_insertions_mixture_is_its_shares_to_a_particle(make_sim):
    """LIGGGHTS's randomize_list (exact numbers): 300 particles of shares 0.63708 and 0.36292 give
    191 or 192 and 109 or 108, never a multinomial's spread (sd 8.3); over 2,000 insertions the
    mean is the share within 4 standard errors of the one particle left to chance."""
    sim = make_sim(dialect="liggghts")
    sim.command("""
        atom_style granular
        region box block 0 1 0 1 0 1 units box
        create_box 1 box
        fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.005
        fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.008
        fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.3 pts2 0.7
    """)
    mix = sim.fixes["pdd1"]
    rng = np.random.default_rng(11)
    counts = np.array([mix.counts(rng, 300) for _ in range(2000)])
    assert set(counts[:, 0]) <= {191, 192} and (counts.sum(axis=1) == 300).all()
    share = 300 * mix.number_fraction[0]
    p = share - math.floor(share)
    assert abs(counts[:, 0].mean() - share) <= 4 * math.sqrt(p * (1 - p) / len(counts))
    radius, _, _, which = mix.draw(rng, 300)
    assert (np.diff(radius) <= 0).all() and (which == 0).sum() in (191, 192)


def test_relative_yes_is_read_and_said_to_change_nothing(make_sim):
    import io
    screen = io.StringIO()
    sim = make_sim(dialect="liggghts", screen=screen)
    sim.command("atom_style granular\nregion box block 0 1 0 1 0 1 units box\ncreate_box 1 box\n"
                "fix t all particletemplate/sphere 15485863 atom_type 1 density constant 2500 "
                "radius constant 0.001 relative yes")
    assert sim.fixes["t"].max_radius == 0.001
    assert ("fix t particletemplate/sphere: relative yes is read by no command; the radii are lengths, and the "
            "neighbor cutoff is sized from them (LIGGGHTS leaves them out of it)") in screen.getvalue()
