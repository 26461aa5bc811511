"""Dump ``movie``: dump image's pictures as the frames of one movie file, encoded by FFmpeg.

Syntax::

    dump ID GROUP movie N FILE COLOR DIAMETER [keyword value ...]

Everything of dump image (image.py) but the file: FILE is one movie, without ``*`` or ``%`` and
not ``.gz``; its suffix chooses FFmpeg's format and codec (``.mp4``, ``.avi``, ``.mkv``, ``.mpg``,
``.m4v``, ``.mov``, ``.flv``, ``.gif``, ``.apng``, ...). As LIGGGHTS's dump movie, rank
0 pipes each picture as a PPM into (LIGGGHTS 3.8.0's command line, from its source)::

    ffmpeg -v error -y -r FRAMERATE -f image2pipe -c:v ppm -i - -r 24.0 -b:v BITRATEk FILE

so the movie plays at 24 frames a second, each picture held for 24 / FRAMERATE of them.
dump_modify ``framerate F`` (pictures a second, above 0.1 and at most 24; 24) and ``bitrate K``
(kbit/s, a whole number > 0; 2000; formats without a bit rate ignore it), beside dump image's.

The ffmpeg is the one the imageio-ffmpeg package ships (a dependency of this plugin; the variable
IMAGEIO_FFMPEG_EXE names another), so no FFmpeg of the system's is needed. The movie is complete
when the dump is closed (undump, clear, or the end of the script). LIGGGHTS 3.8.0 here was built
without FFmpeg ("Cannot generate movie file"), and refuses every keyword after COLOR DIAMETER on a
dump movie line (its dump custom's check names only image: measured); pdps reads them, as the
manual says.

Example::

    dump film all movie 100 grains.mp4 type diameter size 640 480 view 70 30
    dump_modify film framerate 12 bitrate 4000
"""

import os
import re
import subprocess
import tempfile

from pdps_core.api import ScriptError, SimulationError

from .image import DumpImage, ppm_bytes


def ffmpeg():
    """The ffmpeg imageio-ffmpeg ships (or IMAGEIO_FFMPEG_EXE's)."""
    import imageio_ffmpeg              # only a movie needs it
    return imageio_ffmpeg.get_ffmpeg_exe()


class DumpMovie(DumpImage):
    name = "movie"
    usage = "dump ID GROUP movie N FILE.mp4|avi|mkv|... COLOR DIAMETER [keyword value ...]"

    def __init__(self, sim, id, group, args):
        self.framerate, self.bitrate = 24.0, 2000
        self.encoder = self.errors = None
        super().__init__(sim, id, group, args)
        self.kind = "ppm"

    def check_file(self, sim, path):
        if "*" in path or "%" in path or path.endswith(".gz"):
            raise ScriptError(f"dump movie writes one movie file: {path} may have no * or % and not end in .gz")
        if sim.comm.is_root:
            self._probe(path)

    def _probe(self, path):
        """Encode one small frame into a file beside ``path`` with the same suffix: a format FFmpeg
        cannot write, or a folder that cannot be written, is refused here at the dump line, not after
        the run."""
        folder, name = os.path.split(path)
        suffix = name[name.index("."):] if "." in name else ""
        try:
            handle, probe = tempfile.mkstemp(prefix=".pdps-probe-", suffix=suffix, dir=folder or ".")
            os.close(handle)
        except OSError as exc:
            raise ScriptError(f"cannot open movie file {path}: {exc.strerror}") from None
        command = [ffmpeg(), "-v", "error", "-y", "-f", "image2pipe", "-c:v", "ppm", "-i", "-", probe]
        try:
            done = subprocess.run(command, input=b"P6\n16 16\n255\n" + bytes(768), capture_output=True, timeout=60)
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise ScriptError(f"ffmpeg ({command[0]}) does not run: {exc}") from None
        finally:
            if os.path.exists(probe):
                os.remove(probe)
        if done.returncode != 0:
            lines = done.stderr.decode(errors="replace").replace(probe, path).strip().splitlines()
            first = re.sub(r"^\[[^]]*@ 0x[0-9a-f]+\] ", "", lines[0]) if lines else f"exit code {done.returncode}"
            raise ScriptError(f"ffmpeg cannot write the movie {path}: {first}")

    def modify_words(self, sim, keyword, rest):
        if keyword in ("framerate", "bitrate"):
            return 1
        return super().modify_words(sim, keyword, rest)

    def modify(self, sim, keyword, values):
        if keyword == "bitrate":
            try:
                bitrate = int(values[0])
            except ValueError:
                raise ScriptError(f"bitrate must be a whole number of kbit/s (got {values[0]})") from None
            if bitrate <= 0:
                raise ScriptError(f"bitrate must be > 0 (got {values[0]})")
            self.bitrate = bitrate
        elif keyword == "framerate":
            try:
                framerate = float(values[0])
            except ValueError:
                raise ScriptError(f"framerate must be a number (got {values[0]})") from None
            if not 0.1 < framerate <= 24.0:
                raise ScriptError(f"framerate must be above 0.1 and at most 24 (got {values[0]})")
            self.framerate = framerate
        else:
            super().modify(sim, keyword, values)

    def command(self):
        """The ffmpeg command line, as LIGGGHTS's."""
        return [ffmpeg(), "-v", "error", "-y", "-r", f"{self.framerate:.2f}", "-f", "image2pipe", "-c:v", "ppm",
                "-i", "-", "-r", "24.0", "-b:v", f"{self.bitrate}k", self.path]

    def write(self, sim):
        rows = self.render(sim)
        self.frames += 1
        if rows is None:
            return
        if self.encoder is None:
            self.errors = tempfile.TemporaryFile()
            try:
                self.encoder = subprocess.Popen(self.command(), stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                                stderr=self.errors)
            except OSError as exc:
                raise SimulationError(f"dump {self.id}: cannot start ffmpeg for {self.path}: {exc.strerror}") from None
        try:
            self.encoder.stdin.write(ppm_bytes(rows))
            self.encoder.stdin.flush()
        except (BrokenPipeError, OSError):
            raise SimulationError(f"dump {self.id}: ffmpeg stopped writing {self.path}: {self._finish()}") from None

    def _finish(self):
        """Close ffmpeg's input and wait for it; its error text, or '' when it succeeded."""
        encoder, self.encoder = self.encoder, None
        try:
            encoder.stdin.close()
        except OSError:
            pass
        code = encoder.wait()
        self.errors.seek(0)
        text = self.errors.read().decode(errors="replace").strip()
        self.errors.close()
        if code == 0:
            return ""
        return " ".join(text.split()) or f"ffmpeg exited with code {code}"

    def close(self):
        if self.encoder is not None:
            message = self._finish()
            if message:
                # the script has ended or dropped the dump: a warning, which the other dumps' closing survives
                self.sim.warn(f"dump {self.id}: ffmpeg could not write {self.path}: {message}")
