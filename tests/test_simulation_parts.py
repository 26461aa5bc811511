"""The Simulation is a facade over parts made once, in its constructor: neither it nor a part takes
an attribute its constructor did not make, every slot is set there, and clear() renews the parts a
new simulation needs while the script, the output and the communicator stay."""

import ast
from pathlib import Path

import pytest

from pdps_core.api import Simulation
from pdps_core.simulation import READ_THROUGH

PARTS = ("script", "system", "styles", "run_state")
SCENE = """units lj
lattice fcc 0.8442
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.0 87287
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
compute t all temp
fix 1 all nve
thermo 5
run 10
minimize 1e-4 1e-6 10 100
"""


def every_slot(obj):
    return [slot for cls in type(obj).__mro__ for slot in getattr(cls, "__slots__", ()) if slot != "__weakref__"]


def test_the_simulation_and_its_parts_have_no_attribute_dictionary(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    for obj in (sim, *(getattr(sim, name) for name in PARTS)):
        assert not hasattr(obj, "__dict__"), type(obj).__name__
        with pytest.raises(AttributeError):
            obj.made_later = 1


@pytest.mark.parametrize("when", ["new", "after a run and a minimization", "after clear"])
def test_every_slot_is_set_by_the_constructor_and_stays_set(tmp_path, monkeypatch, when):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    if when != "new":
        sim.command(SCENE)
    if when == "after clear":
        script, output = sim.script, sim.output
        sim.clear()
        assert sim.script is script and sim.output is output and sim.box is None and sim.step == 0
    for obj in (sim, *(getattr(sim, name) for name in PARTS)):
        for slot in every_slot(obj):
            getattr(obj, slot)          # an AttributeError here: a slot its constructor left unset


def test_the_names_read_through_are_the_parts_own_and_read_only(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCENE)
    for part, names in READ_THROUGH.items():
        for name in names:
            kept = getattr(getattr(sim, part), name)
            read = getattr(sim, name)
            assert read is kept or read == kept, (part, name)
            with pytest.raises(AttributeError):
                setattr(sim, name, kept)


def test_simulation_py_stays_a_facade():
    source = Path(__import__("pdps_core.simulation").simulation.__file__).read_text()
    assert len(source.splitlines()) < 300
    # only the constructor (and clear, through _new_state) assigns the facade's slots
    assigning = {node.name for node in ast.walk(ast.parse(source)) if isinstance(node, ast.FunctionDef)
                 and any(isinstance(t, ast.Attribute) and isinstance(t.value, ast.Name) and t.value.id == "self"
                         for a in ast.walk(node) if isinstance(a, ast.Assign) for t in a.targets)}
    assert assigning == {"__init__", "_new_state"}
