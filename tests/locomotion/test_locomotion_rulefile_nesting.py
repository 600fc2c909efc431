"""How deep a rule file's expressions may nest (docs/locomotion.md, "Rule
files"): up to 100 levels they load and run, deeper ones are
refused with the file and line; before, 400 parentheses, 5000 `not`s or a
chain of 600 defines ended in a RecursionError traceback."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion import loads

HEADER = "ruleset t\nstates a b\nresting a\n"
LIMIT = 100  # rulefile.MAX_NESTING, the number the docs state


def _rule(require: str) -> str:
    return f'rule R1 "x"\n  priority 1\n  state a\n  require {require}\n  become b\n'


def _chain(length: int) -> str:
    """``length`` defines, each using the one before: X0 nests 1 level (a
    name is its expression in parentheses), Xk k + 1."""
    lines = ["define X0 N is empty"]
    lines += [f"define X{i} X{i - 1} and E is empty" for i in range(1, length)]
    return "\n".join(lines) + "\n"


def _parens(levels: int) -> str:
    return "(" * levels + "N is empty" + ")" * levels


def _nots(levels: int) -> str:
    return "not " * levels + "N is empty"


def _not_parens(levels: int) -> str:  # each `not (` opens two
    return "not (" * (levels // 2) + "N is empty" + ")" * (levels // 2)


def _refused(path, cli_status) -> str:
    code, err = cli_status("locomotion", "run", path, "flat", "--n", "5", "--rounds", "3")
    assert code == 1, err
    return err


@pytest.mark.parametrize("nest", [_parens, _nots, _not_parens])
def test_an_expression_nests_up_to_100_levels_and_no_deeper(nest, tmp_path, cli_status):
    path = tmp_path / "deep.rules"
    path.write_text(HEADER + _rule(nest(LIMIT)))
    code, err = cli_status("locomotion", "run", path, "flat", "--n", "5", "--rounds", "3")
    assert err == ""  # it loaded and ran (what its rule does is the rules' business)
    path.write_text(HEADER + _rule(nest(LIMIT + 2)))
    assert _refused(path, cli_status) == (
        f"hexbot locomotion: error: {path}:7: expression nested deeper than 100 levels\n")


@pytest.mark.parametrize("require", [
    _parens(400), _nots(5000), "! " * 5000 + "N is empty", _not_parens(120)],
    ids=["400 parentheses", "5000 not", "5000 !", "60 not ("])
def test_a_far_deeper_expression_is_one_line_not_a_traceback(require, tmp_path, cli_status):
    path = tmp_path / "deep.rules"
    path.write_text(HEADER + _rule(require))
    assert _refused(path, cli_status) == (
        f"hexbot locomotion: error: {path}:7: expression nested deeper than 100 levels\n")


def test_a_chain_of_defines_counts_each_name_as_one_level(tmp_path, cli_status):
    # X99 nests 100 levels: usable as it is, not inside parentheses or one more define
    top = f"X{LIMIT - 1}"
    text = HEADER + _chain(LIMIT)
    assert loads(text + _rule(top), "ok.rules").rules[0].conditions
    with pytest.raises(ScenarioError) as err:
        loads(text + _rule(f"({top})"), "my.rules")
    assert str(err.value) == (
        f"my.rules:{LIMIT + 7}: expression nested deeper than {LIMIT} levels "
        f"(through {top}, which nests {LIMIT})")
    path = tmp_path / "chain.rules"
    path.write_text(HEADER + _chain(600) + _rule("X599"))
    assert _refused(path, cli_status) == (
        f"hexbot locomotion: error: {path}:{LIMIT + 4}: define X{LIMIT}: expression nested "
        f"deeper than {LIMIT} levels (through {top}, which nests {LIMIT})\n")
