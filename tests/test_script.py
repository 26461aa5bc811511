"""The script language: lexer, substitution, variables, expressions, print and include."""

import io
import textwrap

import pytest

from pdps_core.errors import ScriptError
from pdps_core.script.lexer import logical_lines, split_words, strip_comment, substitute

BOX = """
region box block 0 4 0 4 0 4
create_box 1 box
mass 1 1
"""


def printed(sim, script):
    """Run the script; return the lines it printed."""
    before = len(sim.output.screen.getvalue())
    sim.command(textwrap.dedent(script))
    return sim.output.screen.getvalue()[before:].splitlines()


def error(sim, script):
    with pytest.raises(ScriptError) as info:
        sim.command(textwrap.dedent(script))
    return info.value


# ---- lexer ------------------------------------------------------------------------------------------
class TestLogicalLines:
    def test_plain_lines_are_numbered_from_one(self):
        assert list(logical_lines("a\nb\n\nc")) == [(1, "a"), (2, "b"), (3, ""), (4, "c")]

    def test_ampersand_joins_the_next_line_in_place_of_the_ampersand(self):
        # LAMMPS removes the & and the line break; the text before and after stays as it is
        assert list(logical_lines("pair_coeff 1 1 &\n  25.0 &   \n4.5\nrun 0")) == [
            (1, "pair_coeff 1 1   25.0 4.5"), (4, "run 0")]
        assert list(logical_lines("abc&\ndef")) == [(1, "abcdef")]

    def test_ampersand_on_the_last_line_ends_the_command(self):
        assert list(logical_lines("print a &")) == [(1, "print a ")]

    def test_open_triple_quote_continues_and_keeps_line_breaks(self):
        text = 'print """\nfirst\n  second"""\nrun 0'
        assert list(logical_lines(text)) == [(1, 'print """\nfirst\n  second"""'), (4, "run 0")]


class TestComments:
    def test_hash_starts_a_comment(self):
        assert strip_comment("run 10 # ten steps") == "run 10 "
        assert strip_comment("# whole line") == ""
        assert strip_comment("print a#b") == "print a"

    def test_hash_inside_quotes_is_text(self):
        assert strip_comment('print "a # b" # c') == 'print "a # b" '
        assert strip_comment("print 'x#y'") == "print 'x#y'"
        assert strip_comment('print """#"""#') == 'print """#"""'


class TestWords:
    def test_white_space_separates_words(self):
        assert split_words("  region   box\tblock 0 1  ") == ["region", "box", "block", "0", "1"]

    def test_quotes_make_one_word_without_the_quotes(self):
        assert split_words("""print "a b" 'c  d' \"\"\"e "f" g\"\"\" ''""") == [
            "print", "a b", "c  d", 'e "f" g', ""]

    def test_quoted_text_joins_adjacent_text(self):
        assert split_words('file="my file".txt') == ["file=my file.txt"]

    def test_unbalanced_quote_is_an_error(self):
        with pytest.raises(ScriptError, match=r"unbalanced quote \" in: print \"abc"):
            split_words('print "abc')


class TestSubstitute:
    values = {"a": "1.5", "name": "water", "long_name": "L", "(2*3)": "6"}

    def sub(self, text):
        return substitute(text, self.values.__getitem__)

    def test_braced_and_single_letter_forms(self):
        assert self.sub("x ${name} $a ${long_name}") == "x water 1.5 L"

    def test_single_letter_form_takes_one_character_only(self):
        assert self.sub("$ab") == "1.5b"

    def test_immediate_expression(self):
        assert self.sub("v $(2*3)") == "v 6"

    def test_no_substitution_inside_quotes(self):
        assert self.sub("""print "${name}" '$a' \"\"\"$(2*3)\"\"\" $a""") == \
            """print "${name}" '$a' \"\"\"$(2*3)\"\"\" 1.5"""

    @pytest.mark.parametrize("text, message", [
        ("print $", r"a lone \$ in: print \$"),
        ("print $ a", r"a lone \$ in: print \$ a"),
        ("print ${name", r"unterminated \$\{ in: print \$\{name"),
        ("print $(1+(2)", r"unterminated \$\( in: print \$\(1\+\(2\)"),
    ])
    def test_malformed_references(self, text, message):
        with pytest.raises(ScriptError, match=message):
            self.sub(text)


