"""The public API of pdps_core: everything a plugin or a Python user may import.

Plugins import from here only; anything else in pdps_core may change without notice.
"""

from .contact import ContactHistory, close_slot, find_slot, open_slot
from .commands.words import type_range
from .errors import ScriptError, SimulationError
from .neighbor.neighbor import NeighborList
from .random import pair_gaussian, particle_gaussians, particle_uniforms, philox4x32
from .run.hookspec import HOOKS
from .simulation import Simulation
from .state import observables
from .styles import (API_VERSION, Analyze, Compute, Dump, Fix, FloatOrVariable, Pair, PairLaw, Region, StyleArgs, VariableRef, keyword,
                     param, parse_args, peratom_column, registry)

__all__ = ["API_VERSION", "Analyze", "ContactHistory", "close_slot", "find_slot", "open_slot", "Compute", "Dump", "Fix", "FloatOrVariable", "HOOKS", "NeighborList", "Pair", "PairLaw", "Region",
           "ScriptError", "SimulationError", "Simulation", "StyleArgs", "VariableRef", "keyword", "observables", "param",
           "pair_gaussian", "particle_gaussians", "particle_uniforms", "parse_args", "peratom_column", "philox4x32", "registry", "type_range"]
