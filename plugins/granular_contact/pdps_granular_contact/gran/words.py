"""LIGGGHTS's model words, as ``pair_style gran`` and ``fix wall/gran model`` both take them: a
sub-model of each part (the installed ones: ``pdps doc gran.PART NAME``) and the model settings,
which every sub-model is handed."""

from typing import Annotated, Literal

from pdps_core.api import StyleArgs, StyleName, keyword

from pdps_granular_contact.composition import ContactModel

OnOff = Literal["on", "off"]
# the model words and the contact parts they name (pdps_granular_contact.composition.PARTS)
PART_WORDS = {"model": "normal", "tangential": "tangential", "cohesion": "cohesion", "rolling_friction": "rolling",
              "surface": "surface"}
# LIGGGHTS's model settings: each is read by the sub-models that declare it (settings_read), and
# refused on a line whose models do not
SETTINGS = ("tangential_damping", "limitForce", "absolute_damping", "tangential_reduce", "torsionTorque",
            "limitLiquidContent", "modifyLbVolume")


class GranModelArgs(StyleArgs):
    """LIGGGHTS's model words."""
    model: Annotated[str, StyleName("gran.normal")] = keyword(...)
    tangential: Annotated[str, StyleName("gran.tangential")] = keyword(...)
    rolling_friction: Annotated[str, StyleName("gran.rolling", also=("off",))] = keyword("off")
    cohesion: Annotated[str, StyleName("gran.cohesion", also=("off",))] = keyword("off")
    surface: Annotated[str, StyleName("gran.surface")] = keyword("default")
    tangential_damping: OnOff | None = keyword(None)
    limitForce: OnOff | None = keyword(None)
    absolute_damping: OnOff | None = keyword(None)
    tangential_reduce: OnOff | None = keyword(None)
    torsionTorque: OnOff | None = keyword(None)
    limitLiquidContent: OnOff | None = keyword(None)
    modifyLbVolume: OnOff | None = keyword(None)

    def contact_model(self, heat=None):
        """The composed law these words name; ``heat``: a heat sub-model to compose in (fix
        heat/gran's conduction)."""
        chosen = {part: getattr(self, word) for word, part in PART_WORDS.items() if getattr(self, word) != "off"}
        if heat is not None:
            chosen["heat"] = heat
        return ContactModel("gran", chosen, {name: getattr(self, name) for name in SETTINGS}, slot_cache=True)
