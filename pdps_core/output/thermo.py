"""Thermo output: ``thermo N`` and ``thermo_style [custom] keyword...``.

Keywords: step, elapsed, dt, time, atoms, temp, press, pe (also epair), ke, etotal, vol, lx, ly, lz,
``c_ID``, ``c_ID[i]``, ``c_ID[i][j]`` and ``v_NAME``. A line is written at the start of a run, every N
steps, and at the last step (``thermo 0``: first and last only), as the PDPS manual describes.
"""

import re

from ..errors import ScriptError
from ..state import observables as obs

HEADERS = {"step": "Step", "elapsed": "Elapsed", "dt": "Dt", "time": "Time", "atoms": "Atoms",
           "temp": "Temp", "press": "Press", "pe": "PotEng", "epair": "E_pair", "ke": "KinEng",
           "etotal": "TotEng", "vol": "Volume", "lx": "Lx", "ly": "Ly", "lz": "Lz"}
INTEGER = {"step", "elapsed", "atoms"}
NEEDS = {"press": {"virial"}, "pe": {"energy"}, "epair": {"energy"}, "etotal": {"energy"}}
REFERENCE = re.compile(r"^(c|v|f)_([A-Za-z0-9_]+)((\[\d+\])*)$")


def keyword_value(sim, name, indices=()):
    """A thermo keyword or reference (c_ID[i], v_NAME) as a number: also what variables read."""
    if name == "step":
        return sim.step
    if name == "elapsed":
        return sim.step - sim.run_first_step
    if name == "dt":
        return sim.dt
    if name == "time":
        return sim.time
    if name in HEADERS:
        # the rest describe particles in a box; a variable may read them before one exists
        sim.require_box(f"thermo keyword {name}")
    if name == "atoms":
        return obs.count(sim)
    if name == "temp":
        return obs.temperature(sim)
    if name == "press":
        return obs.pressure(sim)
    if name in ("pe", "epair"):
        return obs.potential_energy(sim) / _normalise(sim)
    if name == "ke":
        return obs.kinetic_energy(sim) / _normalise(sim)
    if name == "etotal":
        return (obs.potential_energy(sim) + obs.kinetic_energy(sim)) / _normalise(sim)
    if name == "vol":
        return sim.box.volume
    if name in ("lx", "ly", "lz"):
        return float(sim.box.length["xyz".index(name[1])])
    if name.startswith("c_"):
        return sim.compute_value(name[2:], indices)
    if name.startswith("f_"):
        return sim.fix_value(name[2:], indices)
    raise ScriptError(f"unknown thermo keyword {name}")


def _normalise(sim):
    """LAMMPS lj units report energies per particle (thermo_modify norm yes)."""
    if sim.units.name == "lj":
        return max(obs.count(sim), 1)
    return 1


class Thermo:
    def __init__(self, sim):
        self.sim = sim
        self.every = 0
        self.columns = ["step", "temp", "pe", "ke", "etotal", "press"]

    def set_style(self, words):
        if words and words[0] == "custom":
            words = words[1:]
        elif words and words[0] == "one":
            words = ["step", "temp", "epair", "etotal", "press"]
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
            raise ScriptError(f"unknown thermo keyword {word} (known: {', '.join(HEADERS)}, c_ID, v_NAME)")
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
        """Called at run setup: every compute and variable a column names must exist."""
        for word in self.columns:
            if word.startswith("c_"):
                ident, _ = self._reference(word)
                if ident not in self.sim.computes:
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

    def values(self):
        out = []
        for word in self.columns:
            if word.startswith("v_"):
                out.append(self.sim.variables.value(self._reference(word)[0]))
            elif word.startswith("c_") or word.startswith("f_"):
                ident, indices = self._reference(word)
                read = self.sim.compute_value if word[0] == "c" else self.sim.fix_value
                out.append(read(ident, indices))
            else:
                out.append(keyword_value(self.sim, word))
        return out

    def line(self, values=None):
        """The thermo line for ``values`` (read now when not given)."""
        values = self.values() if values is None else values
        cells = []
        for word, value in zip(self.columns, values):
            cells.append(f"{int(value):>10d}" if word in INTEGER else f"{value:>14.8g}")
        return " ".join(cells)
