r"""Fix ``heat/gran`` (also ``heat/gran/conduction``): heat conduction through the contacts of
granular particles and the temperature of each particle (LIGGGHTS's fix heat/gran; Chaudhuri et al.,
Chem. Eng. Sci. 61, 6348 (2006); the conductance of two half-spaces through a contact spot).

Each particle has one temperature :math:`T_i` (uniform inside it). Two spheres i and j in contact
(:math:`r < R_i + R_j`) exchange the heat flux

.. math::

    Q_{ij} = h_{ij}\,(T_j - T_i), \qquad h_{ij} = \frac{4 k_i k_j}{k_i + k_j}\sqrt{A_{ij}}

(into i; :math:`-Q_{ij}` into j), with :math:`k` the thermal conductivity of each particle's type
(0 for either: no flux) and the contact area :math:`A_{ij}`:

- ``overlap`` (default): the circle where the spheres intersect,
  :math:`A = -\tfrac{\pi}{4}(r-R_i-R_j)(r+R_i-R_j)(r-R_i+R_j)(r+R_i+R_j)/r^2` (the smaller
  sphere's cross-section once its centre is inside the other sphere, as LIGGGHTS 3.8);
- ``constant A``: the same area A for every contact;
- ``projection``: :math:`\pi\max(R_i, R_j)^2` (LIGGGHTS's source; its manual says the smaller).

The temperatures then advance with explicit Euler steps, as LIGGGHTS's scalar transport equation,

.. math::

    T_i \leftarrow T_i + \Delta t\,\frac{\sum_j Q_{ij} + S_i}{m_i c_i}

for the particles of the fix's group (:math:`c` the heat capacity of its type, :math:`S_i` a heat
source, energy/time); particles outside the group exchange heat but keep their temperature. The
sum :math:`\sum_i m_ic_iT_i` is conserved by the conduction to round-off. Two particles alone relax
as :math:`T_1 - T_2 \propto (1 - \lambda\Delta t)^n \approx e^{-\lambda t}`, :math:`\lambda =
h(1/m_1c_1 + 1/m_2c_2)`.

Material from ``fix property/global`` (per type, ``peratomtype``): ``thermalConductivity`` (>= 0,
energy/(time distance temperature)) and ``thermalCapacity`` (> 0, energy/(mass temperature)); read
at the start of each run. Needs ``pair_style gran`` and spheres: the conduction is a part of pair
gran's composed contacts (``pdps_granular_contact.gran.heat_conduction``, composed in at each run's
start), computed in the same pass over the contacts as their forces; the fix sums the fluxes of
ghosts onto their owners and advances the temperatures.

Per-atom values: ``Temp`` (temperature), ``heatFlux`` (the summed :math:`Q` of the last step,
energy/time), ``heatSource`` (S, 0 unless set) and ``directionalHeatFlux`` (3: half of each
contact's :math:`Q\,(\mathbf{x}_i - \mathbf{x}_j)` on each particle); ``set ... property/atom Temp
T`` and ``set ... property/atom heatSource S`` give them values. Output: ``f_ID`` the group's
thermal energy :math:`\sum m_ic_iT_i` (thermo); per particle ``f_ID[1]`` the temperature and
``f_ID[2]`` the heat flux (dump custom; [0] and [1] in the PDPS dialect).

``store_contact_data yes`` (LIGGGHTS's) keeps, after each step's forces, the per-atom properties
``contactAreaConduction`` (the mean contact area of the particle's contacts with a particle of the
group or between two others in it, by the area model above; 0 without contacts),
``nContactsConduction`` (how many), ``wallHeattransferCoeff`` (the conductance of the particle's contact
with a wall that has a temperature at this step, its last one's; 0 without: LIGGGHTS's) and ``wallTemp`` (0, as
LIGGGHTS leaves it).

Walls: a ``fix wall/gran`` on a ``fix mesh/surface ... temperature T0`` adds each contact's
:math:`\frac{4k_pk_w}{k_p + k_w}\sqrt{A}\,(T_0 - T_p)` to the particle's heat flux, A by this fix's
contact_area (overlap: :math:`\pi(R^2 - d^2)` at centre distance d), :math:`k_w` the conductivity of
the mesh's type (LIGGGHTS's fix wall/gran; recorded: the mesh_temperature case).

Syntax::

    fix ID GROUP heat/gran initial_temperature T0 [contact_area overlap|projection|constant A]
                                                  [area_correction no] [store_contact_data yes|no]

``initial_temperature`` is every particle's temperature until ``set`` changes it (particles
created later start at T0 too). ``area_correction yes`` (LIGGGHTS's correction for a softened
Young's modulus) is not supported.

Example (LIGGGHTS)::

    fix ctc all property/global thermalConductivity peratomtype 5.
    fix cap all property/global thermalCapacity peratomtype 10.
    fix heat all heat/gran initial_temperature 273.15
    set region hot property/atom Temp 800.
    dump d all custom 100 heat.dump id x y z f_heat[1] f_heat[2]
"""

