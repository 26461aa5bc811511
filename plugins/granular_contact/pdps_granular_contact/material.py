"""LIGGGHTS's material: the properties of ``fix property/global`` (youngsModulus, poissonsRatio per
type; coefficientRestitution, coefficientFriction, ... per type pair; characteristicVelocity), read
and checked where a contact sub-model needs them (``Material``), with one-line errors naming the
property and the fix."""

import numpy as np

from pdps_core.api import GlobalProperty, ScriptError

from .composition import coefficient_columns
from .contact_models import restitution_beta, shear_effective, youngs_effective

# LIGGGHTS's property names, the form each is given in, and its range
PROPERTIES = {
    "youngsModulus": ("per_type", "peratomtype", lambda y: y > 0, "> 0"),
    "poissonsRatio": ("per_type", "peratomtype", lambda nu: -1 < nu <= 0.5, "in (-1, 0.5]"),
    "coefficientRestitution": ("per_type_pair", "peratomtypepair", lambda e: 0 < e <= 1, "in (0, 1]"),
    "coefficientFriction": ("per_type_pair", "peratomtypepair", lambda mu: mu >= 0, ">= 0"),
    "coefficientRollingFriction": ("per_type_pair", "peratomtypepair", lambda mu: mu >= 0, ">= 0"),
    "coefficientRollingViscousDamping": ("per_type_pair", "peratomtypepair", lambda eta: eta >= 0, ">= 0"),
    "cohesionEnergyDensity": ("per_type_pair", "peratomtypepair", lambda k: k >= 0, ">= 0"),
    "characteristicVelocity": ("scalar", "scalar", lambda v: v > 0, "> 0"),
    "thermalConductivity": ("per_type", "peratomtype", lambda k: k >= 0, ">= 0"),
    "thermalCapacity": ("per_type", "peratomtype", lambda c: c > 0, "> 0"),
}


# LIGGGHTS's sanity bounds on youngsModulus by unit system (its global_properties.cpp): below
# (soft) or above (hard) them it refuses the material unless soft_particles / hard_particles yes
STIFFNESS_BOUNDS = {"si": (5e6, 1e9), "cgs": (5e7, 1e10)}


def check_stiffness(sim, label, values):
    """LIGGGHTS's bounds on Young's moduli in si and cgs units, each lifted by its command."""
    bounds = STIFFNESS_BOUNDS.get(sim.units.name)
    if bounds is None:
        return
    low, high = bounds
    checks = sim.stiffness_checks
    soft = [float(y) for y in values if float(y) < low]
    hard = [float(y) for y in values if float(y) > high]
    if soft and checks["soft"]:
        raise ScriptError(f"{label} must be >= {low:g} in {sim.units.name} units (got {soft[0]:g}), as LIGGGHTS "
                          "requires; give soft_particles yes to allow softer particles")
    if hard and checks["hard"]:
        raise ScriptError(f"{label} must be <= {high:g} in {sim.units.name} units (got {hard[0]:g}), as LIGGGHTS "
                          "requires; give hard_particles yes to allow harder particles")


def find_property(sim, name):
    """The fix holding global property ``name`` (the last one defined: fix property/global), or None."""
    found = None
    for fix in sim.fixes.values():
        if isinstance(fix, GlobalProperty) and fix.variable == name:
            found = fix
    return found


