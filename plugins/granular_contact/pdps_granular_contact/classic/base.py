"""What the classic sub-models share: one set of numbers for every type pair."""

import numpy as np

from pdps_granular_contact.composition import ContactSubModel


class Constants:
    """The classic law's numbers (kn, kt, gamma_n, gamma_t, xmu, limit_damping, hertz), for
    ``ntypes`` particle types: what the classic sub-models' ``coefficients`` take."""

    def __init__(self, ntypes, **values):
        self.ntypes, self.values = ntypes, values

    def columns(self, *names):
        n = self.ntypes + 1
        out = np.zeros((n, n, len(names)))
        for k, name in enumerate(names):
            out[:, :, k] = float(self.values[name])
        return out


class ClassicSubModel(ContactSubModel):
    """A sub-model of LAMMPS's classic granular styles."""

    def coefficients(self, constants):
        return constants.columns(*self.names)
