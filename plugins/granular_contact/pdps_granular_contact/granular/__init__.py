"""LAMMPS's ``pair_style granular`` family (its GRANULAR package's GranularModel and GranSubMod's) as
sub-models, one per module, in the entry-point groups ``pdps.granular.PART``: normal (hooke, hertz,
hertz/material, dmt, jkr), damping (velocity, mass_velocity, viscoelastic, tsuji,
coeff_restitution), tangential (linear_nohistory, linear_history, mindlin, mindlin/force,
mindlin_rescale, mindlin_rescale/force), rolling (sds), twisting (marshall, sds). Their
coefficients are the words of a ``pair_coeff`` line (``words``), per type pair, mixed between types
as LAMMPS mixes them (``base``)."""
