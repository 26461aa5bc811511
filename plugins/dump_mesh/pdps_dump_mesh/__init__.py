"""pdps plugin: see the style modules for the file formats and the script syntax."""
