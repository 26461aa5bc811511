"""pdps plugin: LIGGGHTS's granular contact computes (pair_gran_local.py, contact_atom.py)."""

PDPS_API = ">=1.0,<2"
