"""The style contract (pdps_core.api.CONTRACT) holds: every plugin under plugins/ reads of ``sim``,
and of what hangs off it, only what the contract names; every name the contract gives exists; the
plugin guide shows each of them."""

import ast
import pathlib
import re
import tomllib

import pytest

from pdps_core.api import CONTRACT, Simulation, registry

ROOT = pathlib.Path(__file__).parents[1]
# attributes of sim whose value is another contract object
HANDED = {"particles": "Particles", "box": "Box", "comm": "Comm", "groups": "Groups", "units": "Units",
          "neighbor": "Neighbor", "pair_list": "NeighborList", "variables": "Variables", "pair": "Pair"}


def chain(node):
    parts = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        return [node.id] + parts[::-1]
    return None


def sim_chain(node):
    """['x', ...] for sim.x... or self.sim.x..., else None."""
    parts = chain(node)
    if not parts:
        return None
    if parts[0] == "sim":
        return parts[1:]
    if parts[:2] == ["self", "sim"]:
        return parts[2:]
    return None


def uses(path):
    """(object, attribute, line) for every read of a contract object in one module."""
    tree = ast.parse(path.read_text())
    found = []
    for function in ast.walk(tree):
        if not isinstance(function, ast.FunctionDef):
            continue
        alias = {a.arg: "NeighborList" for a in function.args.args if a.arg == "nlist"}
        for node in ast.walk(function):
            if isinstance(node, ast.Assign):
                targets, values = node.targets[0], node.value
                pairs = []
                if isinstance(targets, ast.Tuple) and isinstance(values, ast.Tuple):
                    pairs = list(zip(targets.elts, values.elts))
                else:
                    pairs = [(targets, values)]
                for target, value in pairs:
                    if isinstance(target, ast.Name):
                        c = sim_chain(value)
                        if c and len(c) == 1 and c[0] in HANDED:
                            alias[target.id] = HANDED[c[0]]
        for node in ast.walk(function):
            if not isinstance(node, ast.Attribute) or isinstance(getattr(node, "ctx", None), ast.Store):
                continue
            c = sim_chain(node)
            if c is not None:
                if not c:
                    continue
                if len(c) == 1:
                    found.append(("Simulation", c[0], node.lineno))
                elif c[0] in HANDED and len(c) == 2:
                    found.append((HANDED[c[0]], c[1], node.lineno))
                continue
            parts = chain(node)
            if parts and len(parts) == 2 and parts[0] in alias:
                found.append((alias[parts[0]], parts[1], node.lineno))
    return found


def plugin_modules():
    return sorted(ROOT.glob("plugins/*/pdps_*/**/*.py"))


def provides_pair(path):
    """Attributes of sim.pair beyond the contract are the plugin's own business when its own
    distribution provides pair styles (fix shardlow reads pair dpd/fdt's tables)."""
    pyproject = ROOT / "plugins" / path.relative_to(ROOT).parts[1] / "pyproject.toml"
    return '"pdps.pair"' in pyproject.read_text()


def test_the_scanner_sees_reads_through_aliases():
    source = ("def f(self, sim, nlist):\n    p, box = sim.particles, sim.box\n    p.secret\n"
              "    self.sim.hidden\n    nlist.offsets\n    sim.comm.world\n")
    path = ROOT / "build" / "scanner_probe.py"
    path.parent.mkdir(exist_ok=True)
    path.write_text(source)
    try:
        seen = {(kind, name) for kind, name, _ in uses(path)}
    finally:
        path.unlink()
    assert {("Particles", "secret"), ("Simulation", "hidden"), ("NeighborList", "offsets"),
            ("Comm", "world")} <= seen


def test_plugins_read_only_what_the_contract_names():
    outside = []
    for path in plugin_modules():
        for kind, name, line in uses(path):
            if name in CONTRACT[kind] or (kind == "Pair" and provides_pair(path)):
                continue
            outside.append(f"{path.relative_to(ROOT)}:{line}: {kind}.{name}")
    assert not outside, "reads outside the style contract:\n" + "\n".join(outside)
    assert len(plugin_modules()) > 40


