"""What LIGGGHTS's sub-models share: the base class of the ``gran`` family and its settings."""

from pdps_granular_contact.composition import ContactSubModel


class GranSubModel(ContactSubModel):
    """A sub-model of LIGGGHTS's ``pair gran`` and ``fix wall/gran model``: coefficients from the
    material of ``fix property/global``, settings from the model words (``tangential_damping off``)."""
