"""``pdps new-plugin NAME --kind KIND [--style STYLE]``: write a working, tested plugin to start from.

Each kind gets a complete distribution: ``pyproject.toml`` with the entry point, a package whose
``__init__.py`` declares the style API range it supports (``PDPS_API``), one module holding the
style (a docstring with the physics, the syntax and an example; ``Args`` declared with ``param``
and the kind of quantity of each parameter) and tests that pass as written:

- fix: adds a velocity increment to a group each step (the example of docs/plugin-guide.md);
- compute: the kinetic energy of each particle, and its sum over ranks;
- region: a sphere (``inside``, ``bounds``);
- dump: positions in the xyz format;
- pair: a soft harmonic repulsion as a force law in the core's pair loop (per-type tables,
  energy, mixing), tested against finite differences of its energy;
- contact: a cohesion sub-model of LIGGGHTS's granular contacts (a constant pull while bodies
  touch, from a material property of its own), composed by pdps_granular_contact into pair gran
  and fix wall/gran (``cohesion STYLE``), tested against Hertz's force less the pull.

NAME names the distribution (``pdps-KIND-NAME``) and the package (``pdps_KIND_NAME``); STYLE (default
NAME) is the name scripts use and may contain ``/`` (``lj/cut``: module ``lj_cut.py``).
"""

import re
from pathlib import Path
from importlib.resources import files
from string import Template

from .errors import ScriptError
from .styles import API_VERSION

KINDS = ("pair", "fix", "compute", "region", "dump", "contact")
API_RANGE = f">={API_VERSION},<{int(API_VERSION.split('.')[0]) + 1}"


# The plugin's files, as string.Template texts ($style, $module, $cls, ...): pdps_core/plugin_templates,
# data of this package rather than code of it (a template reads like the plugin it makes)
TEMPLATE_FOLDER = files("pdps_core") / "plugin_templates"
# kind -> (module template, test template, base class)
TEMPLATES = {"fix": ("fix", "fix_test", "Fix"), "compute": ("compute", "compute_test", "Compute"),
             "region": ("region", "region_test", "Region"), "dump": ("dump", "dump_test", "Dump"),
             "pair": ("pair", "pair_test", "Pair"), "contact": ("contact", "contact_test", "Cohesion")}
# the entry-point group (pdps.GROUP), what the plugin holds and the distributions it needs, where a
# kind is not a style of its own
GROUPS = {"contact": ("gran.cohesion", "cohesion sub-model", '"pdps-core", "pdps-granular-contact", "numba"')}


def template(name, ext="py"):
    return Template((TEMPLATE_FOLDER / f"{name}.{ext}.tmpl").read_text())


EXAMPLES = {"fix": "fix ID GROUP {style} DVX DVY DVZ", "compute": "compute ID GROUP {style}",
            "region": "region ID {style} XC YC ZC RADIUS", "dump": "dump ID GROUP {style} N FILE",
            "pair": "pair_style {style} RC",
            "contact": "pair_style gran model hertz tangential history cohesion {style}"}

NAME = re.compile(r"[a-z][a-z0-9_]*(/[a-z0-9_]+)*")
# a style name as scripts spell it: LIGGGHTS's have capitals (dump mesh/gran/VTK)
STYLE = re.compile(r"[A-Za-z][A-Za-z0-9_]*(/[A-Za-z0-9_]+)*")


def new_plugin(name, directory="plugins", kind="fix", style=None):
    """Write the plugin; returns (its folder, the script line that uses its style)."""
    if kind not in TEMPLATES:
        raise ScriptError(f"kind must be one of {', '.join(KINDS)} (got {kind})")
    if not NAME.fullmatch(name):
        raise ScriptError(f"plugin name must be lower-case letters, digits, _ and / (got {name})")
    style = style or name
    if not STYLE.fullmatch(style):
        raise ScriptError(f"style name must be letters, digits, _ and / (got {style})")
    ident = name.replace("/", "_")
    root = Path(directory) / f"{kind}_{ident}"
    if root.exists():
        raise ScriptError(f"{root} already exists")
    module_name, test_name, prefix = TEMPLATES[kind]
    module = style.replace("/", "_").lower()
    group, what, dependencies = GROUPS.get(kind, (kind, f"{kind} style", '"pdps-core"'))
    values = dict(kind=kind, style=style, module=module, package=f"pdps_{kind}_{ident}", group=group, what=what,
                  dependencies=dependencies,
                  dist=f"pdps-{kind}-{ident.replace('_', '-')}", api_range=API_RANGE,
                  cls=prefix + "".join(part.capitalize() for part in module.split("_")))
    package = root / values["package"]
    package.mkdir(parents=True)
    (root / "tests").mkdir()
    (root / "pyproject.toml").write_text(template("pyproject", "toml").substitute(values))
    (package / "__init__.py").write_text(template("init").substitute(values))
    (package / f"{module}.py").write_text(template(module_name).substitute(values))
    (root / "tests" / f"test_{module}.py").write_text(template(test_name).substitute(values))
    return root, EXAMPLES[kind].format(style=style)
