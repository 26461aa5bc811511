"""Where the insertion fixes put particles, against LIGGGHTS 3.8.0 over seeds (recorded on this
machine by benchmarks/liggghts_references/insertion.py, LIGGGHTS_RUNS seed sets): insert/stream's
depth counts from each sphere's own radius and keeps it from the box's faces, and insert/pack keeps
every centre its radius inside the box (check_dist_from_subdomain_border). pdps's seeds differ from
LIGGGHTS's: the means are compared within their combined standard errors."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

TABLE = json.loads((Path(__file__).parent / "data" / "liggghts_placement.json").read_text())
PDPS_RUNS = 10
FACE_Z, BOX_TOP = 0.3, 0.455
RADII = (0.006, 0.01)


def seeds(k):
    """Seed set k of pdps's own (LIGGGHTS's seed sets are the recorded ones)."""
    base = 7_000_000 + 100 * k
    return {"s1": base + 1, "s2": base + 3, "s3": base + 7, "s4": base + 9}


def pdps_runs(make_sim, name, numbers):
    Path("face.stl").write_text(TABLE["stl"])
    out = []
    for k in range(PDPS_RUNS):
        sim = make_sim(dialect="liggghts")
        sim.command(TABLE["scripts"][name].format(**seeds(k)))
        p = sim.particles
        out.append(numbers(p.radius[:p.nlocal].copy(), p.x[:p.nlocal].copy()))
    return np.array(out, dtype=float)


def within_errors(ours, theirs, column, sigmas=3.0):
    """Whether the run means of ``column`` agree within ``sigmas`` combined standard errors."""
    a, b = ours[..., column], theirs[..., column]
    error = math.hypot(a.std(ddof=1) / math.sqrt(len(a)), b.std(ddof=1) / math.sqrt(len(b)))
    return abs(a.mean() - b.mean()) <= sigmas * error, (a.mean(), b.mean(), error)


def stream_numbers(radius, x):
    out = []
    for r in RADII:
        mine = np.isclose(radius, r)
        lift = x[mine, 2] - FACE_Z - radius[mine]
        out.append([mine.sum(), lift.mean(), lift.min(), lift.max()])
    return out


def pack_numbers(radius, x):
    room = np.minimum(x, 0.1 - x).min(axis=1) - radius
    return [len(radius), room.min(), room.mean()]


def test_stream_places_each_sphere_its_own_radius_behind_the_face_and_inside_the_box(make_sim):
    ours = pdps_runs(make_sim, "stream", stream_numbers)           # run, radius, (count, mean, min, max)
    theirs = np.array(TABLE["runs"]["stream"])
    for k, r in enumerate(RADII):
        top = BOX_TOP - FACE_Z - 2 * r          # highest lift with the centre its radius below the top
        for program in (ours, theirs):
            assert program[:, k, 2].min() >= 0.0 and program[:, k, 3].max() <= top + 1e-12
        assert ours[:, k, 3].max() > top - 0.002    # and they reach it
        for column in (0, 1):                   # the count and the mean lift of each size
            agree, figures = within_errors(ours[:, k], theirs[:, k], column)
            assert agree, (r, column, figures)


def test_pack_keeps_every_centre_its_radius_inside_the_box_as_liggghts(make_sim):
    ours = pdps_runs(make_sim, "pack", pack_numbers)
    theirs = np.array(TABLE["runs"]["pack"])
    assert theirs[:, 1].min() >= 0.0 and ours[:, 1].min() >= 0.0
    for column in (0, 2):                       # the count and the mean room to the faces
        agree, figures = within_errors(ours, theirs, column)
        assert agree, (column, figures)


def test_pack_without_the_border_check_puts_centres_near_the_faces(make_sim):
    Path("face.stl").write_text(TABLE["stl"])
    sim = make_sim(dialect="liggghts")
    script = TABLE["scripts"]["pack"].format(**seeds(0))
    sim.command(script.replace("region reg\n", "region reg check_dist_from_subdomain_border no\n"))
    p = sim.particles
    assert pack_numbers(p.radius[:p.nlocal], p.x[:p.nlocal])[1] < 0.0


@pytest.mark.parametrize("overlapcheck", ["yes", "no"])
def test_a_streamed_sphere_is_released_after_whole_steps_where_its_flight_ends(make_sim, overlapcheck):
    """No gravity, few spheres: each flies at v_n for n = floor(d / (|v_n| dt)) steps from its depth
    d behind the face, is put at the flight's end with the velocity it was inserted with, and moves
    freely from there: its position after the run follows to round-off."""
    Path("face.stl").write_text(TABLE["stl"])
    script = TABLE["scripts"]["stream"].format(**seeds(0)).replace("particlerate 6000", "particlerate 200")
    script = script.replace("overlapcheck yes", f"overlapcheck {overlapcheck}").replace("run 1\n", "")
    sim = make_sim(dialect="liggghts")
    sim.command(script + "run 1")
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    start, radius, dt = p.x[:p.nlocal][order], p.radius[:p.nlocal][order], sim.dt
    assert 5 < p.nlocal < 40
    steps = 7000
    sim.command(f"run {steps}")
    depth = start[:, 2] - FACE_Z
    flight = np.floor((depth + 1e-14) / (2.0 * dt))
    assert (flight < steps).sum() > 5              # most are free by the end, some are not
    flight = np.minimum(flight, steps)
    expected = start.copy()
    expected[:, 2] -= 2.0 * dt * flight
    free = steps - flight
    expected[:, 1] -= 0.5 * dt * free
    expected[:, 2] -= 2.0 * dt * free
    order = np.argsort(p.tag[:p.nlocal])
    assert np.abs(p.x[:p.nlocal][order] - expected).max() < 1e-12
    if overlapcheck == "no":                    # depth u (L - 2r) + r: inside [r, L - r]
        assert (depth >= radius - 1e-12).all() and (depth <= 0.15 - radius + 1e-12).all()
