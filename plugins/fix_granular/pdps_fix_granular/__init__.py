"""pdps plugin: fixes for granular and driven systems; see the style modules for the physics and the
script syntax (``pdps doc fix nve/sphere`` and so on)."""

PDPS_API = ">=1.0,<2"
