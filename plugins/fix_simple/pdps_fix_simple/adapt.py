r"""Fix ``adapt``: particle diameters (or charges), or pair coefficients, set from a variable during a
run, every N steps (LAMMPS's and LIGGGHTS's fix adapt).

Syntax::

    fix ID GROUP adapt N atom diameter|charge v_NAME [atom ... v_NAME ...] [scale yes|no] [reset yes|no]
        [mass yes|no]
    fix ID GROUP adapt N pair PSTYLE PARAM I J v_NAME [pair ...] [scale yes|no] [reset yes|no]

At the start of every run (LAMMPS's setup_pre_force) and then on every step that is a multiple of
N (none with N = 0), before the forces, each particle of the group takes the variable's value:

- ``atom diameter v_NAME``: its radius becomes :math:`r = d/2`, d the value (distance units); its
  mass follows at constant density, :math:`m' = \tfrac43\pi r'^3 \rho` with
  :math:`\rho = m / \tfrac43\pi r^3` (LAMMPS's ``mass no`` keeps the mass; LAMMPS's
  ``diameter/disc``, in 2-d, uses the disc's :math:`\pi r^2`);
- ``atom charge v_NAME``: its charge becomes the value (charge units).

The dialect decides the rest (docs/liggghts.md, docs/lammps.md; both measured on this machine with
LIGGGHTS 3.8.0 and LAMMPS 22 Jul 2025, plugins/fix_simple/tests/test_adapt.py):

- LAMMPS: the variable is equal-style; ``scale yes`` multiplies the radius the run began with by the
  value; ``reset yes`` gives the group back, after each run, the radii (and charges) they had when
  the fix was made, masses following; defaults ``scale no reset no mass yes``.
- LIGGGHTS: the variable is equal- or atom-style (one value per particle, as the packing
  tutorial's ``v_dgrown`` = growth factor x ``2*c_rad``); ``scale yes`` multiplies the current
  diameter by the value at every adaptation (LIGGGHTS's compounding); ``reset`` changes no particle;
  no ``mass`` keyword. ``scale yes`` with an equal-style variable is refused: LIGGGHTS 3.8.0 then
  multiplies each particle's value into the next particle's (fix_adapt.cpp), so its numbers depend
  on the particle order.

``pair PSTYLE PARAM I J v_NAME`` (LAMMPS's dialect): the coefficient PARAM (the name LAMMPS's
style gives it: ``a`` of soft, ``epsilon`` and ``sigma`` of lj/cut; ``pdps doc pair STYLE``) of the
type pairs I J (``*``, ``2*``, ... ranges, i <= j) of pair style PSTYLE (the pair style, or a
sub-style of hybrid) takes the equal-style variable's value, or with ``scale yes`` that value times
the coefficient the run began with; a pair whose coefficients were mixed is mixed afresh from its
adapted i i and j j, as LAMMPS's Pair::reinit; with ``reset no`` (the default) the values of the
run's end stay for the next run, with ``reset yes`` the pair_coeff values come back. A change of a
cutoff in a run is an error (the neighbor lists were built for the run's cutoffs).

Radii that change in a run: the neighbor lists count radius growth as a move and the granular
pair's cutoffs grow with the radii (the core's rule for ``Fix.varies_radius``); ghosts take the new
radii and masses at once. An adaptation growing a radius by more than half the neighbor skin in
one go is warned about: contacts can be missed until the next rebuild (as in both programs, which
change radii after the step's neighbor decision). ``kspace`` and ``bond`` settings are refused.

Examples (LIGGGHTS's packing tutorial; LAMMPS's micelle push-off)::

    compute rad all property/atom radius
    variable dgrown atom ${Rgrowrate}*2.*c_rad
    fix grow all adapt 40 atom diameter v_dgrown

    variable prefactor equal ramp(1.0,20.0)
    fix 3 all adapt 1 pair soft a * * v_prefactor
"""

import math
from typing import Literal

import numpy as np

from pdps_core.api import Fix, ScriptError, SimulationError, StyleArgs, Variable, keyword, param, type_range

FOUR_THIRDS_PI = 4.0 * math.pi / 3.0
Setting = (tuple[Literal["atom"], Literal["diameter", "diameter/disc", "charge"], Variable]
           | tuple[Literal["pair"], str, str, str, str, Variable]
           | tuple[Literal["bond"], str, str, str, Variable]
           | tuple[Literal["kspace"], Variable])


