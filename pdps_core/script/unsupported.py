"""LAMMPS commands pdps does not run, each with what to use instead: a LAMMPS script that reaches
one stops there with one line saying so, rather than "unknown command"."""

ALTERNATIVES = {
    "angle_coeff": "pdps has no angle styles", "angle_style": "pdps has no angle styles",
    # headings of LIGGGHTS's manual that LIGGGHTS 3.8.0 itself does not know ("Unknown command", run 12-02)
    "neigh_settings": "neigh_modify (LIGGGHTS 3.8.0 itself has no neigh_settings)",
    "neighbor_skin": "neighbor SKIN bin (LIGGGHTS 3.8.0 itself has no neighbor_skin)",
    "orient": "lattice ... orient DIM I J K (LIGGGHTS 3.8.0 itself has no orient command)",
    "origin": "lattice ... origin X Y Z (LIGGGHTS 3.8.0 itself has no origin command)",
    "create_bonds": "bonds from a data file's Bonds section (read_data)",
    "dihedral_coeff": "pdps has no dihedral styles",
    "dihedral_style": "pdps has no dihedral styles", "dynamical_matrix": "none in pdps",
    "fitpod": "none in pdps", "group2ndx": "dump custom with id and the group",
    "improper_coeff": "pdps has no improper styles", "improper_style": "pdps has no improper styles",
    "kim": "none in pdps",
    "kspace_modify": "pdps has no long-range electrostatics", "kspace_style": "pdps has no long-range electrostatics",
    "labelmap": "numeric types", "mdi": "none in pdps",
    "neb": "none in pdps", "package": "nothing: pdps compiles its kernels itself (numba)",
    "pair_write": "pdps doc pair STYLE (the formula) or a compute on two particles",
    "plugin": "pdps plugins are Python distributions (docs/plugin-guide.md)",
    "prd": "none in pdps", "python": "drive pdps from Python: pdps_core.api.Simulation",
    "rerun": "none in pdps",
    "reset_atoms": "none in pdps", "reset_atom_ids": "none in pdps",
    "suffix": "nothing: pdps has one build of each style",
    "tad": "none in pdps", "temper": "none in pdps", "timer": "the timing table printed after each run",
    "write_coeff": "none in pdps",
}


def unsupported(name):
    """The one line for a LAMMPS command pdps does not run, or None."""
    alternative = ALTERNATIVES.get(name)
    if alternative is None:
        return None
    return f"{name} is a LAMMPS command pdps does not support; instead: {alternative} (docs/lammps.md)"


# LAMMPS styles pdps has no plugin for, with the closest one it has
STYLE_ALTERNATIVES = {
    ("pair", "lj/cut/coul/cut"): "pdps has no charges: lj/cut for the Lennard-Jones part",
    ("pair", "lj/cut/coul/long"): "pdps has no charges: lj/cut for the Lennard-Jones part",
    ("pair", "lj/cut/coul/debye"): "pdps has no charges: lj/cut plus yukawa for screened charges",
    ("pair", "lj96/cut"): "pair_style formula with the 9-6 law",
    ("pair", "buck"): "pair_style formula with the Buckingham law",
    ("pair", "born"): "pair_style formula with the Born-Mayer-Huggins law",
    ("pair", "gauss"): "pair_style formula with the Gaussian law",
    ("pair", "eam"): "pdps has no many-body potentials",
    ("pair", "eam/alloy"): "pdps has no many-body potentials",
    ("pair", "tersoff"): "pdps has no many-body potentials",
    ("pair", "sw"): "pdps has no many-body potentials",
    ("pair", "granular"): "gran/hooke, gran/hooke/history, gran/hertz/history, dem/lsd or dem/hertz",
    ("fix", "shake"): "pdps has no constraints",
    ("fix", "rattle"): "pdps has no constraints",
    ("fix", "deposit"): "create_atoms random between runs",
    ("compute", "temp/com"): "compute temp (pdps removes no centre-of-mass bias)",
    ("compute", "rdf/atom"): "compute rdf",
    ("dump", "xyz"): "dump custom with id type x y z",
    ("dump", "dcd"): "dump custom or dump xdmf",
    ("dump", "netcdf"): "dump xdmf",
    **{(kind, name): "pdps simulates spheres only"
       for kind, name in (("fix", "nve/asphere"), ("fix", "nve/asphere/noforce"), ("fix", "nve/line"),
                          ("compute", "erotate/asphere"))},
    ("fix", "poems"): "pdps has no POEMS coupling: fix rigid",
}

# LIGGGHTS's styles for what pdps does not simulate
LIGGGHTS_STYLE_ALTERNATIVES = {
    **{("fix", name): "pdps has no SPH" for name in ("sph/density/continuity", "sph/density/corr",
                                                     "sph/density/summation", "sph/pressure", "wall/region/sph")},
    ("pair", "sph/artVisc/tensCorr"): "pdps has no SPH",
    **{(kind, name): "pdps simulates spheres only"
       for kind, name in (("fix", "nve/superquadric"), ("fix", "particletemplate/superquadric"),
                          ("compute", "erotate/superquadric"))},
    ("fix", "multicontact/halfspace"): "pdps has no multicontact surface model",
    # in LIGGGHTS's manual, not in LIGGGHTS 3.8.0 itself ("Invalid compute style", run 12-02)
    ("compute", "coord/gran"): "compute contact/atom (LIGGGHTS 3.8.0 itself has no coord/gran)",
    ("compute", "voronoi/atom"): "none in pdps (LIGGGHTS 3.8.0 itself has no voronoi/atom)",
    ("compute", "pair/gran/local/bond"): "compute pair/gran/local (pdps has no cohesion bond model; LIGGGHTS "
                                         "3.8.0 itself has no pair/gran/local/bond)",
}


def unsupported_style(kind, name):
    """What to use instead of a LAMMPS or LIGGGHTS style pdps has no plugin for, or None."""
    return STYLE_ALTERNATIVES.get((kind, name)) or LIGGGHTS_STYLE_ALTERNATIVES.get((kind, name))


def style_origin(kind, name):
    """Whose style a refused one is, for its line: (program, the page of docs/ on it)."""
    if (kind, name) in LIGGGHTS_STYLE_ALTERNATIVES:
        return "LIGGGHTS", "docs/liggghts.md"
    return "LAMMPS", "docs/lammps.md"
