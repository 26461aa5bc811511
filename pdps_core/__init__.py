"""pdps: particle dynamics in Python, driven by PDPS/LAMMPS-style input scripts."""

__version__ = "0.1.0"
