"""pdps plugin: LAMMPS's classic granular pair styles (gran/hooke, gran/hooke/history,
gran/hertz/history); see the style modules for the physics and the script syntax, gran.py for the
geometry, torques and contact history, and pdps_granular_contact.lammps_classic for the law."""

PDPS_API = ">=1.0,<2"
