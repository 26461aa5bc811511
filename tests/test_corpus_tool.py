"""benchmarks/corpus.py's rules (make corpus): seeds replaced consistently by primes, thermo rows
read from a run's screen, and the verdicts (deterministic to the printed digits, statistical within
the widened range of the reference's seeds) on made-up runs."""

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
spec = importlib.util.spec_from_file_location("corpus", ROOT / "benchmarks" / "corpus.py")
corpus = importlib.util.module_from_spec(spec)
spec.loader.exec_module(corpus)

SCRIPT = """fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015
fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0
fix ins nve_group insert/pack seed 32452843 distributiontemplate pdd1 &
run 1000 # seed 15485863 again in a comment
"""


def test_seeds_are_replaced_by_primes_the_same_wherever_they_appear():
    assert corpus.with_seeds(SCRIPT, 0) == SCRIPT
    new = corpus.with_seeds(SCRIPT, 2)
    primes = corpus.seed_set(2, 3)
    assert all(corpus.is_prime(p) and p > 10_000 for p in primes)
    assert new.count(str(primes[0])) == 2 and "15485863" not in new      # the comment's too
    assert f"discrete {primes[1]} 1" in new and f"seed {primes[2]} " in new
    assert corpus.with_seeds(SCRIPT, 1) != new


def test_thermo_rows_keep_the_first_printing_of_a_step():
    screen = """Step Atoms KinEng c_rke
       0        0            0            0
INFO: Particle insertion ins: inserted 120 particle templates
    1000      120    0.5e-3   1e-5
Loop time of 1.5 on 1 procs for 1000 steps with 120 atoms
Step Atoms KinEng c_rke
    1000      120    0.6e-3   2e-5
    2000      120    0.7e-3   3e-5
Loop time of 1.25 on 1 procs for 1000 steps with 120 atoms
"""
    rows, names = corpus.thermo(screen)
    assert names == ["Atoms", "KinEng", "c_rke"]
    assert rows == {0: [0.0, 0.0, 0.0], 1000: [120.0, 5e-4, 1e-5], 2000: [120.0, 7e-4, 3e-5]}
    assert corpus.loop_time(screen) == (2.75, 2000)


def run(*values):
    return {"ok": True, "columns": ["KinEng"], "rows": {str(100 * k): [v] for k, v in enumerate(values)}}


def test_deterministic_runs_agree_to_the_printed_digits_or_part():
    reference = [run(1.0, 2.0, 3.0), run(1.0, 2.0, 3.0)]
    assert corpus.compare(reference, [run(1.0, 2.000001, 3.0)]) == ("deterministic", True,
                                                                      "3 rows to the printed digits")
    kind, ok, detail = corpus.compare(reference, [run(1.0, 2.0, 3.01)])
    assert (kind, ok) == ("deterministic", False) and detail.startswith("part at step 200")


@pytest.mark.parametrize("mine, agrees", [((1.0, 2.05), True), ((1.0, 2.25), True), ((1.0, 2.5), False),
                                          ((1.0, 1.5), False)])
def test_statistical_runs_within_the_widened_range(mine, agrees):
    """LIGGGHTS's seeds span 2.0..2.2 at step 100 (log10 range 0.0414): pdps's value agrees up to one
    range beyond either end, so 2.25 passes (0.24 of it past 2.2), 2.5 does not (1.34), nor 1.5 (3.0)."""
    reference = [run(1.0, 2.0), run(1.0, 2.1), run(1.0, 2.2)]
    kind, ok, detail = corpus.compare(reference, [run(*mine)])
    assert kind == "statistical" and ok == agrees, detail


def test_with_six_seed_sets_the_verdict_is_a_permutation_test():
    """Six LIGGGHTS runs at 2.0..2.5 at step 100: pdps's two runs inside that spread are one choice of
    28 among the eight runs, not the most extreme by the pooled t (p > 0.05); two far outside are the
    most extreme of all 28 choices (p = 1/28) and fail."""
    reference = [run(1.0, v) for v in (2.0, 2.1, 2.2, 2.3, 2.4, 2.5)]
    kind, ok, detail = corpus.compare(reference, [run(1.0, 2.15), run(1.0, 2.35)])
    assert (kind, ok) == ("statistical", True), detail
    kind, ok, detail = corpus.compare(reference, [run(1.0, 5.0), run(1.0, 5.2)])
    assert (kind, ok) == ("statistical", False), detail
    assert "at step 100 KinEng" in detail and "as extreme as 1 of the 28 choices of 2 of all 8 runs (p = 0.04" in detail


