"""Otero's rules beyond the core: each family fires where its figure says,
in every orientation, and leaves the rest alone."""

import pytest

from hexbot.errors import ScenarioError
from hexbot.planning.locomotion import Engine, World, load_ruleset, loads
from hexbot.planning.locomotion.engine import Goal
from hexbot.planning.locomotion.rules import rotate

OTERO = load_ruleset("otero")


def run(modules: dict, obstacles=(), rounds=1, turns=0):
    """Run ``rounds`` rounds on a hand-made configuration turned by ``turns``
    quarter turns; returns {turned-back cell: state} and the result."""
    cells = [rotate(c, turns) for c in modules]
    world = World([rotate(c, turns) for c in obstacles], cells, OTERO.states,
                  module_states=list(modules.values()), extend_axis=None)
    result = Engine(OTERO, world).run(rounds, Goal())
    assert result.violation is None, result.violation
    back = {rotate(p, -turns): s for p, s in zip(result.positions, result.states, strict=True)}
    return back, result


ALL_TURNS = pytest.mark.parametrize("turns", [0, 1, 2, 3])


@ALL_TURNS
def test_a_module_between_head_and_stopped_module_becomes_pivot(turns):
    # Fig. 5.14: head west (with a module on it), stopped module east.
    cfg = {(0, 0): "STOPA", (1, 0): "STOPA", (-1, 0): "HEADD", (-1, 1): "STOPA"}
    after, _ = run(cfg, obstacles=[(-1, -1), (0, -1), (1, -1), (2, 0)], turns=turns)
    assert after[(0, 0)] == "PIVOT"


@ALL_TURNS
def test_a_pivot_that_holds_a_corner_becomes_stopped_again(turns):
    # Fig. 5.16: its two edge neighbours meet only through it.
    cfg = {(0, 0): "PIVOT", (1, 0): "STOPA", (0, -1): "STOPA"}
    after, _ = run(cfg, obstacles=[(1, -2), (0, -2), (2, -1)], turns=turns)
    assert after[(0, 0)] == "STOPA"


@ALL_TURNS
def test_a_free_pivot_activates(turns):
    cfg = {(0, 0): "PIVOT", (0, -1): "STOPA", (1, -1): "STOPA"}
    after, _ = run(cfg, obstacles=[(0, -2), (1, -2)], turns=turns)
    assert after[(0, 0)] == "ACTIV"


@ALL_TURNS
def test_a_stopped_module_ahead_of_the_head_takes_it_over(turns):
    # Fig. 5.19: the head is below us and the wall is on our right.
    cfg = {(0, 0): "STOPA", (0, -1): "HEADD", (-1, -1): "STOPA"}
    after, _ = run(cfg, obstacles=[(1, 0), (1, -1), (0, -2), (-1, -2)], turns=turns)
    assert after[(0, 0)] == "HEADD"


@ALL_TURNS
def test_a_pivot_in_a_wall_deadlock_turns_superactive_and_drops_in(turns):
    # Fig. 5.25: a pivot over an empty cell, the obstacle south-east; the
    # module south-west will carry its slide south. An arch over an obstacle
    # keeps both sides connected once it has left.
    arch = [(1, 1), (1, 2), (0, 2), (-1, 2), (-1, 1)]
    cfg = {(0, 0): "PIVOT", (-1, 0): "STOPA", (-1, -1): "STOPA", (1, 0): "STOPA",
           **{c: "STOPA" for c in arch}}
    obstacles = [(1, -1), (-1, -2), (0, -2), (1, -2), (0, 1), (2, -1), (-2, -1), (-2, 0),
                 (2, 0), (2, 1), (-2, 1), (-2, 2), (2, 2)]
    after, _ = run(cfg, obstacles, turns=turns)
    assert after[(0, 0)] == "SUPER"
    after, result = run(cfg, obstacles, rounds=2, turns=turns)
    assert after.get((0, -1)) == "ACTIV" and (0, 0) not in after
    assert result.moves_per_module == [1] + [0] * 8


@ALL_TURNS
def test_the_tail_that_meets_the_head_breaks_the_perfect_cycle(turns):
    # Fig. 5.26-5.27: head east of us, we climb over it and become active.
    # The cycle closes below us, around the empty cell (0,-1).
    ring = [(-1, -1), (-1, -2), (0, -2), (1, -2), (1, -1)]
    cfg = {(0, 0): "STOPA", (-1, 0): "STOPA", (1, 0): "HEADD", **{c: "STOPA" for c in ring}}
    obstacles = [(-2, -1), (-2, -2), (-1, -3), (0, -3), (1, -3), (2, -2), (2, -1), (2, 0)]
    # Between the head and a stopped module, with a module on the head's
    # other side, we are first a pivot (priority 2), then the breaker.
    states = [run(cfg, obstacles, rounds=r, turns=turns)[0].get((0, 0)) for r in (1, 2)]
    assert states == ["PIVOT", "PERFE"]
    after, _ = run(cfg, obstacles, rounds=3, turns=turns)
    assert after.get((1, 1)) == "ACTIV" and (0, 0) not in after


