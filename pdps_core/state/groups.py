"""Groups of particles as bits of the per-particle ``mask``: bit 0 is ``all``, 31 more can be defined.

Two kinds, as the two manuals define groups:

- PDPS's ``group ID region RID`` and ``group ID type T1 [T2 ...]`` (``i*j`` ranges allowed), read as
  PDPS, are definitions: membership is evaluated again before every run, so a region group holds
  the particles inside the region when the run starts (PDPS manual, group).
- Every group a LAMMPS script makes, and LAMMPS's other styles in either dialect (id, variable,
  subtract, union, intersect, empty, clear), are static: the particles that match when the command
  runs join the group (which keeps the ones it had, as in LAMMPS) and stay in it; particles made
  later join only ``all``.
"""

import numpy as np

from ..errors import ScriptError

MAX_GROUPS = 32


class Groups:
    def __init__(self):
        self.bits = {"all": 0}
        self.definitions = {"all": ("all",)}

    def __contains__(self, name):
        return name in self.bits

    def names(self):
        return list(self.bits)

    def define(self, sim, name, definition):
        if name == "all":
            if definition not in ((), ("all",)):
                raise ScriptError("group all is predefined and cannot be redefined")
            return
        if definition[0] == "delete":
            if name not in self.bits:
                raise ScriptError(f"group {name} is not defined")
            sim.particles.mask[:] &= ~np.uint32(1 << self.bits.pop(name))
            del self.definitions[name]
            return
        if name not in self.bits:
            free = sorted(set(range(MAX_GROUPS)) - set(self.bits.values()))
            if not free:
                raise ScriptError(f"too many groups: at most {MAX_GROUPS - 1} besides all (got {name})")
            self.bits[name] = free[0]
        self.definitions[name] = definition
        self._evaluate(sim, name)

    def assign(self, sim, name, member, replace=False):
        """A static group: the owned particles in ``member`` join ``name`` (made if new; emptied
        first with ``replace``)."""
        if name == "all":
            raise ScriptError("group all is predefined and cannot be redefined")
        if name not in self.bits:
            free = sorted(set(range(MAX_GROUPS)) - set(self.bits.values()))
            if not free:
                raise ScriptError(f"too many groups: at most {MAX_GROUPS - 1} besides all (got {name})")
            self.bits[name] = free[0]
        self.definitions[name] = ("static",)
        bit = np.uint32(1 << self.bits[name])
        mask = sim.particles.mask[:sim.particles.nlocal]
        if replace:
            mask[:] &= ~bit
        mask[member] |= bit

    def _evaluate(self, sim, name):
        p = sim.particles
        kind, args = self.definitions[name][0], self.definitions[name][1:]
        n = p.nlocal
        if kind == "static":
            return
        if kind == "all":
            member = np.ones(n, dtype=bool)
        elif kind == "region":
            member = sim.region(args[0]).match(p.x[:n])
        elif kind == "type":
            member = np.zeros(n, dtype=bool)
            for lo, hi in args:
                member |= (p.type[:n] >= lo) & (p.type[:n] <= hi)
        else:
            raise ScriptError(f"unknown group style {kind}")
        bit = np.uint32(1 << self.bits[name])
        mask = p.mask[:n]
        mask[:] = np.where(member, mask | bit, mask & ~bit)

    def update(self, sim):
        for name in self.bits:
            self._evaluate(sim, name)

    def bit(self, name):
        try:
            return np.uint32(1 << self.bits[name])
        except KeyError:
            raise ScriptError(f"group {name} is not defined (defined: {', '.join(self.bits)})") from None

    def select(self, sim, name):
        """Boolean mask over owned particles."""
        p = sim.particles
        bit = self.bit(name)
        if name == "all":
            return np.ones(p.nlocal, dtype=bool)
        return (p.mask[: p.nlocal] & bit) != 0
