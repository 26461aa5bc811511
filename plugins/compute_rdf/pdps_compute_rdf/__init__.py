"""pdps plugin: see the style modules for the physics and the script syntax."""
