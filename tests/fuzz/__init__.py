"""The fuzz suite (issue 10): mutated scripts, data files and restart files, run by the thousand."""
