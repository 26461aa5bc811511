"""pdps plugin: see the style modules for the file formats and the script syntax."""

PDPS_API = ">=1.0,<2"
