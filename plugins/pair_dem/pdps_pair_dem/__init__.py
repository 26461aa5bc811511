"""pdps plugin: DEM contacts between spheres (dem/lsd, dem/hertz); see the style modules for the
physics and the script syntax, and granular.py for the geometry, torques and contact history."""

PDPS_API = ">=1.0,<2"
