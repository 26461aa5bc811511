"""What PDPS's dem sub-models share: coefficients from the pair style's tables."""

import numpy as np

from pdps_granular_contact.composition import ContactSubModel


class Tables:
    """Per-type-pair coefficient tables by name ((ntypes + 1, ntypes + 1) each), as a dem pair style
    read them from its pair_coeff lines: what its sub-models' ``coefficients`` take."""

    def __init__(self, ntypes, tables):
        self.ntypes, self.tables = ntypes, tables

    def table(self, name):
        return self.tables[name]

    def columns(self, *tables):
        n = self.ntypes + 1
        out = np.zeros((n, n, len(tables)))
        for k, table in enumerate(tables):
            out[:, :, k] = table
        return out


class DemSubModel(ContactSubModel):
    """A sub-model of PDPS's dem pair styles."""
