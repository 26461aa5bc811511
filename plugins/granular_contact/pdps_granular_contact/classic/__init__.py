"""LAMMPS's classic granular laws (pair gran/hooke, gran/hooke/history, gran/hertz/history) as
sub-models, one per module, in the entry-point groups ``pdps.classic.PART``; their coefficients are
the pair style's few numbers (``Constants``), the same for every type pair. The formulas are
``pdps_granular_contact.lammps_classic``'s docstring."""
