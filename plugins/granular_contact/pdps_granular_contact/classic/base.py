"""What the classic sub-models share: one set of numbers for every type pair."""

from pdps_granular_contact.composition import ContactSubModel, coefficient_columns


class Constants:
    """The classic law's numbers (kn, kt, gamma_n, gamma_t, xmu, limit_damping, hertz), for
    ``ntypes`` particle types: what the classic sub-models' ``coefficients`` take."""

    def __init__(self, ntypes, **values):
        self.ntypes, self.values = ntypes, values

    def columns(self, *names):
        return coefficient_columns(self.ntypes, [float(self.values[name]) for name in names])


class ClassicSubModel(ContactSubModel):
    """A sub-model of LAMMPS's classic granular styles."""

    def coefficients(self, constants):
        return constants.columns(*self.names)
