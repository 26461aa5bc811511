r"""Granular contacts composed of sub-models, and the one contact loop generated around them.

A contact law is not written per style: it is a list of sub-models, one per part (LAMMPS's
GranularModel of GranSubMod's, LIGGGHTS's contact-model template), called in this order::

    surface  normal  damping  cohesion  tangential  rolling  twisting  heat

Each sub-model is a class (``ContactSubModel``) with a numba function ``compute(c, k, hist, h)``: it
reads and writes the contact's quantities in ``c`` (``contact_state``: overlap, normal, velocities,
and what the parts before it wrote), takes its coefficients for this type pair as the tuple ``k``,
and keeps its own per-contact values in ``hist[h : h + history_width]``. Its coefficients per type
pair come from ``coefficients(material)`` (LIGGGHTS's ``fix property/global`` properties, read
where the model needs them) as columns of one table; its settings (``tangential_damping off``) from
the host style's words.

Sub-models are found through entry points like styles, in the group ``pdps.FAMILY.PART``: the
family is the style whose words name them (``gran``: LIGGGHTS's ``pair_style gran model hertz
tangential history rolling_friction epsd2 cohesion sjkr`` and ``fix wall/gran model ...``), so a
distribution adds a cohesion model with one entry point and no change elsewhere::

    [project.entry-points."pdps.gran.cohesion"]
    washino = "my_cohesion.washino:Washino"

``ContactModel(family, {"normal": "hertz", ...}, settings)`` looks the sub-models up and lays out
their history and coefficients; ``kernels()`` generates (once per composition, cached on disk as
pdps_core's pair loops are) the loops a pair style and a wall call:

- ``pair_forces``: every touching pair of a half list: history loaded and stored on both particles,
  force and torques on both;
- ``pair_contacts``: the same contacts evaluated as a setup force computation does, nothing stored,
  for compute pair/gran/local;
- ``wall_forces``: one particle's contacts with the elements of a wall.

Only the parts a script names are called: a contact without rolling friction has no rolling call
and no rolling history.
"""

import importlib
import inspect
from typing import ClassVar

import numpy as np

from pdps_core.api import ScriptError, SubModel, generated_module, registry

from . import contact_loop, contact_state
from .contact_models import restitution_beta, shear_effective, youngs_effective

PARTS = ("surface", "normal", "damping", "cohesion", "tangential", "rolling", "twisting", "heat")


class ContactSubModel(SubModel):
    """One part of a granular contact. A subclass sets ``kind`` (``"gran.cohesion"``), ``name``
    (the script word), ``compute`` (a module-level numba function ``(c, k, hist, h)``, module
    docstring), ``history_width`` and ``coefficients``; its module's docstring is its manual page
    (``pdps doc gran.cohesion NAME``): the formula, each coefficient with its unit, the paper."""
    history_width: ClassVar[int] = 0
    compute: ClassVar = None
    # material properties of its own (LIGGGHTS's are known): name -> (form, how fix property/global
    # spells it, a check of one value, the check in words), e.g. {"hamakerConstant": ("per_type_pair",
    # "peratomtypepair", lambda a: a > 0, "> 0")}
    properties: ClassVar[dict] = {}

    def __init__(self, settings):
        """``settings``: the host style's model settings by word (``{"tangential_damping": "on"}``)."""
        self.settings = settings

    @property
    def part(self):
        return self.kind.partition(".")[2]

    def coefficients(self, material):
        """This model's coefficients of every type pair: an array (ntypes + 1, ntypes + 1, n), row
        and column 0 unused; ``material`` reads LIGGGHTS's properties (``Material``)."""
        return material.columns()


class Material:
    """LIGGGHTS's material of types 1..ntypes, from its ``fix property/global`` commands, read when a
    sub-model asks (``liggghts.read_property`` checks each property's form and range); ``who`` names
    the style in errors. A wall reads it with ntypes covering its own type."""

    def __init__(self, sim, ntypes, who):
        self.sim, self.ntypes, self.who = sim, ntypes, who
        self._read = {}
        self.declared = {}      # properties sub-models declare (ContactSubModel.properties)

    def property(self, name):
        """The property's values: a float (scalar), per type (ntypes + 1, index 0 unused) or per
        type pair ((ntypes + 1, ntypes + 1))."""
        if name not in self._read:
            from .liggghts import read_property
            self._read[name] = read_property(self.sim, name, self.ntypes, self.who, self.declared.get(name))
        return self._read[name]

    def columns(self, *tables):
        """Per-type-pair tables (or scalars, the same for every pair) stacked as coefficient columns."""
        n = self.ntypes + 1
        out = np.zeros((n, n, len(tables)))
        for k, table in enumerate(tables):
            out[:, :, k] = table
        return out

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


