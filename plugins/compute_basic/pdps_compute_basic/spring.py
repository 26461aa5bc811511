r"""Fix ``spring``: a spring on the centre of mass of a group, tethered to a point (``tether``) or
coupled to the centre of mass of a second group (``couple``) (LAMMPS's and LIGGGHTS's fix spring).

With :math:`\mathbf{x}_{cm}` the group's centre of mass in unwrapped positions (image flags
counted, so a group may straddle a periodic face), the spring's extension is

.. math::

    \mathbf{d} = \mathbf{x}_{cm} - (x, y, z) \quad\text{(tether)}, \qquad
    \mathbf{d} = \mathbf{x}_{cm,2} - \mathbf{x}_{cm} - (x, y, z) \quad\text{(couple)},

with the components whose coordinate is ``NULL`` set to 0 (that dimension is neither measured nor
pulled), :math:`r = \max(|\mathbf{d}|, 10^{-10})`, :math:`\delta = r - R_0` and the spring force
:math:`\mathbf{F} = K \delta\, \mathbf{d} / r`. Each particle i of the group gets its share by
mass, :math:`\mathbf{f}_i = -\mathbf{F}\, m_i / M` for the tether; for the couple the group gets
:math:`+\mathbf{F}\, m_i / M` and each particle j of group2 :math:`-\mathbf{F}\, m_j / M_2`, pulling the
two centres towards a displacement (x, y, z) of group2 from the group at distance R0 from it.
K in force/distance (it is the spring of the whole group, not of each particle; neither program
refuses K < 0, nor does pdps), x y z and R0 in distance (R0 >= 0). The energy is
:math:`E = \tfrac12 K \delta^2`; LAMMPS's manual writes :math:`\tfrac12 K r^2`, but both programs
compute :math:`\delta^2`, as pdps does.

Output: ``f_ID`` is E; ``f_ID[1-4]`` (LAMMPS's and LIGGGHTS's index base) are the total force the
spring puts on the group (tether: :math:`-\mathbf{F}`; couple: :math:`+\mathbf{F}`, the negative of
that on group2) and its magnitude :math:`|\mathbf{F}|`, negative when :math:`\delta < 0` (the spring
pushes). Both extensive. ``fix_modify ID energy yes`` adds E to thermo ``pe``; the fix adds no
virial (as LAMMPS's). Applied in ``post_force``, at a run's setup and in each minimization step.

The total masses M and M2 are taken when a run (or minimize) starts, at its first force
evaluation, and kept through it, as LIGGGHTS 3.8.0 (its init) and LAMMPS for a static group do: the
centre of mass is the sum of :math:`m_i \mathbf{x}^u_i` over that mass (a particle inserted into
the group during the run counts in the sum, not in M, as in both programs). An empty group has its
centre at the origin and pulls nothing (LAMMPS guards the division by M; LIGGGHTS 3.8.0 divides by
0 but has no particle to apply it to: the same numbers). LAMMPS's current fix spring also
recomputes M every step for a dynamic group, which pdps has none of (a PDPS-dialect region group is
evaluated again before each run, and M with it); otherwise its program is LIGGGHTS 3.8.0's. In 2-d
the z coordinate must be NULL or 0 (a z force would move particles out of the plane).

Syntax::

    fix ID GROUP spring tether K X|NULL Y|NULL Z|NULL R0
    fix ID GROUP spring couple GROUP2 K X|NULL Y|NULL Z|NULL R0

Examples::

    fix pull ligand spring tether 50.0 NULL NULL 2.0 3.0
    fix hold bilayer1 spring couple bilayer2 100.0 NULL NULL 10.0 0.0
"""

import math
from typing import Annotated, Literal

import numpy as np
from numba import njit
from pydantic import Field, model_validator

from pdps_core.api import Fix, ScriptError, StyleArgs, param

SMALL = 1.0e-10
NO_RMASS = np.zeros(0)

Coordinate = float | Literal["NULL"]


# the values after each word, as the manual names them
VALUES = {"tether": ("K", "X", "Y", "Z", "R0"), "couple": ("GROUP2", "K", "X", "Y", "Z", "R0")}
Length = Annotated[float, Field(ge=0)]
Tether = tuple[Literal["tether"], float, Coordinate, Coordinate, Coordinate, Length]
Couple = tuple[Literal["couple"], str, float, Coordinate, Coordinate, Coordinate, Length]


@njit(cache=True)
def group_moments(x, image, length, type_, mass, rmass, mask, bit1, bit2, nlocal, out):
    """out[0], out[1:4] = sum of m and of m x^u (unwrapped) over the owned particles of group 1;
    out[4], out[5:8] the same over group 2 (bit2 = 0: none). No temporaries."""
    out[:] = 0.0
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        in1 = (mask[i] & bit1) != 0
        in2 = (mask[i] & bit2) != 0
        if not (in1 or in2):
            continue
        m = rmass[i] if with_rmass else mass[type_[i]]
        for d in range(3):
            xu = x[i, d] + image[i, d] * length[d]
            if in1:
                out[1 + d] += m * xu
            if in2:
                out[5 + d] += m * xu
        if in1:
            out[0] += m
        if in2:
            out[4] += m


@njit(cache=True)
def add_pull(f, type_, mass, rmass, mask, bit1, bit2, nlocal, a1, a2):
    """f_i += m_i a1 on group 1 and f_j -= m_j a2 on group 2 (owned particles)."""
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        in1 = (mask[i] & bit1) != 0
        in2 = (mask[i] & bit2) != 0
        if not (in1 or in2):
            continue
        m = rmass[i] if with_rmass else mass[type_[i]]
        for d in range(3):
            if in1:
                f[i, d] += a1[d] * m
            if in2:
                f[i, d] -= a2[d] * m


