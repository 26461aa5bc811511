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
  force and torques on both; a block of contacts at a time (``contact_block``: gathered, computed in
  one vectorised loop, added in list order), which ``pair_kernels()`` compiles and ``block()``
  gives the work arrays of;
- ``pair_contacts``: the same contacts evaluated as a setup force computation does, nothing stored,
  for compute pair/gran/local;
- ``wall_forces``: one particle's contacts with the elements of a wall.

Only the parts a script names are called: a contact without rolling friction has no rolling call
and no rolling history.

Two extension points serve a liquid bridge (LIGGGHTS's capillary cohesion models):

- a sub-model with a ``close`` function acts on bodies apart, as long as they are closer than its
  ``reach`` times :math:`R_i + R_j` (LIGGGHTS's surfacesClose and contact distance factor): the
  pair loop calls it for those pairs, one at a time (``close_pair``), the other sub-models'
  histories forgotten there (LIGGGHTS's tangential and rolling models zero theirs), and the neighbor
  cutoff covers the reach (``ContactModel.reach``, known after ``bind``). A contact made apart
  (a bridge that forms before touching) gets history slots when its history is not all zero;
- a ``wet`` sub-model reads the surface liquid of both particles and moves it (contact_state's
  ``LIQUID_*``): the loops take the per-atom ``surfaceLiquidContent`` (written back: a model may cap
  it) and ``liquidFlux`` (added to), which the pair style owns and integrates.
"""

import importlib
import inspect
from typing import ClassVar

import numpy as np
from numba import types
from numba.core.registry import CPUDispatcher

from pdps_core.api import ScriptError, SubModel, generated_module, registry

from . import contact_block, contact_loop, contact_slots, contact_state

# the most values a contact may keep (the block's history columns)
MAX_HISTORY = 16
# block_contacts(n, block_in, block_out, block_index, coeff, dt, update, dimension)
BLOCK_SIGNATURE = (types.int64, types.float64[::1], types.float64[::1], types.int64[::1], types.float64[:, :, ::1],
                   types.float64, types.boolean, types.int64)

PARTS = ("surface", "normal", "damping", "cohesion", "tangential", "rolling", "twisting", "heat")


def coefficient_columns(ntypes, tables):
    """Per-type-pair tables ((ntypes + 1, ntypes + 1) each, or numbers: the same for every pair)
    side by side, a sub-model's coefficient columns."""
    n = ntypes + 1
    out = np.zeros((n, n, len(tables)))
    for k, table in enumerate(tables):
        out[:, :, k] = table
    return out


def source_modules(*functions):
    """The modules of the numba functions given and of those they call, to the last: what the
    generated module's cache key reads (a helper in another module changes the law too)."""
    found, visited, todo = [], set(), [f for f in functions if f is not None]
    while todo:
        function = getattr(todo.pop(), "py_func", None)
        if function is None or function in visited:
            continue
        visited.add(function)
        module = importlib.import_module(function.__module__)
        if module not in found:
            found.append(module)
        for name in function.__code__.co_names:
            value = function.__globals__.get(name)
            if isinstance(value, CPUDispatcher):
                todo.append(value)
    return found


class ContactSubModel(SubModel):
    """One part of a granular contact. A subclass sets ``kind`` (``"gran.cohesion"``), ``name``
    (the script word), ``compute`` (a module-level numba function ``(c, k, hist, h)``, module
    docstring), ``history_width`` and ``coefficients``; its module's docstring is its manual page
    (``pdps doc gran.cohesion NAME``): the formula, each coefficient with its unit, the paper."""
    history_width: ClassVar[int] = 0
    # how each history value is handed to the other body of a pair: -1 (the default) a value seen
    # negated from there (a tangential spring), +1 one seen the same (a rolling displacement)
    history_transfer: ClassVar[tuple] = ()
    compute: ClassVar = None
    # the host's model settings this sub-model reads, with their defaults (LIGGGHTS's registerSettings):
    # {"tangential_damping": "on", "limitForce": "off"}
    settings_read: ClassVar[dict] = {}
    # material properties of its own (LIGGGHTS's are known): name -> (form, how fix property/global
    # spells it, a check of one value, the check in words), e.g. {"hamakerConstant": ("per_type_pair",
    # "peratomtypepair", lambda a: a > 0, "> 0")}
    properties: ClassVar[dict] = {}
    # a numba function (c, k, hist, h) for bodies apart but within ``reach`` (LIGGGHTS's surfacesClose:
    # a liquid bridge stretched beyond touching; module docstring)
    close: ClassVar = None
    # reads the particles' surface liquid and may move it (contact_state's LIQUID_*)
    wet: ClassVar[bool] = False

    def __init__(self, settings):
        """``settings``: the host style's model settings given in the script, by word
        (``{"tangential_damping": "off"}``); those it reads (``settings_read``) are kept, with the
        defaults of those not given."""
        self.settings = {name: settings.get(name, default) for name, default in self.settings_read.items()}

    def on(self, setting):
        """An on/off setting this sub-model reads, as 1.0 or 0.0 (a coefficient column)."""
        return 1.0 if self.settings[setting] == "on" else 0.0

    @property
    def part(self):
        return self.kind.partition(".")[2]

    def contact_time(self, material, t, m_eff, r_eff, speed):
        """A normal model's duration of a contact of two bodies of type t (effective mass and radius)
        meeting at ``speed``, for the time-step advice; None where it gives none."""
        return None

    def coefficients(self, material):
        """This model's coefficients of every type pair: an array (ntypes + 1, ntypes + 1, n), row
        and column 0 unused; ``material`` reads LIGGGHTS's properties (``Material``)."""
        return material.columns()

    def reach(self, material):
        """How far bodies apart are handed to ``close``: a factor on R_i + R_j (LIGGGHTS's contact
        distance factor), asked after ``coefficients``."""
        return 1.0


class ContactModel:
    """The sub-models of one contact law, their history layout and their coefficient columns.

    ``chosen``: part -> script word (parts not named are not called; ``surface`` defaults to
    ``default``); ``settings``: the model settings the script gives (word -> value), each read by
    the sub-models that declare it (``settings_read``); one no chosen sub-model reads is refused, as
    LIGGGHTS refuses a setting no model of the line registers."""

    def __init__(self, family, chosen, settings=None, log=False, slot_cache=False):
        self.family = family
        self.log = log          # the pair loop lists each contact and its force (ContactTable styles)
        # the pair loop keeps each list entry's contact slots (a style whose slots stay put between builds)
        self.slot_cache = slot_cache
        chosen = {"surface": "default", **chosen}
        unknown = [part for part in chosen if part not in PARTS]
        if unknown:
            raise ScriptError(f"unknown contact part {unknown[0]} (parts: {', '.join(PARTS)})")
        self.sub_models = []
        for part in PARTS:
            if isinstance(chosen.get(part), ContactSubModel):
                # a sub-model another style composes in (fix heat/gran's conduction), made by it
                self.sub_models.append(chosen[part])
            elif part in chosen:
                cls = registry.lookup(f"{family}.{part}", chosen[part])
                if not (isinstance(cls, type) and issubclass(cls, ContactSubModel) and cls.compute is not None):
                    raise ScriptError(f"{family}.{part} {chosen[part]} is not a contact sub-model with a compute "
                                      "function")
                self.sub_models.append(cls({name: value for name, value in (settings or {}).items()
                                            if value is not None}))
        given = {name: value for name, value in (settings or {}).items() if value is not None}
        unread = [name for name in given if not any(name in m.settings_read for m in self.sub_models)]
        if unread:
            named = " ".join(f"{m.part} {m.name}" for m in self.sub_models if m.part != "surface")
            raise ScriptError(f"{unread[0]} is not a setting of the chosen models ({named})")
        self.history_offsets, offset = [], 0
        for model in self.sub_models:
            self.history_offsets.append(offset)
            offset += model.history_width
        self.history_width = offset
        self.closing = any(model.close is not None for model in self.sub_models)
        self.wet = any(model.wet for model in self.sub_models)
        self.reach = 1.0        # set by bind() where a model acts on bodies apart

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
        parts = "_".join(f"{m.part}_{m.name}" for m in self.sub_models)
        origin = f"{self.family}_{parts}" + ("_log" if self.log else "") + ("_cached" if self.slot_cache else "")
        return generated_module(origin, text, keyed)

    def pair_kernels(self):
        """``kernels()``, its block loop compiled vectorised (contact_block), for a pair style."""
        module = self.kernels()
        if module.block_contacts.signatures:
            return module
        with contact_block.vectorized():
            module.block_contacts.compile(BLOCK_SIGNATURE)
        # a call of other argument types would compile a scalar copy: let it fail instead
        module.block_contacts.disable_compile()
        return module

    @staticmethod
    def block():
        """The work arrays of a pair loop: a block's columns in (float), out (float) and its rows,
        slots and types (integers); made once per style, passed as ``*block`` (contact_block)."""
        return (np.zeros(contact_block.HIST_IN * contact_block.BLOCK + MAX_HISTORY * contact_block.BLOCK),
                np.zeros(contact_block.HIST_OUT * contact_block.BLOCK + MAX_HISTORY * contact_block.BLOCK),
                np.zeros(contact_block.INDEX_COLUMNS * contact_block.BLOCK, dtype=np.int64))

    def _source(self):
        if self.history_width > MAX_HISTORY:
            raise ScriptError(f"the contact models keep {self.history_width} values a contact, more than the "
                              f"{MAX_HISTORY} a pair loop's block holds")
        lines = [f'"""Contact loops of {self.family}: '
                 + ", ".join(f"{m.part} {m.name}" for m in self.sub_models)
                 + ', generated by pdps_granular_contact.composition; do not edit."""',
                 "from numba import njit",
                 "from pdps_granular_contact.contact_block import *  # noqa: F401,F403",
                 "from pdps_granular_contact.contact_loop import *  # noqa: F401,F403",
                 "from pdps_granular_contact.contact_state import *  # noqa: F401,F403",
                 "",
                 f"HISTORY = {self.history_width}",
                 f"HIST_SIZE = {max(self.history_width, 1)}"]
        keyed = [inspect.getsource(module).encode() for module in (contact_loop, contact_state, contact_block,
                                                                   contact_slots)]
        calls, column, beyond, seen = [], 0, "", set()
        for k, (model, offset) in enumerate(zip(self.sub_models, self.history_offsets)):
            function = getattr(model.compute, "py_func", model.compute)
            lines.append(f"from {function.__module__} import {function.__name__} as compute_{k}")
            lines.append(f"part_{k} = inline_part(compute_{k})")
            for module in source_modules(model.compute, model.close):
                if module not in seen:
                    seen.add(module)
                    keyed.append(inspect.getsource(module).encode())
            ncoeff = self.column_counts[k]
            coeff = "(" + "".join(f"coeff[ti, tj, {column + q}], " for q in range(max(ncoeff, 1))) + ")"
            if ncoeff == 0:
                coeff = "(0.0,)"
            column += ncoeff
            calls.append(f"    part_{k}(c, {coeff}, hist, {offset})")
            pulloff = getattr(model, "pulloff", None)
            if pulloff is not None:
                # a contact lasting beyond touching (contact_loop.BEYOND)
                lines += [f"from {pulloff.__module__} import {pulloff.__name__} as pulloff_{k}", "", "",
                          "@njit(cache=True)", "def lasting(coeff, ti, tj, radius_i, radius_j, partner, i, tag_j):",
                          '    """Once made, the contact of i and j reaches the pull-off distance beyond touching."""',
                          "    if find_slot(partner, i, tag_j) < 0:", "        return 0.0",
                          f"    return pulloff_{k}({coeff}, radius_i, radius_j)"]
                beyond = contact_loop.BEYOND
        # the outputs zeroed one by one: a loop over slots would keep c in memory (contact_block)
        zero = [f"    c[{slot}] = 0.0" for slot in range(contact_state.FIRST_OUTPUT, contact_state.SIZE)]
        lines += ["", "", '@njit(inline="always", _nrt=False, error_model="numpy")',
                  "def contact(c, coeff, ti, tj, hist):",
                  '    """The sub-models in order, on the contact in c."""', *zero, *calls,
                  # the loops that take one contact at a time (walls, compute pair/gran/local) call
                  # one compiled copy: the law is compiled into the block loop and here, not four times
                  "", "", '@njit(cache=True, _nrt=False, error_model="numpy")',
                  "def contact_one(c, coeff, ti, tj, hist):",
                  '    """contact(), compiled once for the scalar loops."""',
                  "    contact(c, coeff, ti, tj, hist)"]
        if self.closing:
            lines += self._apart_source()
            beyond += contact_loop.CLOSE
        with_history = self.history_width > 0
        # values the same seen from either body (a rolling displacement, a twist angle) go to the
        # partner as they are, the others negated
        same = {offset + d for model, offset in zip(self.sub_models, self.history_offsets)
                for d, factor in enumerate(model.history_transfer) if factor > 0}
        store = contact_loop.STORE.format(values="".join(
            contact_loop.STORE_VALUE.format(h=h, sign="" if h in same else "-") for h in range(self.history_width)))
        heat = self.part("heat") is not None
        width = self.history_width
        wet = self.wet
        if self.closing:
            lines.append(contact_loop.CLOSE_PAIR.format(store=contact_loop.CLOSE_STORE.format(values="".join(
                contact_loop.CLOSE_STORE_VALUE.format(h=h, sign="" if h in same else "-")
                for h in range(self.history_width))) if with_history else ""))
        lines.append(contact_loop.BLOCK_CONTACTS.format(
            heat_fill=(contact_loop.HEAT_FILL_BLOCK if heat else "") + (contact_loop.LIQUID_FILL_BLOCK if wet else ""),
            heat_out=(contact_loop.HEAT_OUT_BLOCK if heat else "") + (contact_loop.LIQUID_OUT_BLOCK if wet else ""),
            hist_in="".join(f"    hist[{h}] = block_in[(HIST_IN + {h}) * BLOCK + m]\n" for h in range(width)),
            hist_out="".join(f"    block_out[(HIST_OUT + {h}) * BLOCK + m] = hist[{h}]\n" for h in range(width))))
        lines.append(contact_loop.SCATTER_CONTACTS.format(
            store=store if with_history else "",
            heat_apply=(contact_loop.HEAT_APPLY if heat else "") + (contact_loop.LIQUID_APPLY if wet else ""),
            log=contact_loop.LOG if self.log else ""))
        load = contact_loop.LOAD_CACHED if self.slot_cache else contact_loop.LOAD
        blocks = dict(load=load if with_history else contact_loop.NO_SLOTS,
                      heat_zero=contact_loop.HEAT_ZERO if heat else "",
                      heat_gather=(contact_loop.HEAT_GATHER if heat else "") + (contact_loop.LIQUID_GATHER if wet else ""),
                      hist_gather=contact_loop.HIST_GATHER if with_history else "", beyond=beyond)
        lines.append(contact_loop.PAIR_FORCES.format(**blocks, flush_full=contact_loop.flush(16),
                                                     flush_last=contact_loop.flush(4)))
        # the touching loop's body sits one level less deep: its blocks lose four spaces; it has no
        # list entry to key a slot by: it searches
        blocks["load"] = contact_loop.LOAD if with_history else contact_loop.NO_SLOTS
        lines.append(contact_loop.PAIR_FORCES_TOUCHING.format(
            **{name: text if name == "heat_zero" else "".join(line[4:] + "\n" for line in text.splitlines())
               for name, text in blocks.items()}, flush_full=contact_loop.flush(12), flush_last=contact_loop.flush(4)))
        lines.append(contact_loop.PAIR_CONTACTS.format(liquid_fill=contact_loop.LIQUID_FILL_ONE if wet else ""))
        lines.append(contact_loop.WALL_FORCES)
        return "\n".join(lines) + "\n", b"".join(keyed)

    def _apart_source(self):
        """``apart``: the sub-models of bodies apart within reach, each model's ``close`` where it has one,
        the history of the others forgotten (LIGGGHTS's surfacesClose: its tangential and rolling
        models zero theirs), the lever arms the radii (its cohesion models' surfacesClose)."""
        lines = [f"REACH = {sum(self.column_counts)}", "", "", '@njit(inline="always", _nrt=False, error_model="numpy")',
                 "def apart(c, coeff, ti, tj, hist):",
                 '    """Bodies apart, closer than the reach: what each sub-model does then."""',
                 *[f"    c[{slot}] = 0.0" for slot in range(contact_state.FIRST_OUTPUT, contact_state.SIZE)],
                 "    c[ARM_I] = c[RADIUS_I]", "    c[ARM_J] = c[RADIUS_J]", "    slide(c)"]
        column, imports = 0, []
        for k, (model, offset) in enumerate(zip(self.sub_models, self.history_offsets)):
            ncoeff = self.column_counts[k]
            coeff = "(" + "".join(f"coeff[ti, tj, {column + q}], " for q in range(max(ncoeff, 1))) + ")"
            if ncoeff == 0:
                coeff = "(0.0,)"
            column += ncoeff
            if model.close is not None:
                function = getattr(model.close, "py_func", model.close)
                imports += [f"from {function.__module__} import {function.__name__} as close_{k}",
                            f"close_part_{k} = inline_part(close_{k})"]
                lines.append(f"    close_part_{k}(c, {coeff}, hist, {offset})")
            else:
                lines += [f"    hist[{offset + d}] = 0.0" for d in range(model.history_width)]
        return imports + [""] + lines

    column_counts = None      # coefficient columns of each sub-model, once bind() has read them

    def bind(self, material):
        """The coefficient table for ``material``, remembering each model's column count (the
        generated code reads them by position)."""
        declared = getattr(material, "declared", None)      # a material that reads properties by name
        for model in self.sub_models:
            if declared is not None:
                declared.update(model.properties)
        tables = [np.asarray(model.coefficients(material), dtype=np.float64) for model in self.sub_models]
        n = material.ntypes + 1
        for model, table in zip(self.sub_models, tables):
            if table.ndim != 3 or table.shape[:2] != (n, n):
                raise ScriptError(f"{model.kind} {model.name}: coefficients() gave shape {table.shape}, not "
                                  f"({n}, {n}, columns)")
        self.column_counts = tuple(table.shape[2] for table in tables)
        if self.closing:
            # the last column: how far (a factor on R_i + R_j) bodies apart reach the models' close
            self.reach = max([1.0] + [float(model.reach(material)) for model in self.sub_models
                                      if model.close is not None])
            tables.append(np.full((n, n, 1), self.reach))
        table = np.concatenate(tables, axis=2) if tables else np.zeros((n, n, 0))
        return np.ascontiguousarray(table if table.shape[2] else np.zeros((n, n, 1)))

