"""Thermo output: ``thermo N``, ``thermo_style [custom|one] keyword...`` and ``thermo_modify``.

Keywords, as LAMMPS's thermo_style names them: step, elapsed, elaplong, dt, time, cpu, tpcpu, spcpu,
cpuremain, atoms, temp, press, pe, ke, etotal, enthalpy, evdwl, ecoul, epair, ebond, eangle, edihed,
eimp, emol, elong, etail, ecouple, econserve, vol, density, lx, ly, lz, xlo, xhi, ylo, yhi, zlo, zhi,
xy, xz, yz, fmax, fnorm, nbuild, ndanger, bonds (angles, dihedrals, impropers: 0), ``c_ID``, ``c_ID[i]``,
``c_ID[i][j]``, ``f_ID...``,
``v_NAME`` and ``v_NAME[i]`` (indices from 0 in the PDPS dialect, from 1 in LAMMPS's). Energies are
per particle in lj units (``thermo_modify norm yes``, LAMMPS's default there) and totals otherwise.
Energies of interactions pdps has no style for (Coulomb, angles, k-space) read 0, as in LAMMPS
without them. A line is written at the start of a run, every N steps, and at the last step
(``thermo 0``: first and last only), as the PDPS manual describes.

``thermo_modify norm yes|no``, ``format line|int|float FORMAT``, ``format N FORMAT`` (C formats,
``format none`` resets), ``flush yes|no``, ``temp ID``, ``press ID`` and ``lost error|warn|ignore``
(error, the default: a particle leaving through a fixed face stops the run, as the PDPS manual and
LAMMPS say; warn and ignore delete it, warn saying so at the next thermo line, as LAMMPS).
"""

import re
import time

import numpy as np

from ..errors import ScriptError
from ..state import observables as obs

HEADERS = {"step": "Step", "elapsed": "Elapsed", "elaplong": "Elaplong", "dt": "Dt", "time": "Time",
           "cpu": "CPU", "tpcpu": "T/CPU", "spcpu": "S/CPU", "cpuremain": "CPULeft", "atoms": "Atoms",
           "temp": "Temp", "press": "Press", "pe": "PotEng", "ke": "KinEng", "etotal": "TotEng",
           "enthalpy": "Enthalpy", "evdwl": "E_vdwl", "ecoul": "E_coul", "epair": "E_pair",
           "ebond": "E_bond", "eangle": "E_angle", "edihed": "E_dihed", "eimp": "E_impro",
           "emol": "E_mol", "elong": "E_long", "etail": "E_tail", "ecouple": "Ecouple",
           "econserve": "Econserve", "vol": "Volume", "density": "Density", "lx": "Lx", "ly": "Ly",
           "lz": "Lz", "xlo": "Xlo", "xhi": "Xhi", "ylo": "Ylo", "yhi": "Yhi", "zlo": "Zlo", "zhi": "Zhi",
           "xy": "Xy", "xz": "Xz", "yz": "Yz", "fmax": "Fmax", "fnorm": "Fnorm", "nbuild": "Nbuild",
           "ndanger": "Ndanger", "bonds": "Bonds", "angles": "Angles", "dihedrals": "Diheds",
           "impropers": "Impros", "pxx": "Pxx", "pyy": "Pyy", "pzz": "Pzz", "pxy": "Pxy", "pxz": "Pxz",
           "pyz": "Pyz", "xlat": "Xlat", "ylat": "Ylat", "zlat": "Zlat"}
# LAMMPS's thermo_style one, its default (and LIGGGHTS's)
ONE = ("step", "temp", "epair", "emol", "etotal", "press")
PRESSURE_TENSOR = ("pxx", "pyy", "pzz", "pxy", "pxz", "pyz")
INTEGER = {"step", "elapsed", "elaplong", "atoms", "nbuild", "ndanger", "bonds", "angles", "dihedrals", "impropers"}
ENERGY = {"pe", "etotal", "enthalpy", "evdwl", "epair", "econserve", "ebond", "emol"}
NEEDS = {**{name: {"energy"} for name in ENERGY}, "press": {"virial"}, "enthalpy": {"energy", "virial"},
         **{name: {"virial"} for name in PRESSURE_TENSOR}}
