"""pdps plugin: rigid bodies (LAMMPS's fix rigid family); see the style modules for the physics and
the script syntax, and bodies.py for what the styles share."""

PDPS_API = ">=1.0,<2"
