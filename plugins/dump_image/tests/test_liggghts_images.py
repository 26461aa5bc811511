"""pdps draws LIGGGHTS 3.8.0's pictures of the same scenes (recorded here by
benchmarks/liggghts_references/images.py: 17 dumps of the falling bed, 3 pictures each, over the
view, center, up, zoom, box, axes, shiny, ssao, amap, acolor, adiam, backcolor, boxcolor, color,
element and size keywords and the JPEG writer; 2 dumps of a 2-d periodic lattice, its defaults and
a group seen from aside).

Tolerance: none. Every pixel of every picture is LIGGGHTS's, to the byte: pdps's kernels do the
same IEEE double operations in the same order as LIGGGHTS's renderer, and the positions agree to
the last digits LIGGGHTS's thermo prints (the bed's recorded cases). A one-level difference would
mean an operation changed; JPEG files are compared decoded (both are libjpeg at quality 85: their
bytes are the same too)."""

import json
from pathlib import Path

import numpy as np
from PIL import Image

from pdps_core.api import Simulation
from pdps_core.testing import run_ranks

DATA = Path(__file__).parent / "data"
TABLE = json.loads((DATA / "liggghts_images.json").read_text())


def reference():
    with np.load(DATA / "liggghts_images.npz") as pictures:
        return {name: pictures[name] for name in pictures.files}


def picture(path):
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.uint8)


def assert_pictures_are_liggghts(folder):
    pictures = reference()
    assert len(pictures) == 3 * len(TABLE["cases"]) == 57
    for name, expected in pictures.items():
        case, step = name.rsplit(".", 1)
        mine = picture(Path(folder) / f"{case}.{step}.{TABLE['cases'][case]['suffix']}")
        assert mine.shape == expected.shape, name
        differ = np.count_nonzero(np.any(mine != expected, axis=2))
        assert differ == 0, f"{name}: {differ} pixels differ from LIGGGHTS's"


def test_every_picture_is_liggghts_pixel_for_pixel(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for script in TABLE["scripts"].values():
        sim = Simulation(screen=False, log=None, dialect="liggghts")
        sim.command(script)
        sim.close()
    assert_pictures_are_liggghts(tmp_path)
    # LIGGGHTS's libjpeg at quality 85 and Pillow's write the same bytes
    mine = picture(tmp_path / "jpeg.0.jpg")
    assert np.array_equal(mine, reference()["jpeg.0"])


def test_two_ranks_draw_the_same_pictures(tmp_path):
    for name, script in TABLE["scripts"].items():
        run_ranks(script, 2, tmp_path, name=f"in.{name}", dialect="liggghts")
    assert_pictures_are_liggghts(tmp_path)


def test_the_recorded_pictures_show_the_scene():
    """The references are not blank: each shows spheres (more than 5 % of the picture differs
    from the background), and the three pictures of a case differ as the bed falls."""
    pictures = reference()
    for case, entry in TABLE["cases"].items():
        steps = (0, 200, 400) if entry["script"] == "bed" else (0, 100, 200)
        frames = [pictures[f"{case}.{step}"] for step in steps]
        background = frames[0][0, 0]
        assert np.mean(np.any(frames[0] != background, axis=2)) > 0.05, case
        assert not np.array_equal(frames[0], frames[2]), case