# ---- through a simulation ----------------------------------------------------------------------------
class TestScriptReading:
    def test_comments_blank_lines_and_continuations(self, sim):
        assert printed(sim, """
            # a comment line

            print "one # two"   # trailing comment
            print three &
                  four&
            five
            """) == ["one # two", "three fourfive"]

    def test_error_in_a_continued_command_names_its_first_line(self, sim):
        exc = error(sim, "print ok\nbogus_command 1 &\n  2 3\n")
        assert (exc.line, exc.command) == (2, "bogus_command")

    def test_multi_line_triple_quoted_text(self, sim):
        assert printed(sim, 'print """\nline # 1\n  line 2"""\nprint after') == [
            "", "line # 1", "  line 2", "after"]

    def test_error_message_stays_on_one_line_for_an_unclosed_triple_quote(self, sim):
        exc = error(sim, 'print """\nnever\nclosed\n')
        assert "\n" not in str(exc)
        assert exc.message == 'unbalanced quote """ in: print """ never closed'

    def test_substitution_into_any_command(self, sim):
        sim.command('variable dt equal 0.002*2\nvariable n index 3\ntimestep ${dt}\nthermo $n')
        assert sim.dt == pytest.approx(0.004)
        assert sim.output.thermo.every == 3

    def test_quoted_words_are_not_substituted_outside_print(self, sim):
        sim.command("variable x string X\nvariable s string '${x}'")
        assert sim.variables.text("s") == "${x}"

    def test_print_substitutes_inside_quotes(self, sim):
        assert printed(sim, """
            variable T equal 2+3
            variable name string "hello world"
            print "T = ${T}, $(v_T*2), ${name}"
            print 'single $T'
            """) == ["T = 5, 10, hello world", "single 5"]

    def test_print_joins_words_with_one_space(self, sim):
        assert printed(sim, "print a    b   c") == ["a b c"]

    def test_print_goes_to_the_log_too(self, make_sim, tmp_path):
        s = make_sim(log="log.test")
        s.command("variable v equal 6*7\nprint answer=${v}")
        s.close()
        assert "answer=42" in (tmp_path / "log.test").read_text().splitlines()

    def test_undefined_variable_in_print(self, sim):
        exc = error(sim, 'print "value ${nope}"')
        assert (exc.line, exc.command, exc.message) == (1, "print", "undefined variable nope")

    def test_undefined_variable_outside_print(self, sim):
        exc = error(sim, "print ok\ntimestep ${nope}")
        assert (exc.line, exc.message) == (2, "undefined variable nope")


