"""pdps plugin: see the style modules (image, movie) for the script syntax."""

PDPS_API = ">=1.0,<2"