def read_property(sim, name, ntypes, who, spec=None):
    """The values of property ``name`` checked as PROPERTIES (or ``spec``, a tuple of that form, for
    a property a sub-model declares) says: a float (scalar), an array of ntypes + 1 (per type, index
    0 unused) or of (ntypes + 1, ntypes + 1) (per type pair). Missing, wrongly shaped or out-of-range
    values raise a one-line ScriptError naming the fix."""
    form, spelling, valid, bounds = spec or PROPERTIES[name]
    fix = find_property(sim, name)
    if fix is None:
        example = {"scalar": "VALUE", "per_type": "V1 ... V" + str(ntypes),
                   "per_type_pair": f"{ntypes} V11 ... V{ntypes}{ntypes}"}[form]
        raise ScriptError(f"{who} needs {name}: fix ID all property/global {name} {spelling} {example}")
    label = f"{name} (fix {fix.id})"
    if fix.style != form:
        raise ScriptError(f"{label} must be given as {spelling} (got {fix.args.style})")
    values = fix.values
    if form == "per_type" and len(values) != ntypes:
        raise ScriptError(f"{label} has {len(values)} value(s) for {ntypes} particle type(s)")
    if form == "per_type_pair" and fix.columns != ntypes:
        raise ScriptError(f"{label} is a {fix.columns} x {fix.columns} table for {ntypes} particle type(s)")
    bad = [float(x) for x in values if not valid(float(x))]
    if bad:
        raise ScriptError(f"{label} must be {bounds} (got {bad[0]:g})")
    if name == "youngsModulus":
        check_stiffness(sim, label, values)
    if form == "scalar":
        return float(values[0])
    if form == "per_type":
        return np.concatenate([[0.0], values])
    table = np.zeros((ntypes + 1, ntypes + 1))
    table[1:, 1:] = values.reshape(ntypes, ntypes)
    return table


class Material:
    """LIGGGHTS's material of types 1..ntypes, from its ``fix property/global`` commands, read when a
    sub-model asks (``read_property`` checks each property's form and range); ``who`` names
    the style in errors. A wall reads it with ntypes covering its own type."""

    def __init__(self, sim, ntypes, who):
        self.sim, self.ntypes, self.who = sim, ntypes, who
        self._read = {}
        self.declared = {}      # properties sub-models declare (ContactSubModel.properties)

    def property(self, name):
        """The property's values: a float (scalar), per type (ntypes + 1, index 0 unused) or per
        type pair ((ntypes + 1, ntypes + 1))."""
        if name not in self._read:
            self._read[name] = read_property(self.sim, name, self.ntypes, self.who, self.declared.get(name))
        return self._read[name]

    def columns(self, *tables):
        """Per-type-pair tables (or scalars, the same for every pair) stacked as coefficient columns."""
        return coefficient_columns(self.ntypes, tables)

    def pairs(self, function, *names):
        """A per-type-pair table of ``function(values of names for type i ..., for type j ...)``
        over per-type properties (effective moduli)."""
        values = [self.property(name) for name in names]
        table = np.zeros((self.ntypes + 1, self.ntypes + 1))
        for i in range(1, self.ntypes + 1):
            for j in range(1, self.ntypes + 1):
                table[i, j] = function(*[v[i] for v in values], *[v[j] for v in values])
        return table

    def youngs_effective(self):
        """Y* of every type pair: 1/Y* = (1 - nu_i^2)/Y_i + (1 - nu_j^2)/Y_j."""
        return self.pairs(lambda yi, ni, yj, nj: youngs_effective(yi, ni, yj, nj), "youngsModulus", "poissonsRatio")

    def shear_effective(self):
        """G* of every type pair: 1/G* = 2(2 - nu_i)(1 + nu_i)/Y_i + 2(2 - nu_j)(1 + nu_j)/Y_j."""
        return self.pairs(lambda yi, ni, yj, nj: shear_effective(yi, ni, yj, nj), "youngsModulus", "poissonsRatio")

    def restitution_beta(self):
        """beta = ln e / sqrt(ln^2 e + pi^2) of every type pair."""
        e = self.property("coefficientRestitution")
        beta = np.zeros_like(e)
        beta[1:, 1:] = np.vectorize(restitution_beta)(e[1:, 1:])
        return beta

    def log_restitution(self):
        e = self.property("coefficientRestitution")
        out = np.zeros_like(e)
        out[1:, 1:] = np.log(e[1:, 1:])
        return out