class FixAdapt(Fix):
    name = "adapt"
    usage = ("fix ID GROUP adapt N atom diameter|charge v_NAME [atom ...] [scale yes|no] [reset yes|no] "
             "[mass yes|no]")

    class Args(StyleArgs):
        every: int = param(ge=0, unit="timesteps")
        settings: list[Setting] = keyword(default_factory=list, spelled_by_entries=True, unit={
            "atom": "1", "pair": "1", "bond": "1", "kspace": "1"})
        scale: Literal["yes", "no"] = keyword("no")
        reset: Literal["yes", "no"] = keyword("no")
        mass: Literal["yes", "no"] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.rule = sim.dialect.adapt_rule
        if not args.settings:
            raise ScriptError("fix adapt needs an attribute to change: atom diameter v_NAME or atom charge v_NAME")
        for setting in args.settings:
            if setting[0] not in ("atom", "pair") or (setting[0] == "pair" and self.rule != "lammps"):
                raise ScriptError(f"fix adapt {setting[0]} (a {setting[0]} coefficient changed in time) is not in "
                                  f"pdps{' for ' + sim.dialect.label if setting[0] == 'pair' else ''}: set the "
                                  "coefficient between runs instead")
        self.attributes = [(setting[1], setting[2]) for setting in args.settings if setting[0] == "atom"]
        self.pair_settings = [self.pair_setting(sim, *setting[1:]) for setting in args.settings if setting[0] == "pair"]
        names = [attribute for attribute, _ in self.attributes]
        diameters = [a for a in names if a.startswith("diameter")]
        if diameters and "sphere" not in sim.particle_styles:
            raise ScriptError("fix adapt atom diameter needs per-particle radii and masses (atom_style sphere)")
        if "charge" in names and not sim.particles.has("q"):
            raise ScriptError("fix adapt atom charge needs charges (atom_style charge or full)")
        if self.rule == "liggghts":
            if "diameter/disc" in names:
                raise ScriptError("fix adapt atom diameter/disc is LAMMPS's; LIGGGHTS has atom diameter")
            if args.mass is not None:
                raise ScriptError("fix adapt mass is LAMMPS's keyword; LIGGGHTS always keeps the density")
        elif "diameter/disc" in names and sim.dimension != 2:
            raise ScriptError("fix adapt atom diameter/disc needs a 2-d simulation (as LAMMPS)")
        self.keep_density = args.mass != "no"
        self.varies_radius = bool(diameters)
        self.ghost_fields = ("radius", "rmass") if diameters else ()
        self.scale = args.scale == "yes"
        self.ratio = {}             # LAMMPS's scale: the value last applied, per attribute
        self.warned = False
        # LAMMPS's reset yes: each particle's value when the fix was made, carried with it
        self.originals = {}
        if args.reset == "yes" and self.rule == "lammps":
            p = sim.particles
            chosen = sim.groups.select(sim, group)
            for attribute in dict.fromkeys(names):
                column = "radius" if attribute.startswith("diameter") else "q"
                name = f"adapt_{id}_{column}"
                p.request(name, default=np.nan, ghost=False)
                p.arrays[name][:p.nlocal][chosen] = p.arrays[column][:p.nlocal][chosen]
                self.originals[attribute] = (column, name)

    def pair_setting(self, sim, style_name, param_name, itypes, jtypes, variable):
        """(style name, Coeff field, type pairs i <= j, variable) of one ``pair`` setting."""
        style = self.pair_style(sim, style_name)
        if param_name not in style.adaptable:
            known = ", ".join(style.adaptable) or "none"
            raise ScriptError(f"fix adapt pair {style_name}: {param_name} is not a coefficient fix adapt can change "
                              f"(it can: {known})")
        ntypes = sim.ntypes
        ilo, ihi = type_range(itypes, ntypes)
        jlo, jhi = type_range(jtypes, ntypes)
        pairs = [(i, j) for i in range(ilo, ihi + 1) for j in range(max(jlo, i), jhi + 1)]
        return style_name, style.adaptable[param_name], pairs, variable

    def pair_style(self, sim, name):
        pair = sim.pair
        if pair is None:
            raise ScriptError(f"fix adapt pair {name}: there is no pair style")
        if pair.name == name:
            style = pair
        else:
            style = getattr(pair, "substyles", {}).get(name)
        if style is None:
            raise ScriptError(f"fix adapt pair {name}: the pair style is {pair.name}, not {name}")
        return style

    def init_run(self, sim):
        self.began = {}     # (style, pair) -> {field: the run's first value} (scale yes)
        for style_name, field, pairs, variable in self.pair_settings:
            style = self.pair_style(sim, style_name)
            for pair in pairs:
                if pair not in style.resolved:
                    raise ScriptError(f"fix {self.id} (adapt): pair style {style_name} does not act on types "
                                      f"{pair[0]} {pair[1]}")
                self.began.setdefault((style_name, pair), {})[field] = getattr(style.resolved[pair], field)
        for _, _, _, variable in self.pair_settings:
            style = sim.variables.style(variable.name)
            if style not in ("equal", "internal"):
                raise ScriptError(f"fix {self.id} (adapt): variable {variable.name} is {style}-style; fix adapt pair "
                                  "takes equal-style variables")
        for attribute, variable in self.attributes:
            style = sim.variables.style(variable.name)
            allowed = ("equal", "internal", "atom") if self.rule == "liggghts" else ("equal", "internal")
            if style not in allowed:
                raise ScriptError(f"fix {self.id} (adapt): variable {variable.name} is {style}-style; fix adapt "
                                  f"takes {' or '.join(a for a in allowed if a != 'internal')}-style variables "
                                  f"({sim.dialect.label})")
            if self.rule == "liggghts" and self.scale and style != "atom":
                raise ScriptError(f"fix {self.id} (adapt): scale yes with equal-style variable {variable.name}: "
                                  "LIGGGHTS 3.8.0 multiplies each particle's value into the next one's, so its "
                                  "result depends on the particle order; use an atom-style variable (v x 2*c_rad)")
        self.ratio = {attribute: 1.0 for attribute, _ in self.attributes}

    def pre_force(self, sim):
        if sim.in_setup or (self.args.every and sim.step % self.args.every == 0):
            if self.attributes:
                self.change(sim)
            if self.pair_settings:
                self.change_pairs(sim)

    def change_pairs(self, sim):
        changes = {}
        for style_name, field, pairs, variable in self.pair_settings:
            value = float(sim.variables.value(variable.name))
            for pair in pairs:
                new = value * self.began[(style_name, pair)][field] if self.scale else value
                changes.setdefault(style_name, {}).setdefault(pair, {})[field] = new
        for style_name, style_changes in changes.items():
            self.pair_style(sim, style_name).adapt(style_changes)

    def change(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        fields = []
        for attribute, variable in self.attributes:
            value = self.value(sim, variable, chosen)
            if attribute == "charge":
                q = p.q[:n]
                if self.scale and self.rule == "lammps":
                    q[chosen] = value * q[chosen] / self.divisor(attribute, value)
                else:
                    q[chosen] = value
                fields.append("q")
                continue
            radius = p.radius[:n]
            old = radius[chosen]
            if self.scale and self.rule == "liggghts":
                new = 0.5 * (value * (2.0 * old))
            elif self.scale:
                new = value * old / self.divisor(attribute, value)
            else:
                new = 0.5 * np.broadcast_to(value, old.shape)
            self.check_radii(sim, new, chosen)
            self.set_radii(sim, chosen, new, attribute)
            grown = sim.comm.max(float(np.max(new - old, initial=0.0)))
            if grown > 0.5 * sim.neighbor.skin and not self.warned:
                self.warned = True
                sim.warn(f"fix {self.id} (adapt) grew a radius by {grown:.3g} at step {sim.step}, more than half the "
                         f"neighbor skin ({sim.neighbor.skin:g}): contacts may be missed until the next rebuild "
                         "(adapt more often, in smaller steps, or use a larger skin)")
            fields += ["radius", "rmass"]
        sim.comm.forward_comm(p, tuple(dict.fromkeys(fields)))

    def value(self, sim, variable, chosen):
        """The variable now: a number, or for an atom-style one the values of the chosen particles."""
        if sim.variables.style(variable.name) == "atom":
            return np.asarray(sim.variables.atom_values(variable.name), dtype=np.float64)[chosen]
        return float(sim.variables.value(variable.name))

    def divisor(self, attribute, value):
        """LAMMPS's scale yes: the value is a factor on the run's first radius (or charge), applied as
        value / the value before, which must not be 0."""
        before = self.ratio[attribute]
        if before == 0.0:
            raise SimulationError(f"fix {self.id} (adapt) with scale yes: the variable was 0 at the last "
                                  f"adaptation, so no later value can scale from it")
        self.ratio[attribute] = value
        return before

    def check_radii(self, sim, new, chosen):
        bad = ~(np.isfinite(new) & (new > 0.0))
        if sim.comm.max(int(bad.any())):
            p = sim.particles
            rows = np.flatnonzero(chosen)[bad]
            where = (f"particle {int(p.tag[rows[0]])} gets diameter {2.0 * float(new[bad][0]):g}"
                     if len(rows) else "a particle on another rank gets a diameter that is not > 0")
            raise SimulationError(f"fix {self.id} (adapt) at step {sim.step}: {where}; a diameter must be a "
                                  "finite number > 0")

    def set_radii(self, sim, chosen, new, attribute):
        """Radii, and masses at constant density unless ``mass no`` (LAMMPS's order of operations)."""
        p = sim.particles
        n = p.nlocal
        radius, rmass = p.radius[:n], p.rmass[:n]
        old = radius[chosen]
        if self.keep_density:
            if attribute == "diameter/disc":
                density = rmass[chosen] / (math.pi * old * old)
                rmass[chosen] = math.pi * new * new * density
            else:
                density = rmass[chosen] / (FOUR_THIRDS_PI * old * old * old)
                rmass[chosen] = FOUR_THIRDS_PI * new * new * new * density
        radius[chosen] = new

    def post_run(self, sim):
        """LAMMPS's reset yes: the values the particles had when the fix was made; reset no keeps the
        adapted pair coefficients for the runs that follow (they become the pair_coeff values)."""
        if self.pair_settings and self.args.reset != "yes":
            for style_name, field, pairs, _ in self.pair_settings:
                style = self.pair_style(sim, style_name)
                for pair in pairs:
                    if pair in style.coeffs:
                        style.coeffs[pair] = style.coeffs[pair].model_copy(update={field: getattr(style.resolved[pair], field)})
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        for attribute, (column, name) in self.originals.items():
            stored = p.arrays[name][:n]
            rows = chosen & np.isfinite(stored)
            if column == "q":
                p.q[:n][rows] = stored[rows]
            else:
                self.set_radii(sim, rows, stored[rows], attribute)