STRAIGHT = ["NCYCL", "WCYCL", "SCYCL", "ECYCL"]


@ALL_TURNS
def test_the_t_module_of_a_tailed_cycle_knows_its_way_out(turns):
    # Fig. 5.28: the T's middle module leaves north, towards the obstacle piece
    # that closed the cycle; turned, it leaves west, south, east.
    cfg = {(0, 0): "STOPA", (-1, 0): "STOPA", (1, 1): "STOPA", (1, 0): "STOPA",
           (1, -1): "STOPA"}
    obstacles = [(2, 1), (2, 2), (-1, -1), (-2, 0)]
    after, _ = run(cfg, obstacles, turns=turns)
    assert after[(0, 0)] == STRAIGHT[turns]
    after, _ = run(cfg, obstacles, rounds=2, turns=turns)
    assert after.get((0, 1)) == "ACTIV"


def test_without_the_closing_obstacle_there_is_no_t():
    cfg = {(0, 0): "STOPA", (-1, 0): "STOPA", (1, 1): "STOPA", (1, 0): "STOPA",
           (1, -1): "STOPA"}
    after, _ = run(cfg, obstacles=[(-1, -1), (-2, 0)])
    assert after[(0, 0)] not in STRAIGHT


HEADER = "ruleset t\nstates a b c d e\nrule R1\n  priority 1\n  state a\n"


def test_become_takes_one_state_per_quarter_turn():
    rs = loads(HEADER + "  require E is empty\n  become b c d e\n")
    from hexbot.planning.locomotion.rules import variants
    assert [v.become for v in variants(rs.rules[0])] == ["b", "c", "d", "e"]


@pytest.mark.parametrize(("tail", "message"), [
    ("  become b c\n", "one state, or four"),
    ("  become b c d x\n", "unknown state 'x'"),
    ("  symmetry none\n  become b c d e\n", "need 'symmetry rotations'"),
])
def test_bad_become_lines_name_the_problem(tail, message):
    with pytest.raises(ScenarioError, match=message):
        loads(HEADER + tail, "x.rules")


@ALL_TURNS
def test_a_pivot_walled_in_by_a_filled_dead_end_leaves_as_superactive(turns):
    # U4 (ours): three static edge neighbours, its west side free; it leaves
    # north-west around its north neighbour (the deadlock of cavity-simple).
    block = [(0, 1), (1, 1), (1, 0), (1, -1), (0, -1)]
    cfg = {(0, 0): "PIVOT", **{c: "STOPA" for c in block}}
    obstacles = [(-1, -1), (-1, -2), (0, -2), (1, -2), (2, -1), (2, 0), (2, 1), (1, 2), (0, 2)]
    after, _ = run(cfg, obstacles, turns=turns)
    assert after[(0, 0)] == "SUPER"
    after, _ = run(cfg, obstacles, rounds=2, turns=turns)
    assert after.get((-1, 1)) == "ACTIV" and (0, 0) not in after


def test_a_walled_in_pivot_that_holds_the_robot_together_stays():
    # Without the diagonal modules its neighbours meet only through it.
    cfg = {(0, 0): "PIVOT", (0, 1): "STOPA", (1, 0): "STOPA", (0, -1): "STOPA"}
    after, _ = run(cfg, obstacles=[(-1, -1), (1, -1), (1, 1), (0, 2), (2, 0), (0, -2)])
    assert after[(0, 0)] != "SUPER"


def test_anchored_candidates_choose_exactly_what_a_full_scan_chooses(monkeypatch):
    # The engine finds candidates for 'W is HEADD'-style rules from the rare
    # modules they name; a run must not change when every module is scanned.
    from hexbot.planning.locomotion import load_scenario, simulate

    def run_once():
        r = simulate(OTERO, load_scenario("irregular-multi", 10), rounds=3000)
        return r.status, r.rounds, r.moves_per_module, r.positions, r.states, r.rule_counts

    anchored = run_once()
    compile_ = Engine._compile

    def no_anchors(self):
        compile_(self)
        self.by_state = [[(v, f, None) for v, f, _ in lst] for lst in self.by_state]

    monkeypatch.setattr(Engine, "_compile", no_anchors)
    assert run_once() == anchored
    assert anchored[0] == "reached" and "U4" in " ".join(anchored[5])
