"""pdps plugin: heat transfer between granular particles (LIGGGHTS's fix heat/gran; heat_gran.py)."""

PDPS_API = ">=1.0,<2"