def test_a_count_is_resolved_to_one():
    """Particle counts the reference's runs print alike (a zero range at step 0): one particle more is
    one count's width past them (log10(1 + 1/12)), an excess of 1, not 87 widths of 0.1 %."""
    reference = [run(12.0, 1.0), run(12.0, 1.1), run(12.0, 1.2)]
    kind, ok, detail = corpus.compare(reference, [run(13.0, 1.1)])
    assert kind == "statistical" and detail.startswith("worst 1.00 of the seeds' range (step 0 KinEng)"), detail


def test_the_manual_items_and_what_pdps_makes_of_them():
    """benchmarks/liggghts_manual.py on made-up pages: each heading once, sub-models named, and a
    known style, a refused one, an unknown one and the CFD coupling told apart."""
    spec = importlib.util.spec_from_file_location("liggghts_manual", ROOT / "benchmarks" / "liggghts_manual.py")
    manual = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(manual)
    pages = ["fix insert/pack command :h3\n[Syntax:]\nkeyword = {region} or {sideways} :l\n"
             "  {region} value = region-ID\n[Examples:]\nfix insert/pack command :h3\n",
             "run command :h3\n", "gran model hertz model :h3\n", "fix multicontact/halfspace command :h3\n",
             "fix imaginary/style command :h3\n", "fix couple/cfd command :h3\n",
             "Syntax: fix ID group command :h3\n"]
    assert manual.items(pages) == [("fix", "couple/cfd"), ("fix", "imaginary/style"), ("fix", "insert/pack"),
                                   ("fix", "multicontact/halfspace"), ("gran", "model hertz"), ("run", None)]
    text = manual.table(pages)
    # insert/pack reads region, not the made-up sideways: known and checked, not fully working
    assert "| `fix insert/pack` | style | keywords: 1 of 2, not sideways | plugins/fix_insert" in text
    assert "| `run` | command |" in text
    assert "| `gran model hertz` | style |" in text and "| `fix imaginary/style` | unknown |" in text
    assert "| `fix multicontact/halfspace` | refused: pdps has no multicontact surface model" in text
    # run and gran model hertz have recorded LIGGGHTS cases (the tables' checks, and CHECKED)
    assert "| `run` | command |  | plugins/fix_granular/tests/data/liggghts.cases.json (bed" in text
    assert text.endswith("5 items (CFD coupling left out): 3 known to pdps, 1 refused with a reason, 1 unknown; "
                         "0 styles read every keyword of their page; 2 work fully (known, every keyword, numbers "
                         f"checked against LIGGGHTS's, or LAMMPS's for the {len(manual.LAMMPS_CHECKED)} items LIGGGHTS 3.8.0 "
                         "lacks or cannot run here).")
    # headings in a row share the page after them; LAMMPS's page rules some keywords out for rigid/small
    shared = manual.sections(["fix rigid command :h3\n\nfix rigid/small command :h3\n[Syntax:]\n"
                              "keyword = {temp} or {infile} :l\n[Examples:]\n"])
    assert manual.manual_keywords(shared[("fix", "rigid")]) == manual.manual_keywords(shared[("fix", "rigid/small")]) \
        == ["temp", "infile"]
    assert manual.keyword_answer("fix", "rigid/small", shared[("fix", "rigid/small")]) == \
        "keywords: all 1 (LAMMPS's page rules out temp for it)"


def test_a_shift_the_range_misses_the_t_test_finds():
    """LIGGGHTS's runs tight (2.070..2.082), pdps's two both low but apart (1.995, 2.044), as
    insert_stream's kinetic energy: a pair with one pdps run widens the others' range, so the range's
    excess ranks pdps's pair among several; the pooled t puts it alone at the top (p = 1/28)."""
    reference = [run(1.0, v) for v in (2.0793, 2.0813, 2.0787, 2.0717, 2.0723, 2.0814)]
    kind, ok, detail = corpus.compare(reference, [run(1.0, 2.0442), run(1.0, 1.9948)])
    assert (kind, ok) == ("statistical", False), detail
    assert "(p = 0.04" in detail