class ContactModel:
    """The sub-models of one contact law, their history layout and their coefficient columns.

    ``chosen``: part -> script word (parts not named are not called; ``surface`` defaults to
    ``default``); ``settings``: the host style's model settings, handed to every sub-model."""

    def __init__(self, family, chosen, settings=None):
        self.family = family
        chosen = {"surface": "default", **chosen}
        unknown = [part for part in chosen if part not in PARTS]
        if unknown:
            raise ScriptError(f"unknown contact part {unknown[0]} (parts: {', '.join(PARTS)})")
        self.sub_models = []
        for part in PARTS:
            if part in chosen:
                cls = registry.lookup(f"{family}.{part}", chosen[part])
                if not (isinstance(cls, type) and issubclass(cls, ContactSubModel) and cls.compute is not None):
                    raise ScriptError(f"{family}.{part} {chosen[part]} is not a contact sub-model with a compute "
                                      "function")
                self.sub_models.append(cls(settings or {}))
        self.history_offsets, offset = [], 0
        for model in self.sub_models:
            self.history_offsets.append(offset)
            offset += model.history_width
        self.history_width = offset

    def part(self, part):
        """The sub-model of ``part``, or None."""
        for model in self.sub_models:
            if model.part == part:
                return model
        return None

    def history_at(self, part):
        """Where ``part``'s values start in a contact's history."""
        for model, offset in zip(self.sub_models, self.history_offsets):
            if model.part == part:
                return offset
        raise KeyError(part)

    def kernels(self):
        """The generated module of this composition (module docstring); after ``bind``."""
        text, keyed = self._source()
        origin = f"{self.family}_" + "_".join(f"{m.part}_{m.name}" for m in self.sub_models)
        return generated_module(origin, text, keyed)

    def _source(self):
        lines = [f'"""Contact loops of {self.family}: '
                 + ", ".join(f"{m.part} {m.name}" for m in self.sub_models)
                 + ', generated by pdps_granular_contact.composition; do not edit."""',
                 "from numba import njit",
                 "from pdps_granular_contact.contact_loop import *  # noqa: F401,F403",
                 "from pdps_granular_contact.contact_state import *  # noqa: F401,F403"]
        keyed = [inspect.getsource(contact_loop).encode(), inspect.getsource(contact_state).encode()]
        calls, column = [], 0
        for k, (model, offset) in enumerate(zip(self.sub_models, self.history_offsets)):
            function = getattr(model.compute, "py_func", model.compute)
            module = importlib.import_module(function.__module__)
            lines.append(f"from {function.__module__} import {function.__name__} as part_{k}")
            keyed.append(inspect.getsource(module).encode())
            ncoeff = self.column_counts[k]
            coeff = "(" + "".join(f"coeff[ti, tj, {column + q}], " for q in range(max(ncoeff, 1))) + ")"
            if ncoeff == 0:
                coeff = "(0.0,)"
            column += ncoeff
            calls.append(f"    part_{k}(c, {coeff}, hist, {offset})")
        lines += ["", "", "@njit(cache=True, _nrt=False)", "def contact(c, coeff, ti, tj, hist):",
                  '    """The sub-models in order, on the contact in c."""',
                  "    for s in range(FIRST_OUTPUT, SIZE):", "        c[s] = 0.0", *calls]
        with_history = self.history_width > 0
        lines.append(contact_loop.PAIR_FORCES if with_history else contact_loop.PAIR_FORCES_NO_HISTORY)
        lines.append(contact_loop.PAIR_CONTACTS)
        lines.append(contact_loop.WALL_FORCES)
        return "\n".join(lines) + "\n", b"".join(keyed)

    column_counts = None      # coefficient columns of each sub-model, once bind() has read them

    def bind(self, material):
        """The coefficient table for ``material``, remembering each model's column count (the
        generated code reads them by position)."""
        for model in self.sub_models:
            material.declared.update(model.properties)
        tables = [np.asarray(model.coefficients(material), dtype=np.float64) for model in self.sub_models]
        n = material.ntypes + 1
        for model, table in zip(self.sub_models, tables):
            if table.ndim != 3 or table.shape[:2] != (n, n):
                raise ScriptError(f"{model.kind} {model.name}: coefficients() gave shape {table.shape}, not "
                                  f"({n}, {n}, columns)")
        self.column_counts = tuple(table.shape[2] for table in tables)
        table = np.concatenate(tables, axis=2) if tables else np.zeros((n, n, 0))
        return np.ascontiguousarray(table if table.shape[2] else np.zeros((n, n, 1)))