ABSENT = {"ecoul", "eangle", "edihed", "eimp", "elong", "xy", "xz", "yz"}
REFERENCE = re.compile(r"^(c|v|f)_([A-Za-z0-9_]+)((\[\d+\])*)$")
BOUNDS = {"xlo": (0, 0), "xhi": (1, 0), "ylo": (0, 1), "yhi": (1, 1), "zlo": (0, 2), "zhi": (1, 2)}


def keyword_value(sim, name, indices=()):
    """A thermo keyword or reference (c_ID[i], v_NAME) as a number: also what variables read."""
    if name == "step":
        return sim.step
    if name == "elapsed":
        return sim.step - sim.run_first_step
    if name == "elaplong":
        return sim.step - sim.run_state.ramp_bounds[0]
    if name == "dt":
        return sim.dt
    if name == "time":
        return sim.time
    if name in ("cpu", "tpcpu", "spcpu", "cpuremain"):
        return sim.output.thermo.clock(name)
    if name in ABSENT:
        return 0.0
    if name == "etail":
        sim.require_box("thermo keyword etail")
        return obs.tail_corrections(sim)[0] / _normalise(sim)
    if name == "ecouple":
        return _ecouple(sim) / _normalise(sim)
    if name in HEADERS:
        # the rest describe particles in a box; a variable may read them before one exists
        sim.require_box(f"thermo keyword {name}")
    if name == "atoms":
        return obs.count(sim)
    if name == "bonds":
        p = sim.particles
        return int(sim.comm.sum(int(p.num_bond[:p.nlocal].sum()))) if p.has("num_bond") else 0
    if name in ("angles", "dihedrals", "impropers"):
        return 0
    if name == "temp":
        return sim.output.thermo.temperature()
    if name == "press":
        return sim.output.thermo.pressure()
    if name in PRESSURE_TENSOR:
        # LAMMPS's: the thermo temperature group's kinetic tensor (all, or thermo_modify temp's)
        return float(obs.pressure_tensor(sim, sim.output.thermo.temp_group())[PRESSURE_TENSOR.index(name)])
    if name == "epair":
        # the pair style's energy alone, as LAMMPS's (pe adds the fixes' of fix_modify energy yes)
        return obs.pair_energy(sim) / _normalise(sim)
    if name == "ke" and sim.dialect.thermo_ke_sum:
        return obs.kinetic_energy_with_clumps(sim) / _normalise(sim)
    if name in ("pe", "econserve", "etotal", "enthalpy", "ke"):
        total = 0.0
        if name != "ke":
            total += obs.potential_energy(sim)
        if name in ("ke", "etotal", "econserve", "enthalpy"):
            # LAMMPS's thermo ke: from the temperature, 1/2 dof k_B T with the temperature compute's
            # degrees of freedom (its group's, after thermo_modify temp; 0 with none)
            thermo = sim.output.thermo
            if obs.clump_rows(sim) is not None:
                # LIGGGHTS's thermo ke with rigid clumps (fix multisphere): compute ke's sum, each
                # clump counted as one body
                total += obs.kinetic_energy_with_clumps(sim, thermo.temp_group())
            else:
                dof = obs.degrees_of_freedom(sim, extra=thermo.extra_dof) if thermo.temp_id is None else \
                    obs.compute_dof(sim, sim.computes[thermo.temp_id])
                total += 0.5 * dof * sim.units.boltz * thermo.temperature()
        if name == "enthalpy":
            total += sim.output.thermo.pressure() * sim.box.volume / sim.units.nktv2p
        if name == "econserve":
            total += _ecouple(sim)
        return total / _normalise(sim)
    if name in ("ebond", "emol"):
        return obs.bond_energy(sim) / _normalise(sim)
    if name == "evdwl":
        # with the pair style's tail correction, as LAMMPS's thermo evdwl
        return obs.pair_energy(sim) / _normalise(sim)
    if name == "vol":
        return sim.box.volume
    if name == "density":
        total_mass = sim.comm.sum(float(obs.masses(sim, np.ones(sim.nlocal, dtype=bool)).sum()))
        return total_mass / sim.box.volume * sim.units.mv2d
    if name in ("lx", "ly", "lz"):
        return float(sim.box.length["xyz".index(name[1])])
    if name in ("xlat", "ylat", "zlat"):
        # the lattice spacings; LAMMPS's lattice before any lattice command is "none 1.0"
        return 1.0 if sim.lattice is None else float(sim.lattice.spacing["xyz".index(name[0])])
    if name in BOUNDS:
        side, d = BOUNDS[name]
        return float((sim.box.lo, sim.box.hi)[side][d])
    if name in ("fmax", "fnorm"):
        f = sim.f
        if name == "fmax":
            return float(sim.comm.max(float(np.abs(f).max()) if len(f) else 0.0))
        return float(np.sqrt(sim.comm.sum(float((f * f).sum()))))
    if name in ("nbuild", "ndanger"):
        return sim.neighbor.builds if name == "nbuild" else sim.neighbor.dangerous
    if name.startswith("c_"):
        return sim.compute_value(name[2:], indices)
    if name.startswith("f_"):
        return sim.fix_value(name[2:], indices)
    raise ScriptError(f"unknown thermo keyword {name}")