def test_every_name_in_the_contract_exists(tmp_path):
    (tmp_path / "pair.mol").write_text("two spheres\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 1 0 0\n\nTypes\n\n1 1\n2 1\n")
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        particle_style sphere
        region box block 0 5 0 5 0 5
        create_box 1 box
        create_particle 1 single 1 1 1
        create_particle 1 single 2 1 1
        variable a equal 1
        pair_style dem/lsd 0.3 1.0
        pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1
        molecule pair {tmp_path / 'pair.mol'}
        run 0
    """)
    objects = {"Simulation": sim, "Particles": sim.particles, "Box": sim.box, "Comm": sim.comm,
               "Groups": sim.groups, "Units": sim.units, "Neighbor": sim.neighbor,
               "NeighborList": sim.pair_list, "Variables": sim.variables, "Pair": sim.pair,
               "MoleculeTemplate": sim.molecule_template("pair")}
    assert set(objects) == set(CONTRACT)
    missing = [f"{kind}.{name}" for kind, names in CONTRACT.items() for name in names
               if not hasattr(objects[kind], name)]
    # molecule ids and charges exist with the particle styles that have them, not with sphere
    full = Simulation(screen=False, log=None)
    full.command("particle_style full\nregion box block 0 5 0 5 0 5\ncreate_box 1 box")
    # body_mass exists where a fix of rigid bodies provides it
    # bonds' arrays exist in a scene with bonds
    assert missing == ["Particles.molecule", "Particles.q", "Particles.body_mass", "Particles.num_bond",
                       "Particles.bond_type", "Particles.bond_atom", "Particles.nspecial", "Particles.special"]
    assert hasattr(full.particles, "molecule") and hasattr(full.particles, "q")
    (tmp_path / "bonded.data").write_text("two bonded\n\n2 atoms\n1 atom types\n1 bonds\n1 bond types\n\n"
                                          "0 5 xlo xhi\n0 5 ylo yhi\n0 5 zlo zhi\n\nMasses\n\n1 1\n\n"
                                          "Atoms # bond\n\n1 1 1 1 1 1\n2 1 1 2 1 1\n\nBonds\n\n1 1 1 2\n")
    bonded = Simulation(screen=False, log=None)
    bonded.command(f"particle_style bond\nread_data {tmp_path / 'bonded.data'}")
    assert all(hasattr(bonded.particles, name) for name in ("num_bond", "bond_type", "bond_atom", "nspecial", "special"))
    # contacts(sim, group) is the ContactTable capability: LIGGGHTS's gran and the dem styles have it
    from pdps_core.api import ContactTable
    assert isinstance(sim.pair, ContactTable)
    assert all(issubclass(registry.lookup("pair", name), ContactTable)
               for name in ("gran", "dem/hertz", "dem/lsd"))
    assert not issubclass(registry.lookup("pair", "lj/cut"), ContactTable)


def test_the_plugin_guide_shows_every_name():
    code, inside = [], None
    for line in (ROOT / "docs" / "plugin-guide.md").read_text().splitlines():
        if line.startswith("```"):
            inside = None if inside is not None else line[3:].strip()
        elif inside in ("", "python"):
            code.append(line)
    code = "\n".join(code)
    import pdps_core.api as api
    absent = [name for name in api.__all__ if name not in code]
    absent += [f"{kind}.{name}" for kind, names in CONTRACT.items() for name in names
               if not re.search(rf"\.{name}\b", code)]
    assert not absent, f"docs/plugin-guide.md has no example for: {', '.join(absent)}"


KIT_FIXTURES = {"make_sim", "pdps_cli"}


def uses_the_kit(path):
    """True when a test module imports from pdps_core.testing or takes one of its fixtures."""
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.module == "pdps_core.testing":
            return True
        if isinstance(node, ast.Import) and any(a.name == "pdps_core.testing" for a in node.names):
            return True
        if isinstance(node, ast.FunctionDef) and KIT_FIXTURES & {a.arg for a in node.args.args}:
            return True
    return False


def provides_styles(folder):
    """A plugin declares styles (pdps.* entry points); a library distribution such as
    granular_contact declares none, and its tests call its functions without a simulation."""
    project = tomllib.loads((folder / "pyproject.toml").read_text())["project"]
    return any(group.startswith("pdps.") for group in project.get("entry-points", {}))


def test_every_plugin_uses_the_test_kit():
    plugins = sorted(p.parent for p in ROOT.glob("plugins/*/tests") if provides_styles(p.parent))
    assert len(plugins) > 10
    without = [p.name for p in plugins
               if not any(uses_the_kit(m) for m in (p / "tests").rglob("*.py"))]
    assert not without, f"plugins whose tests use nothing of pdps_core.testing: {', '.join(without)}"
