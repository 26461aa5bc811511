"""What PDPS's dem sub-models share: coefficients from the pair style's tables."""

from pdps_granular_contact.composition import ContactSubModel, coefficient_columns


class Tables:
    """Per-type-pair coefficient tables by name ((ntypes + 1, ntypes + 1) each), as a dem pair style
    read them from its pair_coeff lines: what its sub-models' ``coefficients`` take."""

    def __init__(self, ntypes, tables):
        self.ntypes, self.tables = ntypes, tables

    def table(self, name):
        return self.tables[name]

    def columns(self, *tables):
        return coefficient_columns(self.ntypes, tables)


class DemSubModel(ContactSubModel):
    """A sub-model of PDPS's dem pair styles."""