def _ecouple(sim):
    """Energy thermostats and barostats exchanged with their reservoirs (LAMMPS's ecouple): the sum
    of ``ecouple(sim)`` of the fixes that define it (fix nvt, npt, nph)."""
    return float(sum(fix.ecouple(sim) for fix in sim.fixes.values() if callable(getattr(fix, "ecouple", None))))


def _normalise(sim):
    """Energies per particle (thermo_modify norm yes; LAMMPS's default in lj units only)."""
    norm = sim.output.thermo.norm
    if norm is None:
        norm = sim.units.name == "lj"
    return max(obs.count(sim), 1) if norm else 1


class _ThermoCompute:
    """One of the computes LAMMPS defines in every run for its thermo output, read as ``c_ID``
    wherever the script defines no compute of that ID (``variable t equal c_thermo_temp``)."""
    kind = "compute"
    group = "all"
    peratom = None
    needs_energy = needs_virial = extensive = gives_temperature = gives_pressure = array_rows_vary = False

    def __init__(self, ident):
        self.id = ident


class _ThermoTemp(_ThermoCompute):
    """thermo_temp: compute temp of group all (thermo_modify temp leaves it as it is, as LAMMPS)."""
    name = "temp"
    gives_temperature = True

    def scalar(self, sim):
        return obs.temperature(sim, extra=sim.output.thermo.extra_dof)

    def vector(self, sim):
        return obs.kinetic_tensor(sim)


class _ThermoPress(_ThermoCompute):
    """thermo_press: compute pressure with thermo's temperature (thermo_modify temp's, as LAMMPS's
    thermo_press follows it)."""
    name = "pressure"
    gives_pressure = True
    needs_virial = True

    def scalar(self, sim):
        thermo = sim.output.thermo
        if thermo.temp_id is None:
            return obs.pressure(sim, extra=thermo.extra_dof)
        return obs.pressure(sim, temp=thermo.temperature(), temp_group=thermo.temp_group())

    def vector(self, sim):
        return obs.pressure_tensor(sim, sim.output.thermo.temp_group())


class _ThermoPe(_ThermoCompute):
    """thermo_pe: compute pe, the total potential energy (extensive: thermo normalises it)."""
    name = "pe"
    needs_energy = extensive = True

    def scalar(self, sim):
        return obs.potential_energy(sim)


