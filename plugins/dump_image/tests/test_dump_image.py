"""dump image beyond LIGGGHTS's pictures: the file formats, the color maps as the dump_modify page
defines them, the RanMars generator against its published test, and the one-line refusals."""

import gzip
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from pdps_core.api import ScriptError, Simulation
from pdps_dump_image import render
from pdps_dump_image.colors import COLORS, ColorMap, Palette
from pdps_dump_image.ranmars import RanMars

DATA = Path(__file__).parent / "data"
TABLE = json.loads((DATA / "liggghts_images.json").read_text())


def scene(tmp_path, monkeypatch, dialect="liggghts"):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect=dialect)
    sim.command(TABLE["scene"])
    return sim


def ppm(path):
    data = Path(path).read_bytes() if not str(path).endswith(".gz") else gzip.decompress(Path(path).read_bytes())
    header, width_height, depth, pixels = data.split(b"\n", 3)
    width, height = map(int, width_height.split())
    assert (header, depth, len(pixels)) == (b"P6", b"255", 3 * width * height)
    return np.frombuffer(pixels, dtype=np.uint8).reshape(height, width, 3)


def test_png_and_gzipped_ppm_hold_the_ppm_picture(tmp_path, monkeypatch):
    sim = scene(tmp_path, monkeypatch)
    for name, suffix in (("a", "ppm"), ("b", "png"), ("c", "PNG"), ("d", "ppm.gz")):
        sim.command(f"dump {name} all image 1 {name}.*.{suffix} type diameter size 64 48 zoom 1.5")
    sim.command("run 0")
    sim.close()
    picture = ppm(tmp_path / "a.0.ppm")
    assert np.array_equal(picture, np.asarray(Image.open(tmp_path / "b.0.png")))
    assert np.array_equal(picture, np.asarray(Image.open(tmp_path / "c.0.PNG")))
    assert np.array_equal(picture, ppm(tmp_path / "d.0.ppm.gz"))
    with np.load(DATA / "liggghts_images.npz") as pictures:      # the default view, at another size
        assert pictures["default.0"].shape == (75, 100, 3) and picture.shape == (48, 64, 3)


def table(words):
    palette = Palette()
    cmap = ColorMap(palette)
    cmap.reset(words.split(), palette)
    return cmap


def colors(cmap, values, lo=None, hi=None):
    if cmap.dynamic:
        cmap.minmax(min(values) if lo is None else lo, max(values) if hi is None else hi)
    out = np.empty((len(values), 3))
    render.map_colors(np.array(values, dtype=float), *cmap.table(), out)
    return out


def rgb(name):
    return np.array(COLORS[name]) / 255.0


def test_a_continuous_map_interpolates_between_its_entries():
    cmap = table("-1.0 1.0 ca 0.0 3 min red 0.5 white max blue")
    got = colors(cmap, [-2.0, -1.0, -0.25, 0.5, 0.75, 3.0])
    expected = [rgb("red"), rgb("red"), rgb("red") + 0.5 * (rgb("white") - rgb("red")), rgb("white"),
                rgb("white") + 0.5 * (rgb("blue") - rgb("white")), rgb("blue")]
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-15)


def test_a_fractional_map_spans_the_values_drawn():
    cmap = ColorMap(Palette())            # the default: min blue .. max red, fractional
    got = colors(cmap, [2.0, 3.0, 6.0])
    np.testing.assert_allclose(got, [rgb("blue"), rgb("blue") + 0.25 * (rgb("red") - rgb("blue")), rgb("red")],
                               atol=1e-15)


def test_a_discrete_map_takes_the_first_entry_that_holds_the_value():
    """As the dump_modify page says (LIGGGHTS 3.8.0 refuses every discrete map: it stores an entry's
    min/max in the wrong slot; measured)."""
    cmap = table("min max da 0.0 3 -1.0 0.0 green -0.5 1.0 orange min max gray")
    got = colors(cmap, [-2.0, -0.75, -0.25, 0.5, 2.0])
    np.testing.assert_allclose(got, [rgb(c) for c in ("gray", "green", "green", "orange", "gray")], atol=0)


def test_a_sequential_map_gives_the_colors_in_turn_over_its_bins():
    cmap = table("0.0 1.0 sa 0.25 3 red green blue")
    got = colors(cmap, [0.0, 0.2, 0.25, 0.6, 0.8, 1.0, 1.5])
    np.testing.assert_allclose(got, [rgb(c) for c in ("red", "red", "green", "blue", "red", "green", "green")],
                               atol=0)


def test_ranmars_gives_the_published_test_numbers():
    """RANMAR's test (F. James, Comp. Phys. Comm. 60 (1990) 329): seeds ij = 1802, kl = 9373, the
    numbers 20001 to 20006 times 2^24. LIGGGHTS's seed is 30082 ij + kl + 1, and its generator has
    drawn the first number when it is made."""
    generator = RanMars(1802 * 30082 + 9373 + 1)
    for _ in range(19999):
        generator.uniform()
    assert [generator.uniform() * 4096.0 * 4096.0 for _ in range(6)] == [
        6533892.0, 14220222.0, 7275067.0, 6172232.0, 8354498.0, 10633180.0]