# ---- variables ---------------------------------------------------------------------------------------
class TestVariables:
    def test_equal_is_evaluated_each_time_it_is_read(self, sim):
        sim.command(BOX + "variable s equal step*10")
        assert printed(sim, "print ${s}") == ["0"]
        sim.command("run 3")
        assert printed(sim, "print ${s}") == ["30"]
        sim.command("reset_timestep 7")
        assert printed(sim, "print $s") == ["70"]

    def test_equal_formats_integers_without_a_fraction(self, sim):
        assert printed(sim, "variable a equal 6/3\nvariable b equal 1/4\nprint $a $b") == ["2 0.25"]

    def test_string_joins_its_words(self, sim):
        sim.command("variable s string a b   c")
        assert sim.variables.text("s") == "a b c"

    def test_string_and_equal_can_be_redefined(self, sim):
        assert printed(sim, """
            variable s string first
            variable s string second
            variable e equal 1
            variable e equal 2
            print "$s $e"
            """) == ["second 2"]

    def test_index_steps_with_next_and_is_deleted_when_exhausted(self, sim):
        assert printed(sim, "variable r index a b c\nprint $r\nnext r\nprint $r\nnext r\nprint $r") == \
            ["a", "b", "c"]
        sim.command("next r")
        assert "r" not in sim.variables
        exc = error(sim, "print ${r}")
        assert exc.message == "undefined variable r"

    def test_next_steps_several_variables(self, sim):
        sim.command("variable a index 1 2\nvariable b index x y\nnext a b")
        assert (sim.variables.text("a"), sim.variables.text("b")) == ("2", "y")

    def test_next_needs_an_index_variable(self, sim):
        exc = error(sim, "variable e equal 1\nnext e")
        assert exc.command == "next"
        assert exc.message == ("next works only on index, loop, universe, uloop, world, file and atomfile variables "
                               "(e is equal)")
        assert error(sim, "next").message == "expected: next NAME..."
        assert error(sim, "next missing").message == "undefined variable missing"

    def test_a_redefined_index_keeps_its_first_value(self, sim):
        assert printed(sim, "variable n index 1 2\nvariable n index 5\nprint $n") == ["1"]

    def test_command_line_var_overrides_the_scripts_index_variable(self, make_sim):
        screen = io.StringIO()
        s = make_sim(screen=screen, variables={"T": "2.5"})
        s.command("variable T index 1.0\nvariable U index 1.0\nprint T=$T U=$U")
        assert screen.getvalue().splitlines() == ["T=2.5 U=1.0"]

    def test_a_variable_cannot_change_style(self, make_sim):
        # as LAMMPS: otherwise `variable T equal ...` would silently drop a -var T value
        s = make_sim(variables={"T": "2.5"})
        with pytest.raises(ScriptError) as info:
            s.command("variable T equal 1.0")
        assert info.value.command == "variable"
        assert info.value.message == ("variable T is already defined as index; it cannot become equal "
                                      "(use variable T delete first)")
        s.command("variable T delete\nvariable T equal 1.0")
        assert s.variables.value("T") == 1.0

    def test_delete(self, sim):
        sim.command("variable a string x\nvariable a delete\nvariable never delete")
        assert "a" not in sim.variables

    @pytest.mark.parametrize("line, message", [
        ("variable", "expected: variable NAME STYLE ARGS"),
        ("variable a", "expected: variable NAME STYLE ARGS"),
        ("variable a equal", "variable a equal needs a value"),
        ("variable a loops 10", "unknown variable style loops (known: index, loop, universe, uloop, world, "
                                "file, string, getenv, format, internal, equal, atom, atomfile, vector, delete)"),
        ("variable a loop 0 x", "variable a loop: bounds must be integers (got 0 x)"),
        ("variable a equal x", "variable a: an equal-style formula cannot read atom vectors (atom-style: "
                               "variable a atom ...) in 'x'"),
        ("variable 2a index 1", "variable name must be letters, digits and _ (got 2a)"),
        ("variable a-b index 1", "variable name must be letters, digits and _ (got a-b)"),
        ("variable a equal 1+", "variable a: unexpected 'end' in formula '1+'"),
        ("variable a equal (1", "variable a: expected ')', got 'the end' in formula '(1'"),
    ])
    def test_definition_errors(self, sim, line, message):
        exc = error(sim, line)
        assert (exc.command, exc.message) == ("variable", message)


