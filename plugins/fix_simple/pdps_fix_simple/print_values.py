r"""Fix ``print``: every N steps, a line of text with its variables substituted then (LAMMPS's fix
print), on the screen and in the log, or to a file.

Syntax::

    fix ID GROUP print N "TEXT" [file FILE | append FILE] [screen yes|no] [title TEXT]

N the interval (steps); TEXT in quotes, with ``$x``, ``${name}`` and ``$(formula)`` replaced on each
printing step (so ``$(temp)`` is the temperature then). ``file`` starts FILE afresh (with the title
line, default ``# Fix print output for fix ID``), ``append`` adds to it.

As LAMMPS: a line is printed at each run's first step too when it is a multiple of N (so a step
ending one run and starting the next is printed twice), and the steps it prints on compute the
energy and virial its text may read (``$(pe)``, ``$(press)``, variables), thermo step or not.

Example::

    fix p all print 100 "step $(step) T $(temp:%.4f)" file temp.txt screen no
"""

from typing import Literal

from pydantic import model_validator

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param


class FixPrint(Fix):
    name = "print"
    usage = 'fix ID GROUP print N "TEXT" [file FILE | append FILE] [screen yes|no] [title TEXT]'

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        text: str = param()
        file: str | None = keyword(None)
        append: str | None = keyword(None)
        screen: Literal["yes", "no"] = keyword("yes")
        title: str | None = keyword(None)

        @model_validator(mode="after")
        def _one_file(self):
            if self.file is not None and self.append is not None:
                raise ValueError(f"give file or append, not both (got file {self.file} append {self.append})")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.text = args.text
        named = args.file if args.file is not None else args.append
        self.path = None if named is None else sim.resolve(named)
        mode = "a" if args.append is not None else "w"
        self.screen = args.screen == "yes"
        title = args.title if args.title is not None else f"# Fix print output for fix {id}"
        self.handle = None
        if self.path is not None and sim.comm.is_root:
            try:
                self.handle = open(self.path, mode)
            except OSError as exc:
                raise ScriptError(f"cannot open fix print file {self.path}: {exc.strerror}") from None
            if mode == "w":
                self.handle.write(title + "\n")
                self.handle.flush()

    def needs(self, step):
        # a substitution may read anything (pe, press, a variable of them), as thermo assumes
        return {"energy", "virial"} if step % self.args.every == 0 and "$" in self.text else set()

    def setup(self, sim):
        if sim.dialect.print_at_setup:
            self.end_of_step(sim)

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        line = sim.substitute(self.text)
        if self.screen:
            sim.info(line)
        if self.handle is not None:
            self.handle.write(line + "\n")
            self.handle.flush()

    def post_run(self, sim):
        if self.handle is not None:
            self.handle.flush()