@pytest.mark.parametrize("line, message", [
    ("dump d all image 1 d.ppm type diameter", "dump image writes one picture per file: put a * (the step) in d.ppm"),
    ("dump d all image 1 nowhere/d.*.ppm type diameter", "cannot write pictures nowhere/d.*.ppm: No such file or "
                                                         "directory"),
    ("dump d all image 1 d.*.ppm type diameter persp 0.5",
     "persp: pdps draws no perspective (LIGGGHTS 3.8.0 refuses persp: \"not yet supported\"; LAMMPS has none); "
     "leave persp out, or give 0"),
    ("dump d all image 1 d.*.ppm type diameter view 200 30", "view: theta must be from 0 to 180 degrees (got 200)"),
    ("dump d all image 1 d.*.ppm type diameter zoom 0", "zoom must be > 0 (got 0.0)"),
    ("dump d all image 1 d.*.ppm type diameter up 0 0 0", "the up vector is zero (up 0 0 0)"),
    ("dump d all image 1 d.*.ppm type diameter size 0 10", "size must be two whole numbers > 0 (got 0 10)"),
    ("dump d all image 1 d.*.ppm type diameter ssao yes 10000 0.5",
     "ssao: LIGGGHTS asks for a seed > 10000 that is a prime number (got 10000); e.g. 15485863, 32452843, 49979687"),
    ("dump d all image 1 d.*.ppm type diameter ssao yes 15485863 1.5",
     "ssao: the strength must be from 0.0 to 1.0 (got 1.5)"),
    ("dump d all image 1 d.*.ppm type density",
     "dump image diameter density is not an attribute pdps reads (type, element, id, mass, xs, ys, zs, xu, "
     "yu, zu, q, radius, diameter, x, y, z, vx, vy, vz, fx, fy, fz, ix, iy, iz, omegax, omegay, omegaz, tqx, tqy, "
     "tqz, c_ID, c_ID[k], f_ID, f_ID[k], v_NAME)"),
    ("dump d all image 1 d.*.ppm type diameter bond atom 0.5", "dump image bond: this box has no bond types"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d acolor 3 red", "type 3 is out of range 1..2"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d acolor 1 nocolor",
     "color nocolor is not a color name (dump_modify color NAME R G B defines one)"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d color mine 0.5 1.2 0", "color mine: R, G and B must be "
                                                                                      "from 0.0 to 1.0 (got 0.5 1.2 0.0)"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d amap min max xf 0 2 min red max blue",
     "amap: style must be c, d or s followed by a or f (got xf)"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d amap min max cf 0 2 0.2 red max blue",
     "amap: a continuous map has 2 entries or more, the first min, the last max"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d amap min max df 0 2 min 0 red 0 1 blue",
     "amap: the last entry of a discrete map must be min max COLOR"),
    ("dump d all image 1 d.*.ppm element diameter\ndump_modify d element O Xx",
     "dump image: Xx is not an element symbol this dump knows (H to Mt)"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d bcolor 1 red", "dump_modify bcolor: this box has no "
                                                                              "bond types"),
    ("dump d all image 1 d.*.ppm type diameter\ndump_modify d element O", "dump_modify element needs 2 value(s) here "
                                                                          "(got 1)"),
])
def test_bad_words_are_refused_at_their_line(tmp_path, monkeypatch, line, message):
    sim = scene(tmp_path, monkeypatch)
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value).split(": ", 2)[-1] == message or str(caught.value).endswith(f": {message}")


def test_any_seed_in_range_serves_in_the_lammps_dialect(tmp_path, monkeypatch):
    """Only LIGGGHTS asks for a prime seed; LAMMPS's RanMars takes 1 to 900000000."""
    sim = scene(tmp_path, monkeypatch, dialect="lammps")
    sim.command("dump d all image 1 d.*.ppm type diameter size 40 30 ssao yes 10000 0.5")
    with pytest.raises(ScriptError, match="ssao: the seed must be from 1 to 900000000"):
        sim.command("dump e all image 1 e.*.ppm type diameter ssao yes 900000001 0.5")
    sim.command("run 0")
    sim.close()
    assert ppm(tmp_path / "d.0.ppm").shape == (30, 40, 3)


def test_dynamic_view_errors_stop_the_run(tmp_path, monkeypatch):
    """A zoom variable that reaches 0 stops the run at the picture that needs it."""
    sim = scene(tmp_path, monkeypatch)
    sim.command("variable z equal 1-step/100\ndump d all image 50 d.*.ppm type diameter size 40 30 zoom v_z")
    with pytest.raises(Exception, match="zoom must be > 0 \\(got 0\\)"):
        sim.command("fix integr all nve/sphere\nrun 100")
    assert sorted(p.name for p in tmp_path.glob("d.*.ppm")) == ["d.0.ppm", "d.50.ppm"]


def test_absurd_sizes_and_distances_draw_at_once(tmp_path, monkeypatch):
    """Spheres a billion boxes wide, a view centred a billion boxes away, zooms of 1e-30 and 1e30 with
    SSAO: each picture is drawn (loops stay within the picture) and nothing is raised; the spheres
    that enclose the camera are not drawn (their surface is behind it, as LIGGGHTS's depth test has
    it), and the far view is empty."""
    sim = scene(tmp_path, monkeypatch)
    sim.command("dump a all image 1 a.*.ppm type diameter size 40 30 box no 0.0 adiam 1e8\n"
                "dump f all image 1 f.*.ppm type diameter size 40 30 center s 1e9 0.5 0.5\n"
                "dump b all image 1 b.*.ppm type diameter size 40 30 zoom 1e-30 ssao yes 15485863 1.0\n"
                "dump c all image 1 c.*.ppm type diameter size 40 30 zoom 1e30 ssao yes 15485863 1.0\n"
                "run 0")
    sim.close()
    assert not np.any(ppm(tmp_path / "f.0.ppm"))
    for name in ("a", "b", "c"):
        assert ppm(tmp_path / f"{name}.0.ppm").shape == (30, 40, 3)


def test_too_many_pixels_are_refused(tmp_path, monkeypatch):
    sim = scene(tmp_path, monkeypatch)
    with pytest.raises(ScriptError, match="size 10000 10000: at most 5e\\+07 pixels"):
        sim.command("dump d all image 1 d.*.ppm type diameter size 10000 10000")
