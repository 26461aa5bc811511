"""pdps granular contacts: a library the granular packs depend on, and the sub-models of its
contact laws.

``composition`` builds a contact law from sub-models (normal, damping, cohesion, tangential,
rolling, twisting, heat, surface) found through the entry-point groups ``pdps.FAMILY.PART`` and
generates the one contact loop pair styles and walls call; ``gran`` holds LIGGGHTS's sub-models
(``pair_style gran model ...``), ``granular`` LAMMPS's of its pair granular (``pair_coeff I J
hertz/material ... tangential mindlin ...``), ``classic`` and ``dem`` those of LAMMPS's gran/* and
PDPS's dem/*. ``contact_models`` and ``lammps_classic`` hold the laws the other
styles call directly; ``contact_slots`` the bookkeeping of the per-contact history
(``pdps_core.api.ContactHistory``).
"""

PDPS_API = ">=1.0,<2"