THERMO_COMPUTES = {ident: cls(ident) for ident, cls in (("thermo_temp", _ThermoTemp),
                                                        ("thermo_press", _ThermoPress),
                                                        ("thermo_pe", _ThermoPe))}


class Thermo:
    def __init__(self, sim):
        self.sim = sim
        self.every = 0
        # None until thermo_style: the dialect's default line; "one": LAMMPS's thermo_style one
        self.style = None
        self.columns = list(ONE)        # until a run's setup names the dialect's (validate)
        self.norm = None                # thermo_modify norm; None: LAMMPS's default for the units
        self.formats = {"line": None, "int": None, "float": None, "columns": {}}
        self.flush_each = False
        self.temp_id = self.press_id = None
        self.extra_dof = None           # compute_modify thermo_temp extra/dof N (None: the dimension)
        self.lost = None                # thermo_modify lost (None: the dialect's default): particles leaving fixed faces
        self.told_lost = False          # the dialect's ignore has said once that particles went
        self.counted = None             # the particle count at the last line (lost warn)
        self.last_clock = None          # (wall time, step, time) of the last line, for tpcpu/spcpu

    # ---- thermo_modify --------------------------------------------------------------------------
    def modify(self, words):
        usage = ("thermo_modify norm yes|no | format line|int|float|N FORMAT | format none | "
                 "flush yes|no | temp ID | press ID | lost error|warn|ignore")
        if not words:
            raise ScriptError(f"expected keywords; usage: {usage}")
        i = 0
        while i < len(words):
            key = words[i]
            value = words[i + 1] if i + 1 < len(words) else None
            if value is None:
                raise ScriptError(f"keyword {key} needs a value; usage: {usage}")
            if key in ("norm", "flush"):
                if value not in ("yes", "no"):
                    raise ScriptError(f"{key} must be yes or no (got {value})")
                if key == "norm":
                    self.norm = value == "yes"
                else:
                    self.flush_each = value == "yes"
            elif key == "format":
                if value == "none":
                    self.formats = {"line": None, "int": None, "float": None, "columns": {}}
                    i += 2
                    continue
                if i + 2 >= len(words):
                    raise ScriptError(f"format {value} needs a format string; usage: {usage}")
                self._set_format(value, words[i + 2])
                i += 3
                continue
            elif key in ("temp", "press"):
                if value not in self.sim.computes:
                    raise ScriptError(f"compute {value} is not defined (thermo_modify {key})")
                setattr(self, f"{key}_id", value)
            elif key == "lost":
                if value not in ("error", "warn", "ignore"):
                    raise ScriptError(f"lost must be error, warn or ignore (got {value})")
                self.lost = value
            elif key in ("lost/bond", "line", "every", "triclinic/general"):
                raise ScriptError(f"thermo_modify {key} is not supported (supported: norm, format, "
                                  "flush, temp, press, lost)")
            else:
                raise ScriptError(f"unknown thermo_modify keyword {key}; usage: {usage}")
            i += 2

    def _set_format(self, which, fmt):
        fmt = fmt.strip('"\'')
        try:
            fmt % (1,)
        except (TypeError, ValueError):
            raise ScriptError(f"format {which}: {fmt} is not a C format for one number") from None
        if which in ("line",):
            self.formats["line"] = fmt.split()
        elif which in ("int", "float"):
            self.formats[which] = fmt
        else:
            try:
                column = int(which)
            except ValueError:
                raise ScriptError(f"format must be line, int, float, none or a column number (got {which})") from None
            if not 1 <= column <= len(self.columns):
                raise ScriptError(f"format {column}: thermo has columns 1 to {len(self.columns)}")
            self.formats["columns"][column] = fmt

    # ---- what thermo computes with ----------------------------------------------------------------
    def temperature(self):
        if self.temp_id is not None:
            return float(self.sim.compute_value(self.temp_id))
        return obs.temperature(self.sim, extra=self.extra_dof)

    def temp_group(self):
        """The group of the thermo temperature (thermo_modify temp's compute, or all): pxx ... pyz
        take its kinetic tensor, sum m v_a v_b."""
        compute = self.sim.computes.get(self.temp_id) if self.temp_id is not None else None
        return getattr(compute, "group", "all") if compute is not None else "all"

    def pressure(self):
        if self.press_id is not None:
            return float(self.sim.compute_value(self.press_id))
        if self.temp_id is not None:
            # the kinetic part is the temperature compute's: its T and its group's degrees of freedom
            dof = obs.compute_dof(self.sim, self.sim.computes[self.temp_id])
            return obs.pressure(self.sim, temp=self.temperature(), dof=dof)
        return obs.pressure(self.sim, extra=self.extra_dof)

    def clock(self, name):
        """cpu (wall seconds of this run), tpcpu and spcpu (simulated time and steps per wall second
        since the last line), cpuremain (an estimate of the seconds left), as LAMMPS's."""
        sim = self.sim
        now = time.perf_counter()
        started = sim.run_state.run_wall_start
        if started is None:
            return 0.0
        if name == "cpu":
            return now - started
        if name == "cpuremain":
            done = sim.step - sim.run_first_step
            left = sim.run_last_step - sim.step
            return (now - started) * left / done if done > 0 else 0.0
        if self.last_clock is None:
            return 0.0
        wall, step, at = self.last_clock
        if now <= wall:
            return 0.0
        return ((sim.time - at) if name == "tpcpu" else (sim.step - step)) / (now - wall)

    def set_style(self, words):
        self.style = "custom"
        if words and words[0] == "custom":
            words = words[1:]
        elif words and words[0] == "one":
            self.style, words = "one", list(ONE)
        if not words:
            raise ScriptError("thermo_style needs at least one keyword")
        for word in words:
            self._parse(word)
        self.columns = list(words)

    def _parse(self, word):
        if word in HEADERS:
            return word, ()
        match = REFERENCE.match(word)
        if not match:
            import difflib
            close = difflib.get_close_matches(word, HEADERS, n=1)
            hint = f"did you mean {close[0]}? " if close else ""
            raise ScriptError(f"unknown thermo keyword {word} ({hint}keywords: step, temp, press, pe, ke, "
                              "etotal and the rest of LAMMPS's thermo_style list; c_ID, f_ID, v_NAME)")
        indices = tuple(int(i) for i in re.findall(r"\[(\d+)\]", match.group(3)))
        return word, indices

    def needs(self):
        """'energy'/'virial' as the columns read them (computes declare theirs)."""
        sim, needs = self.sim, set()
        for word in self.columns:
            if word in NEEDS:
                needs |= NEEDS[word]
            elif word.startswith("c_"):
                needs |= sim.compute_needs(self._reference(word)[0])
            elif word.startswith("v_"):
                needs |= {"energy", "virial"}
        return needs

    @staticmethod
    def _reference(word):
        match = REFERENCE.match(word)
        indices = tuple(int(i) for i in re.findall(r"\[(\d+)\]", match.group(3)))
        return match.group(2), indices

    def validate(self):
        """Called at run setup: every compute and variable a column names must exist; LAMMPS's
        line (the default of the LAMMPS and LIGGGHTS dialects, and thermo_style one) gains Volume
        where the box changes in the run, a shrink-wrapped face or a fix's (its Thermo::init)."""
        sim = self.sim
        if self.style is None:
            self.columns = list(sim.dialect.thermo_default)
        if self.style == "one" or (self.style is None and self.columns == list(ONE)):
            changes = bool(sim.system.shrink_faces) or any(fix.changes_box for fix in sim.fixes.values())
            self.columns = list(ONE) + (["vol"] if changes else [])
        for word in self.columns:
            if word.startswith("c_"):
                ident, _ = self._reference(word)
                if self.sim.styles.find_compute(ident) is None:
                    raise ScriptError(f"thermo_style: compute {ident} is not defined (thermo keyword {word})")
            elif word.startswith("f_"):
                ident, _ = self._reference(word)
                if ident not in self.sim.fixes and ident not in self.sim.analyzes:
                    raise ScriptError(f"thermo_style: fix {ident} is not defined (thermo keyword {word})")
            elif word.startswith("v_"):
                ident, _ = self._reference(word)
                if ident not in self.sim.variables:
                    raise ScriptError(f"thermo_style: variable {ident} is not defined (thermo keyword {word})")

    def due(self, step, first, last):
        if step == first or step == last:
            return True
        return self.every > 0 and step % self.every == 0

    def names(self):
        """Column names as the header shows them (``Step``, ``Temp``, ``c_1[0]``, ...)."""
        return [HEADERS.get(word, word) for word in self.columns]

    def integer(self):
        """Which columns are integers (step, elapsed, atoms)."""
        return [word in INTEGER for word in self.columns]

    def header(self):
        cells = []
        for word, name in zip(self.columns, self.names()):
            cells.append(f"{name:>10}" if word in INTEGER else f"{name:>14}")
        return " ".join(cells)

    def lost_policy(self):
        """error, warn or ignore: thermo_modify lost, or the dialect's default."""
        return self.lost or self.sim.dialect.lost_default

    def values(self):
        if self.lost == "warn" or (self.lost is None and not self.told_lost and self.lost_policy() == "ignore"):
            count = obs.count(self.sim)
            if self.counted is not None and count < self.counted:
                if self.lost == "warn":
                    self.sim.warn(f"Lost atoms: original {self.counted} current {count}")
                else:
                    self.told_lost = True
                    self.sim.warn(f"{self.counted - count} particle(s) lost through fixed boundaries by step "
                                  f"{self.sim.step} and dropped, as LIGGGHTS does by default (thermo_modify "
                                  "lost ignore); thermo_modify lost error stops the run instead")
            self.counted = count
        out = self._values()
        self.last_clock = (time.perf_counter(), self.sim.step, self.sim.time)
        return out

    def _values(self):
        out = []
        for word in self.columns:
            if word.startswith("v_"):
                ident, indices = self._reference(word)
                out.append(self.sim.variables.read(ident, indices, index_base=self.sim.dialect.index_base))
            elif word.startswith("c_") or word.startswith("f_"):
                ident, indices = self._reference(word)
                read = self.sim.compute_value if word[0] == "c" else self.sim.fix_value
                value = read(ident, indices)
                style = self.sim.styles.find_compute(ident) if word[0] == "c" else self.sim.fixes.get(ident)
                extensive = getattr(style, "extensive", False)
                if len(indices) == 1:
                    extensive = getattr(style, "extensive_vector", extensive)
                elif len(indices) == 2:
                    extensive = getattr(style, "extensive_array", extensive)
                if extensive:
                    value /= _normalise(self.sim)
                out.append(value)
            else:
                out.append(keyword_value(self.sim, word))
        return out

    def line(self, values=None):
        """The thermo line for ``values`` (read now when not given)."""
        values = self.values() if values is None else values
        cells = []
        line = self.formats["line"]
        for k, (word, value) in enumerate(zip(self.columns, values)):
            fmt = self.formats["columns"].get(k + 1)
            if fmt is None and line is not None and k < len(line):
                fmt = line[k]
            if fmt is None:
                fmt = self.formats["int" if word in INTEGER else "float"]
            if fmt is not None:
                cells.append(fmt % (int(value) if word in INTEGER and "d" in fmt else value))
            else:
                cells.append(f"{int(value):>10d}" if word in INTEGER else f"{value:>14.8g}")
        return " ".join(cells)