# ---- expressions -------------------------------------------------------------------------------------
class TestExpressions:
    @pytest.mark.parametrize("expression, value", [
        ("1+2*3", 7), ("(1+2)*3", 9), ("2^3^2", 64), ("-2^2", 4), ("-7%3", -1), ("1 < 2 < 3", 1), ("3 > 2 > 1", 0), ("1 |^ 1", 0), ("2^-1", 0.5), ("7%4", 3), ("-3+1", -2),
        ("1e3/4", 250), ("sqrt(16)+abs(-2)", 6), ("exp(0)+ln(1)+log(100)", 3), ("PI", 3.141592653589793),
        ("floor(2.7)+ceil(2.2)+round(2.5)+round(-2.5)", 6), ("min(3,1,2)+max(4,5)", 6), ("atan2(1,1)*4", 3.141592653589793),
        ("3>2", 1), ("3<2", 0), ("2==2.0", 1), ("2!=2", 0), ("1<=1 && 2>=3", 0), ("1<0 || 2>1", 1),
        ("!0", 1), ("!(2>1) || 1!=1", 0), ("sin(0)+cos(0)", 1),
    ])
    def test_arithmetic(self, sim, expression, value):
        assert sim.variables.evaluate(expression) == pytest.approx(value, rel=1e-15)

    def test_immediate_expressions_in_a_line(self, sim):
        assert printed(sim, "print $(1+1) $(2^10)") == ["2 1024"]

    def test_thermo_keywords(self, sim):
        sim.command(BOX + "lattice sc 1.0\ncreate_particle 1 box\ntimestep 0.01\nreset_timestep 12")
        v = sim.variables
        assert v.evaluate("step") == 12
        assert v.evaluate("atoms") == 64
        assert v.evaluate("vol") == 64
        assert v.evaluate("lx + ly + lz") == 12
        assert v.evaluate("dt") == pytest.approx(0.01)
        assert v.evaluate("temp") == 0.0
        sim.command("velocity all create 1.5 4928")
        assert v.evaluate("temp") == pytest.approx(1.5, rel=1e-12)
        assert v.evaluate("ke") == pytest.approx(1.5 * 1.5 * 63 / 64, rel=1e-12)  # per particle in lj

    def test_step_and_time_follow_a_run(self, sim):
        sim.command(BOX + "create_particle 1 single 1 1 1\ntimestep 0.5\nvariable t equal time\nrun 4")
        assert sim.variables.value("t") == pytest.approx(2.0)
        assert sim.variables.evaluate("step") == 4

    def test_v_references(self, sim):
        sim.command("variable a equal 2\nvariable b equal v_a*v_a+1\nvariable c index 2.5\n"
                    "variable d string -4\nvariable e equal v_b+v_c+v_d")
        assert sim.variables.value("b") == 5
        assert sim.variables.value("e") == pytest.approx(3.5)

    def test_c_references(self, sim):
        sim.command(BOX + "create_particle 1 single 1 1 1\ncreate_particle 1 single 3 2 1\n"
                    "compute cen all centroid\nvariable cx equal c_cen[0]+c_cen[1]")
        assert sim.variables.value("cx") == pytest.approx(2.0 + 1.5)

    def test_reading_energy_needs_a_step_where_it_was_computed(self, sim):
        sim.command(BOX + "create_particle 1 single 1 1 1\nvariable e equal pe")
        exc = error(sim, "print $e")
        assert exc.message == ("potential energy was not computed on step 0: read it on a thermo step, "
                               "or run 0 first")
        sim.command("run 0")
        assert sim.variables.value("e") == 0.0

    @pytest.mark.parametrize("expression, message", [
        ("1/0", "divide by 0 in formula '1/0'"),
        ("5%0", "modulo 0 in formula '5%0'"),
        ("0^-1", "0 to a negative power in formula '0^-1'"),
        ("(-8)^(1/3)", "a negative number to a fractional power in formula '(-8)^(1/3)'"),
        ("10^400", "formula '10^400' gives a non-finite value"),
        ("10^10^10^10", "formula '10^10^10^10' gives a non-finite value"),
        ("exp(1000)", "formula 'exp(1000)' gives a non-finite value"),
        ("sqrt(-1)", "a negative value in sqrt() in formula 'sqrt(-1)'"),
        ("ln(0)", "a value <= 0 in ln() in formula 'ln(0)'"),
        ("foo(1)", "unknown function foo() in formula 'foo(1)'"),
        ("'text'", "unexpected character \"'\" in formula \"'text'\""),
        ("__import__('os')", "unexpected character \"'\" in formula \"__import__('os')\""),
        ("(lambda: 1)()", "unexpected character ':' in formula '(lambda: 1)()'"),
        ("x.real", "unexpected character '.' in formula 'x.real'"),
        ("atan2(1)", "atan2() takes 2 argument(s), got 1 in formula 'atan2(1)'"),
        ("x", "x is an atom vector: only atom-style variables read it (an equal-style formula reads one "
              "particle as x[ID])"),
        ("bogus", "unknown thermo keyword bogus"),
        ("v_missing + 1", "undefined variable missing"),
        ("c_missing", "compute missing is not defined"),
    ])
    def test_evaluation_errors(self, sim, expression, message):
        with pytest.raises(ScriptError) as info:
            sim.variables.evaluate(expression)
        assert info.value.message == message

    def test_errors_show_when_the_variable_is_read(self, sim):
        sim.command("variable r equal 1/(step)")     # defining it is fine: it is evaluated lazily
        exc = error(sim, "print ok\nprint $r")
        assert (exc.line, exc.message) == (2, "divide by 0 in formula '1/(step)'")

    def test_non_numeric_string_in_a_formula(self, sim):
        sim.command("variable name string water\nvariable x equal v_name+1")
        with pytest.raises(ScriptError) as info:
            sim.variables.value("x")
        assert info.value.message == "variable name is not a number (got water)"

    def test_an_index_value_is_a_number_not_a_formula(self, sim):
        # LAMMPS reads v_NAME of an index variable as a number; "temp" must not read the temperature
        sim.command(BOX + "variable k index temp\nvariable x equal v_k")
        with pytest.raises(ScriptError, match=r"variable k is not a number \(got temp\)"):
            sim.variables.value("x")

    def test_box_keywords_before_the_box_exists(self, sim):
        assert sim.variables.evaluate("step") == 0
        for keyword in ("vol", "lx", "temp", "atoms", "press"):
            with pytest.raises(ScriptError) as info:
                sim.variables.evaluate(keyword)
            assert info.value.message == (f"thermo keyword {keyword} before the simulation box exists "
                                          "(use create_box or read_data first)")


