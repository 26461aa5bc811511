"""pdps plugin: computes ke, msd, com, reduce, property/atom and pair/contact; see each style's
module for the physics and the script syntax."""

PDPS_API = ">=1.0,<2"
