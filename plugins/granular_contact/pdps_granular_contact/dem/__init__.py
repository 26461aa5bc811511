"""PDPS's granular contact sub-models (pair dem/lsd and dem/hertz), one per module, registered in
the entry-point groups ``pdps.dem.PART``; their coefficients come from the pair style's pair_coeff
tables (``Tables``), not from a material."""
