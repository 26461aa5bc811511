"""pdps plugin: LIGGGHTS's property fixes; fix property/global holds the named material constants
that LIGGGHTS's granular models read (property_global.py)."""

PDPS_API = ">=1.0,<2"
