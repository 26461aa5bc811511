"""benchmarks/corpus_lammps.py's rules (make corpus): LAMMPS's seeds found by command and replaced,
through the variable that holds one too; long runs cut alike; thermo rows read by column name without
the clock's, each run's apart; the row where two runs part beyond LAMMPS's printed digits."""

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
spec = importlib.util.spec_from_file_location("corpus_lammps", ROOT / "benchmarks" / "corpus_lammps.py")
tool = importlib.util.module_from_spec(spec)
spec.loader.exec_module(tool)

SCRIPT = """variable seed equal 4928
variable n equal 20000
velocity all create 1.0 87287 loop geom
fix 2 all langevin 1.0 1.0 0.1 ${seed}   # a comment stays
pair_style hybrid/overlay lj/cut 2.5 dpd/tstat 1.0 1.0 2.5 34387
run 100
run ${n}
run 8000 every 100
"""


def test_seeds_are_found_by_command_and_through_variables():
    places = tool.seed_places(SCRIPT.splitlines())
    assert places == [(2, 4), (0, 3), (4, 8)]
    new = tool.prepared(SCRIPT, 1, 5000).splitlines()
    primes = [str(p) for p in tool.seed_set(1, 3)]
    assert new[2] == f"velocity all create 1.0 {primes[0]} loop geom"
    assert new[0] == f"variable seed equal {primes[1]}"
    assert new[3] == "fix 2 all langevin 1.0 1.0 0.1 ${seed}   # a comment stays"
    assert new[4].split()[-1] == primes[2]
    assert tool.prepared(SCRIPT, 0, 5000).splitlines()[2] == "velocity all create 1.0 87287 loop geom"


def test_long_runs_are_cut_and_short_ones_kept():
    lines = tool.prepared(SCRIPT, 0, 5000).splitlines()
    assert lines[1] == "variable n equal 5000"
    assert lines[5:8] == ["run 100", "run ${n}", "run 5000 every 100"]
    assert tool.prepared(SCRIPT, 0, None).splitlines()[1] == "variable n equal 20000"


def test_a_run_length_worked_out_from_variables_is_cut_at_the_run_line():
    script = """variable dt equal 0.007
variable tprod equal 5000
variable Nprod equal floor(${tprod}/${dt})
variable short equal ${tprod}/10
variable unknown equal v_x*1000000
run ${Nprod}
run ${short}
run ${unknown}
"""
    lines = tool.prepared(script, 0, 5000).splitlines()
    assert lines[2] == "variable Nprod equal floor(${tprod}/${dt})"
    assert lines[5:8] == ["run 5000", "run ${short}", "run ${unknown}"]


def test_thermo_rows_by_name_without_the_clock():
    screen = """   Step          Temp          CPU           Press
         0   1.5            0             -4.97
       100   0.75           0.0215        0.73
Loop time of 0.07 on 1 procs for 100 steps with 256 atoms
   Step          Temp          CPU           Press
       100   0.76           0.0300        0.74
"""
    assert tool.thermo(screen) == {"1:0": {"Temp": 1.5, "Press": -4.97}, "1:100": {"Temp": 0.75, "Press": 0.73},
                                   "2:100": {"Temp": 0.76, "Press": 0.74}}


def test_runs_part_beyond_one_unit_of_the_eighth_digit():
    one = {"rows": {"1:0": {"Temp": 1.2345678}, "1:50": {"Temp": 0.98765432}, "2:0": {"Temp": 0.5}}}
    close = {"rows": {"1:0": {"Temp": 1.2345679}, "1:50": {"Temp": 0.98765433}, "2:0": {"Temp": 0.5000002}}}
    assert tool.parting(one, close) == ("2:0", "Temp", 0.5, 0.5000002, 2)
    assert tool.parting(one, one)[0] is None


def test_a_flagged_script_is_measured_again_on_more_seed_sets(monkeypatch):
    import numpy as np
    generator = np.random.default_rng(5)

    def fake_run(command, examples, script, k, steps, timeout, label):
        # pdps's runs sit 0.5 standard deviations off LAMMPS's: no real difference the larger test sees
        shift = 0.5 if label == "pdps" else 0.0
        rows = {f"1:{s}": {"Temp": 1.0 + shift + float(generator.normal())} for s in (0, 100, 200)}
        return {"ok": True, "rows": rows, "label": label, "k": k}

    monkeypatch.setattr(tool, "run_script", fake_run)
    entry = {"reference": [fake_run(None, None, None, k, 0, 0, "lammps") for k in range(5)],
             "pdps": [fake_run(None, None, None, k, 0, 0, "pdps") for k in (0, 100, 101)], "twin": None}
    tool.confirm(entry, ["lmp"], ["pdps"], None, "x/in.x", 5000, 60)
    assert [run["k"] for run in entry["reference"]] == list(range(10))
    assert [run["k"] for run in entry["pdps"]] == [0, 100, 101, 102, 103]
    how, _, detail = entry["agreement"]
    assert how == "statistics" and "of the 1001 choices of 4 of 14 runs" in detail


def test_seeds_after_keywords_are_found():
    script = """velocity all create 0.45 2349852
fix 5 solute rigid/small molecule langevin 0.45 0.45 0.5 112211
fix 6 all bond/create 10 1 1 1.0 1 prob 0.5 8834
set type 1 type/fraction 2 0.3 4821
"""
    lines = tool.prepared(script, 1, 5000).splitlines()
    assert [line.split()[-1] for line in lines] != ["2349852", "112211", "8834", "4821"]
    assert all(line.split()[-1].isdigit() for line in lines)
    assert [place for place in tool.seed_places(script.splitlines())] == [(0, 4), (1, 9), (2, 11), (3, 6)]
