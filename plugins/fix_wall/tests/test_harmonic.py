"""fix wall/harmonic: forces and energy against the formula, walls crossed. The pressure of a gas held
by these walls (their virial) is tested with the other thermo contributions in
tests/test_fix_contributions.py."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import build, forces_by_tag

EPS, RC = 50.0, 1.0
WALLS = " ".join(f"{face} EDGE {EPS} 1.0 {RC}" for face in ("xlo", "xhi", "ylo", "yhi", "zlo", "zhi"))


def test_force_and_energy_near_each_face(tmp_path):
    x = [[0.3, 5.0, 5.0], [5.0, 9.4, 5.0], [5.0, 5.0, 5.0]]
    sim = build(tmp_path, x, boundary="f f f", setup=f"fix w all wall/harmonic {WALLS} units box\n"
                "fix_modify w energy yes\nrun 0")
    f = forces_by_tag(sim)
    assert f[0] == pytest.approx([2 * EPS * (RC - 0.3), 0, 0], rel=1e-14)
    assert f[1] == pytest.approx([0, -2 * EPS * (RC - 0.6), 0], rel=1e-14)
    assert not f[2].any()
    energy = EPS * (RC - 0.3) ** 2 + EPS * (RC - 0.6) ** 2
    assert sim.fix_value("w") == pytest.approx(energy, rel=1e-14)
    assert sim.pe == pytest.approx(energy, rel=1e-14)


def test_particle_behind_a_wall_stops_the_run(tmp_path):
    sim = build(tmp_path, [[5.0, 5.0, 5.0]], setup="fix w all wall/harmonic xlo 6.0 1.0 1.0 1.0 units box")
    with pytest.raises(ScriptError, match=r"fix w \(wall/harmonic\): particle 1 is on or behind a wall at step 0"):
        sim.command("run 0")