class FixSpring(Fix):
    name = "spring"
    usage = ("fix ID GROUP spring tether K X|NULL Y|NULL Z|NULL R0 | "
             "couple GROUP2 K X|NULL Y|NULL Z|NULL R0")
    can_energy = True
    extensive = True

    class Args(StyleArgs):
        spring: Tether | Couple = param(
            unit={"tether": ("force/distance", "distance", "distance", "distance", "distance"),
                  "couple": ("1", "force/distance", "distance", "distance", "distance", "distance")})

        @model_validator(mode="before")
        @classmethod
        def _each_value_by_its_name(cls, data):
            """A bad number is named as the manual names it (R0, Y), not by its place in the tuple."""
            words = data.get("spring") if isinstance(data, dict) else None
            if not (isinstance(words, (tuple, list)) and words and words[0] in VALUES):
                return data
            for name, word in zip(VALUES[words[0]], words[1:]):
                if name == "GROUP2" or (name in ("X", "Y", "Z") and word == "NULL"):
                    continue
                try:
                    value = float(word)
                except (TypeError, ValueError):
                    value = math.nan
                if not math.isfinite(value):
                    null = " or NULL" if name in ("X", "Y", "Z") else ""
                    raise ValueError(f"spring {words[0]}: {name} must be a finite number{null} (got {word})")
                if name == "R0" and value < 0.0:
                    raise ValueError(f"spring {words[0]}: R0 must be >= 0 (got {word})")
            return data

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        style, *values = args.spring
        self.couple = style == "couple"
        self.group2 = values.pop(0) if self.couple else None
        k, *centre, r0 = values
        if self.couple:
            if self.group2 == group:
                raise ScriptError(f"spring couple: GROUP2 must differ from the fix group (got {group} twice)")
            self._bits(sim)
        self.kept = np.array([c != "NULL" for c in centre], dtype=np.float64)
        self.centre = np.array([0.0 if c == "NULL" else float(c) for c in centre], dtype=np.float64)
        if sim.dimension == 2 and centre[2] != "NULL" and centre[2] != 0.0:
            raise ScriptError(f"spring {style}: z must be NULL or 0 in a 2-d simulation (got {centre[2]:g}): "
                              "a z force would move particles out of the plane")
        self.k, self.r0 = float(k), float(r0)
        self.moments = np.zeros(8)
        self.totals = None          # (M, M2) of the run: taken at its first force evaluation
        self.a1 = np.zeros(3)
        self.a2 = np.zeros(3)
        self.espring = 0.0
        self.ftotal = np.zeros(4)

    def _bits(self, sim):
        bit1 = sim.groups.bit(self.group)
        if not self.couple:
            return bit1, np.uint32(0)
        try:
            # checked again at each run, as LAMMPS's init: the group may have been deleted
            return bit1, sim.groups.bit(self.group2)
        except ScriptError as error:
            raise ScriptError(f"spring couple: GROUP2: {error}") from None

    def _sums(self, sim):
        """This rank's moments of both groups, summed over every rank."""
        p = sim.particles
        bit1, bit2 = self._bits(sim)
        group_moments(p.x, p.image, np.asarray(sim.box.length, dtype=np.float64), p.type, sim.mass,
                      p.rmass if p.has("rmass") else NO_RMASS, p.mask, bit1, bit2, p.nlocal, self.moments)
        return np.asarray(sim.comm.sum(self.moments), dtype=np.float64)

    def init_run(self, sim):
        """A run starts: its first force evaluation (setup, or a minimization's first) takes the
        groups' total masses, after the run has evaluated its groups."""
        self.totals = None

    def post_force(self, sim):
        sums = self._sums(sim)
        if self.totals is None:
            # kept through the run, as LIGGGHTS's and LAMMPS's init take them
            self.totals = (float(sums[0]), float(sums[4]))
        mass1, mass2 = self.totals
        xcm = sums[1:4] / mass1 if mass1 > 0.0 else sums[1:4]
        if self.couple:
            xcm2 = sums[5:8] / mass2 if mass2 > 0.0 else sums[5:8]
            d = (xcm2 - xcm - self.centre) * self.kept
        else:
            d = (xcm - self.centre) * self.kept
        r = max(math.sqrt(float(d @ d)), SMALL)
        dr = r - self.r0
        force = self.k * d * dr / r
        self.ftotal[:3] = force if self.couple else -force
        self.ftotal[3] = math.sqrt(float(force @ force)) * (-1.0 if dr < 0.0 else 1.0)
        self.espring = 0.5 * self.k * dr * dr
        if self.couple:
            # the group is pulled along +F, group2 against it
            self.a1[:] = force / mass1 if mass1 > 0.0 else 0.0
            self.a2[:] = force / mass2 if mass2 > 0.0 else 0.0
        else:
            self.a1[:] = -force / mass1 if mass1 > 0.0 else 0.0
        p = sim.particles
        bit1, bit2 = self._bits(sim)
        add_pull(p.f, p.type, sim.mass, p.rmass if p.has("rmass") else NO_RMASS, p.mask, bit1, bit2,
                 p.nlocal, self.a1, self.a2)

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def compute_energy(self, sim):
        """E on the first rank (the energy is global: every rank knows it)."""
        return self.espring if sim.comm.is_root else 0.0

    def scalar(self, sim):
        """``f_ID``: the spring's energy 0.5 K (r - R0)^2 at the last step it acted."""
        return self.espring

    def vector(self, sim):
        """``f_ID[1-4]``: the spring's total force on the group (x, y, z) and its signed magnitude."""
        return self.ftotal.copy()
