"""LIGGGHTS's granular contact sub-models (the words of ``pair_style gran model ...`` and ``fix
wall/gran model ...``), one per module, registered in the entry-point groups ``pdps.gran.PART``."""
