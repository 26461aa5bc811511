"""LIGGGHTS 2.x spellings of its granular models, still in its own tutorials (conveyor): read as
today's, in the LIGGGHTS dialect only (the pair and wall styles' ``respell``).

``pair_style gran/hertz/history`` with no coefficients reads the material from fix property/global,
as ``pair_style gran model hertz tangential history`` does; ``fix ... wall/gran/hooke/history
mesh|primitive ...`` likewise is ``wall/gran model hooke tangential history mesh|primitive ...``.
Model settings written after the style (and, for walls, after the geometry too) go where today's
spelling wants them, after the model (LIGGGHTS's note on the 3.x syntax change)."""

MODELS = {
    "gran/hertz/history": ["model", "hertz", "tangential", "history"],
    "gran/hooke/history": ["model", "hooke", "tangential", "history"],
    "gran/hooke": ["model", "hooke", "tangential", "no_history"],
}

MODEL_SETTINGS = ("rolling_friction", "cohesion", "tangential_damping", "limitForce", "absolute_damping",
                  "viscous")


def pair_words(style, words):
    """Today's words for ``pair_style STYLE words`` in 2.x spelling, or None: coefficients given
    make it LAMMPS's style of that name."""
    if words and words[0] not in MODEL_SETTINGS:
        return None
    return MODELS[style] + list(words)


def wall_words(style, words):
    """Today's ``wall/gran`` words for a 2.x ``wall/gran/MODEL`` fix, or None where the words name
    no mesh or primitive wall."""
    words = list(words)
    if words[:1] == ["type"]:
        words = ["primitive"] + words       # 2.x: wall/gran/hooke/history type 1 xplane -0.5
    if not words or words[0] not in ("mesh", "primitive"):
        return None
    settings, geometry, k = [], [], 0
    while k < len(words):
        if words[k] in MODEL_SETTINGS and k + 1 < len(words):
            settings += words[k:k + 2]
            k += 2
        else:
            geometry.append(words[k])
            k += 1
    return MODELS[style[len("wall/"):]] + settings + geometry
