"""fix property/atom/tracer/stream: the marked particles are, packet by packet, the first to cross the
stream's face at or after the packet's step (their release steps, read off the stream's flight
record); a packet waits for the next insertion; what it needs, one line each. (LIGGGHTS 3.8.0's
counts for the same fix: plugins/fix_property/tests/data/liggghts.cases.json, case tracer_stream.)"""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import liggghts_material

FACE = """solid face
facet normal 0 0 1
 outer loop
  vertex -0.04 -0.04 0.15
  vertex 0.04 -0.04 0.15
  vertex 0.04 0.04 0.15
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -0.04 -0.04 0.15
  vertex 0.04 0.04 0.15
  vertex -0.04 0.04 0.15
 endloop
endfacet
endsolid face
"""
STREAM = """atom_style granular
atom_modify map array
boundary f f f
units si
region box block -0.06 0.06 -0.06 0.06 0 0.2 units box
create_box 1 box
neighbor 0.001 bin
""" + liggghts_material(5.e6, 0.45, 0.3, 0.5) + """pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002
fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0
fix inface all mesh/surface file face.stl type 1
fix ins all insert/stream seed 49979687 distributiontemplate pdd1 nparticles INF particlerate 5000 overlapcheck yes &
    vel constant 0. 0. -1.0 insertion_face inface extrude_length 0.02
fix integr all nve/sphere
"""


@pytest.fixture
def stream(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "face.stl").write_text(FACE)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(STREAM)
    return sim


def release_steps(sim):
    """Each particle's (id, release step), from the stream's flight record (column 1: release time)."""
    p = sim.particles
    record = p.arrays[sim.fixes["ins"].flight_name][:p.nlocal]
    return p.tag[:p.nlocal].copy(), np.rint(record[:, 1] / sim.dt).astype(np.int64)


def test_a_packet_marks_the_first_to_cross_after_its_step(stream):
    stream.command("fix tr all property/atom/tracer/stream mark_step 2900 n_tracer 30 insert_stream ins every once\n"
                   "run 2001")
    tags, release = release_steps(stream)
    marker = stream.particles.arrays["tr"][:stream.particles.nlocal]
    assert int(marker.sum()) == 30
    assert stream.fixes["tr"].scalar(stream) == 30 and stream.fixes["tr"].scalar(stream) == 0
    # the 30 marked are the 30 earliest crossings at or after step 2900
    after = np.flatnonzero(release >= 2900)
    earliest = after[np.argsort(release[after], kind="stable")[:30]]
    assert set(tags[earliest]) == set(tags[marker == 1.0])
    assert release[marker == 1.0].max() <= np.sort(release[after])[30]


def test_a_packet_waits_for_the_next_insertion_and_every_opens_more(stream):
    stream.command("fix tr all property/atom/tracer/stream mark_step 3500 n_tracer 150 insert_stream ins every 4000\n"
                   "run 6001")
    tags, release = release_steps(stream)
    marked = stream.particles.arrays["tr"][:stream.particles.nlocal] == 1.0
    # the packet of step 3500 takes the second batch's crossings from 3500 on and the third's
    # (inserted at 4001) until it holds 150: the 150 earliest from 3500 among those two batches
    early = np.flatnonzero((release >= 3500) & (release < 6201))
    first = early[np.argsort(release[early], kind="stable")[:150]]
    assert set(tags[first]) == set(tags[marked & (release < 6201)])
    # the insertion at step 6001 opens the packet of 7500 (LIGGGHTS opens one within an insertion
    # interval ahead), which takes the fourth batch's crossings from 7500 on: fewer than 150, all
    late = release >= 7500
    assert 0 < late.sum() < 150 and marked[late].all()
    assert not marked[(release >= 6201) & (release < 7500)].any()


@pytest.mark.parametrize("line, message", [
    ("fix t all property/atom/tracer/stream mark_step 10 n_tracer 5 insert_stream integr every once",
     "insert_stream integr is not a fix insert/stream (it is fix nve/sphere)"),
    ("fix t all property/atom/tracer/stream mark_step 10 n_tracer 5 insert_stream ins every 0",
     "every must be once or > 0 (got 0)"),
    ("fix t all property/atom/tracer/stream mark_step 10 n_tracer 5 insert_stream ins",
     "missing keyword every; usage: fix ID GROUP property/atom/tracer/stream mark_step S n_tracer N "
     "insert_stream INS_ID every once|E"),
    ("fix t all property/atom/tracer/stream mark_step 10 n_tracer -1 insert_stream ins every once",
     "n_tracer must be >= 0 (got -1)"),
])
def test_what_it_needs_is_one_line(stream, line, message):
    with pytest.raises(ScriptError) as error:
        stream.command(line)
    assert str(error.value) == f"<command>:1: fix: {message}"
