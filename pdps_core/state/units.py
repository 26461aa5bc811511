"""Unit systems, as LAMMPS defines them (its units page; the constants of its update.cpp):
lj, real, metal, si, cgs, micro, nano.

``boltz`` turns temperature into energy, ``mvv2e`` mass*velocity^2 into energy, ``ftm2v``
force*time/mass into velocity (integrators: v += dt f / m * ftm2v), ``nktv2p`` an energy density into
pressure, ``mv2d`` mass/volume into the density thermo reports. ``dt`` and ``skin`` are the timestep
and neighbor skin a ``units`` command sets.
"""

from dataclasses import dataclass


@dataclass(frozen=True)
class Units:
    name: str
    boltz: float
    mvv2e: float = 1.0
    nktv2p: float = 1.0
    dt: float = 0.005
    ftm2v: float = 1.0
    mv2d: float = 1.0
    qe2f: float = 1.0                 # charge*electric field to force (fix efield), LAMMPS's
    skin: float = 0.3


_REAL_V = 48.88821291
UNITS = {
    "lj": Units("lj", boltz=1.0, dt=0.005, skin=0.3),
    "real": Units("real", boltz=0.0019872067, mvv2e=_REAL_V * _REAL_V, nktv2p=68568.415, dt=1.0,
                  ftm2v=1.0 / _REAL_V / _REAL_V, mv2d=1.0 / 0.602214129, qe2f=23.060549, skin=2.0),
    "metal": Units("metal", boltz=8.617343e-5, mvv2e=1.0364269e-4, nktv2p=1.6021765e6, dt=0.001,
                   ftm2v=1.0 / 1.0364269e-4, mv2d=1.0 / 0.602214129, skin=2.0),
    "si": Units("si", boltz=1.3806504e-23, dt=1e-8, skin=0.001),
    "cgs": Units("cgs", boltz=1.3806504e-16, dt=1e-8, skin=0.1),
    "micro": Units("micro", boltz=1.3806504e-8, dt=2.0, skin=0.1),
    "nano": Units("nano", boltz=0.013806504, dt=0.00045, skin=0.1),
}
