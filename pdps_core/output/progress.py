"""Progress of a long run: percent done, steps per second and time left, on stderr.

On a terminal one line is rewritten in place (``\\r``), from one second into a run, at most twice a
second; it is cleared before anything else goes to the screen and at the end of the run, so the
thermo table on screen stays whole. Otherwise (a pipe, a batch job's file) plain lines: one when the
run passes a further 10 % mark, but no more often than every 30 s (so a run shorter than that prints
none), and one at least every 10 minutes when marks are far apart. Example::

    progress:  45% (step 4500 of 10000), 1234 steps/s, 0:00:04 left

stderr, not stdout: the screen copy of the thermo table (``pdps run in.x > out.txt``) stays clean,
and progress never reaches the log. Off with ``pdps run --no-progress`` and for
``Simulation(screen=False)``. The clock is a parameter, so the schedule is tested without waiting.
"""

import sys
import time

TTY_DELAY = 1.0         # s into a run before the first in-place line: short runs show none
TTY_EVERY = 0.5         # s between in-place redraws
PLAIN_EVERY = 30.0      # s: plain lines at most this often, the first no earlier
PLAIN_MARK = 10         # percent between plain lines
PLAIN_HEARTBEAT = 600.0 # s: a plain line at least this often


def clock_text(seconds):
    """``H:MM:SS`` (``Dd HH:MM:SS`` from a day on)."""
    seconds = int(round(max(seconds, 0.0)))
    days, seconds = divmod(seconds, 86400)
    hours, seconds = divmod(seconds, 3600)
    minutes, seconds = divmod(seconds, 60)
    if days:
        return f"{days}d {hours:02d}:{minutes:02d}:{seconds:02d}"
    return f"{hours}:{minutes:02d}:{seconds:02d}"


def progress_text(step, first, last, elapsed):
    """The progress line for a run from step ``first`` to ``last`` now at ``step``, ``elapsed``
    seconds in. The percentage is rounded down: 100 % only when the run is done."""
    done, total = step - first, last - first
    percent = 100 * done // total if total > 0 else 100
    rate = done / elapsed if elapsed > 0 else 0.0
    left = clock_text((last - step) / rate) if rate > 0 else "?"
    return f"progress: {percent:3d}% (step {step} of {last}), {rate:.4g} steps/s, {left} left"


class Progress:
    def __init__(self, stream=None, clock=time.monotonic, tty=None):
        """``stream``: where lines go (default: sys.stderr as it is when written); ``clock``:
        seconds, monotonic; ``tty``: force in-place (True) or plain (False) lines."""
        self._stream = stream
        self.clock = clock
        self._tty = tty
        self.active = False
        self.width = 0              # characters of the in-place line now on screen
        self.seen = False           # an in-place line was shown during this run

    @property
    def stream(self):
        return self._stream if self._stream is not None else sys.stderr

    def _is_tty(self):
        if self._tty is not None:
            return self._tty
        try:
            return self.stream.isatty()
        except (AttributeError, ValueError):
            return False

    def start(self, first, last):
        self.first, self.last = first, last
        self.active = last > first
        self.tty = self._is_tty()
        self.t0 = self.last_line = self.clock()
        self.mark = 0
        self.seen = False
        self.width = 0

    def update(self, step):
        if not self.active:
            return
        if step >= self.last:
            self.finish()
            return
        now = self.clock()
        elapsed = now - self.t0
        if self.tty:
            # redrawn at once after other output cleared it, so it stays under the thermo lines
            if (self.seen and self.width == 0) or (
                    elapsed >= TTY_DELAY and now - self.last_line >= TTY_EVERY):
                self._draw(progress_text(step, self.first, self.last, elapsed), now)
            return
        since = now - self.last_line
        mark = (100 * (step - self.first) // (self.last - self.first)) // PLAIN_MARK
        if since >= PLAIN_EVERY and (mark > self.mark or since >= PLAIN_HEARTBEAT):
            self.mark = mark
            self.last_line = now
            print(progress_text(step, self.first, self.last, elapsed), file=self.stream, flush=True)

    def _draw(self, text, now):
        pad = " " * max(self.width - len(text), 0)
        self.stream.write("\r" + text + pad)
        self.stream.flush()
        self.width = len(text)
        self.seen = True
        self.last_line = now

    def clear(self):
        """Remove the in-place line (before other output, at the end of a run or on an error)."""
        if self.width:
            self.stream.write("\r" + " " * self.width + "\r")
            self.stream.flush()
            self.width = 0

    def finish(self):
        self.clear()
        self.active = False
