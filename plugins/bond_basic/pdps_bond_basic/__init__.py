"""pdps plugin: see the style modules for the physics and the script syntax."""

PDPS_API = ">=1.0,<2"