import math
from typing import Literal

import numpy as np
from numba import njit
from pydantic import PositiveFloat, model_validator

from pdps_core.api import ContactConduction, Fix, HeatTransport, ScriptError, StyleArgs, keyword
from pdps_granular_contact.contact_models import intersection_area
from pdps_granular_contact.gran.heat_conduction import AREAS, CONSTANT, OVERLAP, HeatConduction
from pdps_granular_contact.material import read_property


# the per-atom properties of store_contact_data yes
CONTACT_DATA = ("contactAreaConduction", "nContactsConduction", "wallHeattransferCoeff", "wallTemp")


@njit(cache=True)
def advance(temp, heat_flux, heat_source, rmass, type_, capacity, mask, groupbit, dt, nlocal):
    """T += dt (Q + S) / (m c) for the owned particles of the group."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            temp[i] += dt * (heat_flux[i] + heat_source[i]) / (rmass[i] * capacity[type_[i]])


@njit(cache=True)
def thermal_energy(temp, rmass, type_, capacity, mask, groupbit, nlocal):
    total = 0.0
    for i in range(nlocal):
        if mask[i] & groupbit:
            total += rmass[i] * capacity[type_[i]] * temp[i]
    return total


class FixHeatGran(Fix):
    name = "heat/gran"
    minimize_idle = True         # heat, not forces: LIGGGHTS's fix heat/gran has no min_post_force
    usage = ("fix ID GROUP heat/gran initial_temperature T0 [contact_area overlap|projection|constant A] "
             "[area_correction no] [store_contact_data yes|no]")
    ghost_fields = ("Temp",)

    class Args(StyleArgs):
        initial_temperature: float = keyword(..., unit="temperature")
        # LIGGGHTS's "contact_area constant A"
        contact_area: Literal["overlap", "projection"] | tuple[Literal["constant"], PositiveFloat] = keyword(
            "overlap", unit={"constant": ("1", "area")})
        area_correction: Literal["yes", "no"] = keyword("no")
        store_contact_data: bool = keyword(False)

        @model_validator(mode="after")
        def _supported(self):
            if self.area_correction == "yes":
                raise ValueError("area_correction yes is not supported (it needs youngsModulusOriginal); "
                                 "use area_correction no")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        for fix in sim.fixes.values():
            if isinstance(fix, HeatTransport) and fix is not self:
                raise ScriptError(f"fix {fix.id} ({fix.name}) already transports heat: one heat/gran fix at most")
        p = sim.particles
        # a replicated particle's copies have its temperature (LIGGGHTS's replicate copies it)
        p.request("Temp", 1, default=args.initial_temperature, replicate="copy")
        p.request("heatFlux", 1, replicate="copy")
        p.request("heatSource", 1, replicate="copy")
        p.request("directionalHeatFlux", 3, replicate="copy")
        constant = isinstance(args.contact_area, tuple)
        self.mode = AREAS["constant" if constant else args.contact_area]
        self.area_constant = args.contact_area[1] if constant else 0.0
        self.conductivity = self.capacity = None
        self.store_contact_data = args.store_contact_data
        if self.store_contact_data:
            for name in CONTACT_DATA:
                p.request(name, 1, replicate="copy")

    def init_run(self, sim):
        if not sim.particles.has("radius") or not sim.particles.has("rmass"):
            raise ScriptError(f"fix {self.id} ({self.name}) needs atom_style granular or sphere")
        if not isinstance(sim.pair, ContactConduction):
            raise ScriptError(f"fix {self.id} ({self.name}) needs pair_style gran (LIGGGHTS's), whose contacts "
                              "carry the heat")
        self.conductivity = read_property(sim, "thermalConductivity", sim.ntypes, f"fix {self.id} ({self.name})")
        self.capacity = read_property(sim, "thermalCapacity", sim.ntypes, f"fix {self.id} ({self.name})")
        self.groupbit = np.uint32(sim.groups.bit(self.group))

    def setup(self, sim):
        self.conduct(sim)

    def pre_force(self, sim):
        # a wall contact's conductance is this step's (LIGGGHTS: 0 out of contact)
        if self.store_contact_data:
            sim.particles.arrays["wallHeattransferCoeff"][:] = 0.0

    def post_force(self, sim):
        self.conduct(sim)

    def conduct(self, sim):
        """The pair style's contacts filled each particle's heat flux in its force computation
        (ContactConduction): ghosts' go to their owners."""
        sim.comm.reverse_comm(sim.particles, ("heatFlux", "directionalHeatFlux"))
        if self.store_contact_data:
            self._store_contact_data(sim)

    def _store_contact_data(self, sim):
        """Each particle's contacts: their mean area and number (LIGGGHTS's contactAreaConduction,
        nContactsConduction), over the contacts with at least one particle of the group."""
        p = sim.particles
        a = p.arrays
        area, number = a["contactAreaConduction"], a["nContactsConduction"]
        area[:] = 0.0
        number[:] = 0.0
        a["wallTemp"][:] = 0.0
        found = sim.pair.contacts(sim)
        i, j = found["i"], found["j"]
        either = ((p.mask[i] | p.mask[j]) & self.groupbit) != 0
        i, j = i[either], j[either]
        d = p.x[i] - p.x[j]
        r = np.sqrt((d * d).sum(axis=1))
        ri, rj = p.radius[i], p.radius[j]
        if self.mode == OVERLAP:
            spot = intersection_area(r, ri, rj)
        elif self.mode == CONSTANT:
            spot = np.full(len(i), self.area_constant)
        else:
            spot = math.pi * np.maximum(ri, rj) ** 2
        for rows in (i, j):
            np.add.at(area, rows, spot)
            np.add.at(number, rows, 1.0)
        sim.comm.reverse_comm(p, ("contactAreaConduction", "nContactsConduction"))
        n = p.nlocal
        touching = number[:n] > 0.5
        area[:n][touching] /= number[:n][touching]

    def contact_heat_model(self, sim):
        """The conduction law as a contact part (HeatTransport): pdps_granular_contact's gran.heat
        conduction, with this fix's contact area and the conductivities it reads now."""
        area = self.args.contact_area
        constant = isinstance(area, tuple)
        model = HeatConduction({"contact_area": "constant" if constant else area, "area": area[1] if constant else 0.0})
        model.conductivity = read_property(sim, "thermalConductivity", sim.ntypes, f"fix {self.id} ({self.name})")
        return model

    def wall_conduction(self, sim):
        """(contact area model, constant area, conductivity per type) for the walls' contacts (the
        HeatTransport capability: fix wall/gran on a mesh with a temperature)."""
        if self.conductivity is None:
            raise ScriptError(f"fix {self.id} ({self.name}): the conductivities are read at a run's start")
        return self.mode, self.area_constant, self.conductivity

    def contact_heat_flux(self, sim, i, j, r):
        """Heat into i from j of each contact (the HeatTransport capability), by the docstring's
        conductance: 4 k_i k_j / (k_i + k_j) sqrt(A) (T_j - T_i)."""
        if self.conductivity is None:
            raise ScriptError(f"fix {self.id} ({self.name}): contact heat fluxes are known once a run has started")
        p = sim.particles
        ri, rj = p.radius[i], p.radius[j]
        ki, kj = self.conductivity[p.type[i]], self.conductivity[p.type[j]]
        if self.mode == OVERLAP:
            area = intersection_area(r, ri, rj)
        elif self.mode == CONSTANT:
            area = np.full(len(i), self.area_constant)
        else:
            area = math.pi * np.maximum(ri, rj) ** 2
        with np.errstate(invalid="ignore", divide="ignore"):
            h = np.where((ki > 0) & (kj > 0), 4 * ki * kj / (ki + kj) * np.sqrt(np.maximum(area, 0.0)), 0.0)
        temp = p.arrays["Temp"]
        return h * (temp[j] - temp[i])

    def final_integrate(self, sim):
        p = sim.particles
        a = p.arrays
        advance(a["Temp"], a["heatFlux"], a["heatSource"], a["rmass"], a["type"], self.capacity,
                a["mask"], self.groupbit, sim.dt, p.nlocal)

    def scalar(self, sim):
        """The group's thermal energy sum m c T (energy)."""
        if self.capacity is None:
            raise ScriptError(f"f_{self.id}: the thermal energy is known once a run has started")
        p = sim.particles
        a = p.arrays
        return sim.comm.sum(thermal_energy(a["Temp"], a["rmass"], a["type"], self.capacity, a["mask"],
                                           self.groupbit, p.nlocal))

    def peratom(self, sim):
        """Temperature and heat flux of each owned particle."""
        p = sim.particles
        n = p.nlocal
        return np.column_stack([p.arrays["Temp"][:n], p.arrays["heatFlux"][:n]])


class FixHeatGranConduction(FixHeatGran):
    name = "heat/gran/conduction"
    usage = FixHeatGran.usage.replace("heat/gran", "heat/gran/conduction", 1)
