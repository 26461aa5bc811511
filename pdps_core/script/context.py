"""What a formula reads of the simulation (pdps_core.script.expression's ``env``).

``FormulaContext(sim)`` reads global values (equal-style variables, thermo, ``$(...)``);
``FormulaContext(sim, per_atom=True)`` reads per-atom vectors of the owned particles (atom-style
variables). Indices in references (``c_ID[i]``) count as the script's dialect says.
"""

import numpy as np

from ..errors import ScriptError
from ..state import observables as obs

AXES = {"x": 0, "y": 1, "z": 2}
BOUNDS = {"xmin": (0, min), "xmax": (0, max), "ymin": (1, min), "ymax": (1, max), "zmin": (2, min),
          "zmax": (2, max)}


class FormulaContext:
    def __init__(self, sim, per_atom=False, vector=False):
        self.sim, self.per_atom, self.vector = sim, per_atom, vector

    # ---- the clock ----------------------------------------------------------------------------------
    def step(self):
        return self.sim.step

    def dt(self):
        return self.sim.dt

    def run_bounds(self):
        return self.sim.run_state.ramp_bounds

    # ---- thermo keywords and references -------------------------------------------------------------
    def thermo(self, name):
        from ..output.thermo import keyword_value
        return float(keyword_value(self.sim, name))

    def reference(self, prefix, ident, indices):
        sim = self.sim
        if prefix == "v":
            if self.vector and not indices and sim.variables.style(ident) == "vector":
                return sim.variables.vector(ident)
            return sim.variables.read(ident, indices, per_atom=self.per_atom, index_base=sim.dialect.index_base)
        if self.vector and not indices:
            style = self._style(prefix, ident)
            method = getattr(style, "vector", None)
            if method is None:
                raise ScriptError(f"{prefix}_{ident}: {style.kind} {ident} ({style.name}) has no global vector")
            return np.asarray(method(sim), dtype=np.float64).ravel()
        if self.per_atom and prefix == "f" and len(indices) <= 1 and self._liggghts_property(ident):
            from ..styles import PeratomReference
            word = f"f_{ident}" + (f"[{indices[0]}]" if indices else "")
            return PeratomReference(sim, word, word).values(sim)
        if self.per_atom and (not indices or len(indices) == 1 and self._has_peratom(prefix, ident)):
            return self._peratom(prefix, ident, indices)
        if prefix == "c":
            return float(sim.compute_value(ident, indices))
        return float(sim.fix_value(ident, indices))

    def _style(self, prefix, ident):
        sim = self.sim
        style = sim.styles.find_compute(ident) if prefix == "c" else (sim.fixes.get(ident) or sim.analyzes.get(ident))
        if style is None:
            raise ScriptError(f"{'compute' if prefix == 'c' else 'fix'} {ident} is not defined")
        return style

    def _liggghts_property(self, ident):
        """In the LIGGGHTS dialect, f_NAME of no fix names a per-atom property a style made
        (f_surfaceLiquidContent of a liquid bridge, f_Temp of fix heat/gran), as in dumps."""
        sim = self.sim
        return (sim.dialect.name == "liggghts" and ident not in sim.fixes and ident not in sim.analyzes
                and sim.particles.has(ident))

    def _has_peratom(self, prefix, ident):
        return callable(getattr(self._style(prefix, ident), "peratom", None))

    def _peratom(self, prefix, ident, indices):
        from ..styles import peratom_column
        style = self._style(prefix, ident)
        if not callable(getattr(style, "peratom", None)):
            raise ScriptError(f"{prefix}_{ident}: {style.kind} {ident} ({style.name}) has no per-atom values")
        column = indices[0] if indices else None
        return peratom_column(self.sim, style, column, f"{prefix}_{ident}")

    # ---- atoms ----------------------------------------------------------------------------------------
    def atom_vector(self, name):
        if not self.per_atom:
            raise ScriptError(f"{name} is an atom vector: only atom-style variables read it "
                              f"(an equal-style formula reads one particle as {name}[ID])")
        return self._column(name)

    def _column(self, name):
        sim = self.sim
        p = sim.particles
        n = p.nlocal
        if name in AXES or name in ("vx", "vy", "vz", "fx", "fy", "fz"):
            array = {"": "x", "v": "v", "f": "f"}[name[:-1]]
            return p.arrays[array][:n, AXES[name[-1]]].astype(np.float64)
        if name == "id":
            return p.tag[:n].astype(np.float64)
        if name == "type":
            return p.type[:n].astype(np.float64)
        if name == "mass":
            return obs.masses(sim, np.ones(n, dtype=bool)).astype(np.float64)
        if name == "radius":
            if "radius" not in p.arrays:
                raise ScriptError("radius needs particle radii (atom_style sphere)")
            return p.arrays["radius"][:n].astype(np.float64)
        for optional, array in (("mol", "molecule"), ("q", "q")):
            if name == optional:
                if array not in p.arrays:
                    raise ScriptError(f"{name}: the particles have no {'molecule ids' if name == 'mol' else 'charges'}")
                return p.arrays[array][:n].astype(np.float64)
        raise ScriptError(f"unknown atom vector {name}")

    def atom_value(self, name, tag):
        sim = self.sim
        rows = np.flatnonzero(sim.particles.tag[:sim.particles.nlocal] == tag)
        mine = float(self._column(name)[rows[0]]) if len(rows) else 0.0
        found = sim.comm.sum(len(rows))
        if found != 1:
            raise ScriptError(f"{name}[{tag}]: there is no particle with id {tag}")
        return float(sim.comm.sum(mine))

    # ---- group functions -----------------------------------------------------------------------------
    def group_function(self, name, group, rest):
        sim = self.sim
        sim.require_box(f"{name}()")
        members = sim.groups.select(sim, sim.require_group(group))
        words = list(rest)
        if words and words[-1] in sim.system.regions and not (name in ("xcm", "vcm", "fcm", "bound") and len(words) == 1):
            region = sim.system.regions[words.pop()]
            members = members & region.match(sim.x)
        p = sim.particles
        m = obs.masses(sim, members)
        if name == "count":
            return float(sim.comm.sum(int(members.sum())))
        if name == "mass":
            return float(sim.comm.sum(float(m.sum())))
        if name == "charge":
            if "q" not in p.arrays:
                return 0.0
            return float(sim.comm.sum(float(p.arrays["q"][:p.nlocal][members].sum())))
        if name == "ke":
            v = sim.v[members]
            return float(sim.comm.sum(0.5 * float((m[:, None] * v * v).sum()))) * sim.units.mvv2e
        if name in ("xcm", "vcm", "fcm", "gyration"):
            total = sim.comm.sum(float(m.sum()))
            if name == "fcm":
                vector = sim.comm.sum(sim.f[members].sum(axis=0))
                return float(vector[self._axis(name, words)])
            if total <= 0.0:
                return 0.0
            x = (sim.x[members] + p.image[:p.nlocal][members] * sim.box.length) if name != "vcm" else sim.v[members]
            centre = sim.comm.sum((m[:, None] * x).sum(axis=0)) / total
            if name == "gyration":
                spread = sim.comm.sum(float((m * ((x - centre) ** 2).sum(axis=1)).sum()))
                return float(np.sqrt(spread / total))
            return float(centre[self._axis(name, words)])
        if name == "bound":
            if not words or words[0] not in BOUNDS:
                raise ScriptError(f"bound() takes xmin, xmax, ymin, ymax, zmin or zmax (got {' '.join(words) or 'nothing'})")
            d, pick = BOUNDS[words[0]]
            values = sim.x[members, d]
            local = (values.min() if pick is min else values.max()) if len(values) else (
                np.inf if pick is min else -np.inf)
            return float(sim.comm.min(float(local)) if pick is min else sim.comm.max(float(local)))
        raise ScriptError(f"group function {name}() is not supported")

    @staticmethod
    def _axis(name, words):
        if not words or words[0] not in AXES:
            raise ScriptError(f"{name}() takes a group and a dimension x, y or z (got {' '.join(words) or 'nothing'})")
        return AXES[words[0]]

    # ---- special functions ---------------------------------------------------------------------------
    def vector_reduce(self, name, prefix, ident, column=None):
        """sum(), min(), max(), ave(), trap(), slope() of a global vector (c_ID, f_ID, v_NAME), or of
        one column of a global array (c_ID[i], f_ID[i], i counted as the dialect counts)."""
        sim = self.sim
        if prefix == "v":
            values = np.asarray(sim.variables.vector(ident), dtype=np.float64)
        elif column is not None:
            style = self._style(prefix, ident)
            method = getattr(style, "array", None)
            shown = f"{prefix}_{ident}[{column}]"
            if method is None:
                raise ScriptError(f"{name}({shown}): {style.kind} {ident} has no global array")
            table = np.asarray(method(sim), dtype=np.float64)
            k = sim.dialect_index(column, shown)
            if table.ndim != 2 or not 0 <= k < table.shape[1]:
                raise ScriptError(f"{name}({shown}): {style.kind} {ident}'s array has {np.shape(table)} values")
            values = table[:, k]
        else:
            style = self._style(prefix, ident)
            method = getattr(style, "vector", None)
            if method is None:
                raise ScriptError(f"{name}({prefix}_{ident}): {style.kind} {ident} has no global vector")
            values = np.asarray(method(sim), dtype=np.float64).ravel()
        if len(values) == 0:
            return 0.0
        if name == "sum":
            return float(values.sum())
        if name == "min":
            return float(values.min())
        if name == "max":
            return float(values.max())
        if name == "ave":
            return float(values.mean())
        if name == "trap":
            return float(values.sum() - 0.5 * (values[0] + values[-1]))
        # slope: least-squares slope of the values against their index (LAMMPS's slope()); of one
        # value, LAMMPS's BIG, 1e20 (measured: slope(f_ID) of a fix vector's first row)
        index = np.arange(len(values), dtype=np.float64)
        if len(values) < 2:
            return 1.0e20
        return float(np.polyfit(index, values, 1)[0])

    def mask_function(self, name, words):
        sim = self.sim
        if not self.per_atom:
            raise ScriptError(f"{name}() is per atom: only atom-style variables read it")
        member = np.ones(sim.nlocal, dtype=bool)
        if name in ("gmask", "grmask"):
            member &= sim.groups.select(sim, sim.require_group(words[0]))
        if name in ("rmask", "grmask"):
            region_id = words[-1]
            if region_id not in sim.system.regions:
                raise ScriptError(f"{name}(): region {region_id} is not defined")
            member &= sim.system.regions[region_id].match(sim.x)
        return member.astype(np.float64)