# ---- include -----------------------------------------------------------------------------------------
class TestInclude:
    def test_include_is_relative_to_the_including_script(self, sim, tmp_path):
        (tmp_path / "cases" / "parts").mkdir(parents=True)
        (tmp_path / "cases" / "main.in").write_text("variable v string main\ninclude parts/a.in\nprint end $v\n")
        (tmp_path / "cases" / "parts" / "a.in").write_text("print in a $v\ninclude b.in\n")
        (tmp_path / "cases" / "parts" / "b.in").write_text("variable v string set-in-b\nprint in b\n")
        before = len(sim.output.screen.getvalue())
        sim.file(str(tmp_path / "cases" / "main.in"))   # run from tmp_path: not the scripts' directory
        assert sim.output.screen.getvalue()[before:].splitlines() == [
            "read as PDPS: no command names a dialect (PDPS is the default)", "in a main", "in b", "end set-in-b"]

    def test_error_in_an_included_file_names_that_file_and_line(self, sim, tmp_path):
        (tmp_path / "main.in").write_text("print start\ninclude inc.in\n")
        (tmp_path / "inc.in").write_text("print one\n\nrun\n")
        with pytest.raises(ScriptError) as info:
            sim.file(str(tmp_path / "main.in"))
        exc = info.value
        assert exc.source.endswith("inc.in")
        assert (exc.line, exc.command) == (3, "run")

    def test_missing_include_file(self, sim):
        exc = error(sim, "include nowhere.in")
        assert exc.command == "include"
        assert exc.message.startswith("cannot read input script ")
        assert exc.message.endswith("nowhere.in: No such file or directory")

    def test_include_needs_one_file(self, sim):
        exc = error(sim, "include a b")
        assert exc.message.startswith("expected 1 argument(s), got 2")


@pytest.mark.parametrize("later, message", [
    ("fix 2 all deposit 10 1 100 1 region box", "fix: fix style deposit is a LAMMPS style pdps does not have; "
     "instead: create_atoms random between runs (docs/lammps.md)"),
    ("kspace_style pppm 1e-4", "kspace_style: kspace_style is a LAMMPS command pdps does not support; "
     "instead: pdps has no long-range electrostatics (docs/lammps.md)"),
    ("fix 2 all multicontact/halfspace", "fix: fix style multicontact/halfspace is a LIGGGHTS style pdps does not "
     "have; instead: pdps has no multicontact surface model (docs/liggghts.md)"),
    ("compute 3 all no/such/style", "compute: unknown compute style no/such/style"),
    ("thermo_stlye custom step", "thermo_stlye: unknown command thermo_stlye; did you mean thermo_style?"),
])
def test_what_a_later_line_refuses_is_refused_before_the_first_run(pdps_cli, later, message):
    """A command or style the script names after its runs is refused at its line before any step is
    computed (it stopped only when reached: after 100,000 steps of LIGGGHTS's insert_stream)."""
    result = pdps_cli(f"""
        units lj
        atom_style atomic
        lattice fcc 0.8442
        region box block 0 3 0 3 0 3
        create_box 1 box
        create_atoms 1 box
        mass 1 1.0
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0 2.5
        fix 1 all nve
        run 1000
        {later}
        run 10
    """, name="in.later")
    assert result.returncode == 1
    assert result.stderr.strip().splitlines()[-1].startswith(f"ERROR: in.later:13: {message}")
    assert "Step" not in result.stdout


def test_a_later_line_built_from_variables_waits_for_its_turn(pdps_cli):
    """Words that depend on variables are checked when the line runs, with the values of then."""
    result = pdps_cli("""
        variable style string nve
        region box block 0 4 0 4 0 4
        create_box 1 box
        create_particle 1 single 1 1 1
        mass 1 1.0
        run 2
        variable style string nvt/nonsense
        fix 1 all ${style}
    """, name="in.vars")
    assert result.returncode == 1
    assert "Step" in result.stdout
    assert result.stderr.strip().splitlines()[-1].startswith("ERROR: in.vars:9: fix: unknown fix style nvt/nonsense")
