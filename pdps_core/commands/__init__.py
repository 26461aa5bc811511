"""The core commands. Each is a function ``(sim, args)`` registered under its name(s) with ``command``;
they parse and validate their words and call into the Simulation, nothing more."""

COMMANDS = {}


def command(*names):
    def register(function):
        for name in names:
            COMMANDS[name] = function
        return function
    return register


from . import (bonds, change_box, control, create_atoms, edit_atoms, geometry, minimize, particles,  # noqa: E402,F401
               info, molecule, read_dump, replicate, restart, settings, setup, styles, velocity)  # (they register)
