"""Unit systems, as LAMMPS defines them: ``lj`` (reduced) and ``si``.

``boltz`` turns temperature into energy, ``mvv2e`` mass*velocity^2 into energy, ``nktv2p`` an energy
density into pressure. In both systems here they are 1 except Boltzmann's constant in SI.
"""

from dataclasses import dataclass


@dataclass(frozen=True)
class Units:
    name: str
    boltz: float
    mvv2e: float = 1.0
    nktv2p: float = 1.0
    dt: float = 0.005


UNITS = {
    "lj": Units("lj", boltz=1.0, dt=0.005),
    "si": Units("si", boltz=1.380649e-23, dt=1e-8),
}
