"""Start holds (``engine.start_holds``, hexbot model): the search gives the holds
of their definition (docs/traversal.md, "Rigid modules whose ways fold back")
at a fraction of its cost, and with the run's own limits."""

from __future__ import annotations

import pytest

from hexbot.planning.traversal.bank import random_surface
from hexbot.planning.traversal.bridges import find_bridge_cells
from hexbot.planning.traversal.cli import resolve_map
from hexbot.planning.traversal.engine import Engine, Violation, start_holds, traverse


def defined_holds(bmap, **options) -> tuple[int, ...]:
    """The holds as defined, computed the plain way (the code of 8167808 with
    the run's options): module ``k + 1`` run with the first ``k`` and their
    holds from round 0, for a hold of 0, 1, ... up to the rounds the first
    ``k`` take to settle, plus one; the first whose run breaks no invariant,
    else 0."""
    n = bmap.surface.n
    holds = [0] * n
    for k in range(1, n):
        ahead = Engine(bmap, holds=tuple(holds), active=k, **options).run()
        for hold in range(ahead.time_steps + 2):
            holds[k] = hold
            if Engine(bmap, holds=tuple(holds), active=k + 1,
                      **options).run().status != "violation":
                break
        else:
            holds[k] = 0
    return tuple(holds)


def rigid(seed: int, n: int, width: int, pockets: int = 4):
    return find_bridge_cells(random_surface(seed, n=n, width=width, pockets=pockets), "hexbot")


@pytest.fixture
def rounds_played(monkeypatch):
    """Counts the rounds every engine plays (one invariant check a round)."""
    played = [0]
    check = Engine.check

    def counting(self, rnd, actions):
        played[0] += 1
        return check(self, rnd, actions)
    monkeypatch.setattr(Engine, "check", counting)
    return played


# (map, holds): one module held (random:51), a hold of 13 (random:422), held
# modules among 8, and a hold whose run ends in a deadlock (module 8 of 8 held
# 11 rounds: every hold below crosses, every one from 11 on leaves it on a
# Bridge cell with nobody behind it to pass)
CASES = [
    (lambda: find_bridge_cells(random_surface(51), "hexbot"), (0, 0, 1, 1)),
    (lambda: find_bridge_cells(random_surface(422), "hexbot"), (0, 1, 1, 13)),
    (lambda: rigid(16, n=8, width=60), (0, 0, 2, 2, 3, 3, 3, 3)),
    (lambda: rigid(40, n=8, width=48, pockets=8), (0, 0, 1, 1, 1, 1, 1, 11)),
]


@pytest.mark.parametrize("case", range(len(CASES)))
def test_the_holds_are_those_of_the_definition_and_the_run_is_the_one_with_them(case):
    make, holds = CASES[case]
    bmap = make()
    assert start_holds(bmap) == defined_holds(bmap) == holds
    # the search ends with the run of all modules: traverse returns it
    assert traverse(bmap) == Engine(bmap, holds=holds).run() == Engine(bmap).run()


def test_the_search_plays_a_fraction_of_the_rounds_of_the_definition(rounds_played):
    # fig14-n13: 13 modules, no hold. The plain way runs the first k modules and
    # then module k + 1 with them, each from round 0: 1,937 rounds, then the run
    # itself (160). The search runs each module once from the round it starts (a
    # copy of the run of the ones ahead as it stood then), and the last of those
    # runs is the run itself: 728 rounds in all
    bmap = find_bridge_cells(resolve_map("fig14-n13"), "hexbot")
    rounds_played[0] = 0
    assert defined_holds(bmap) == (0,) * 13
    plain, rounds_played[0] = rounds_played[0], 0
    result = traverse(bmap)
    search = rounds_played[0]
    assert result.status == "reached" and result.holds == (0,) * 13
    assert result == Engine(bmap, holds=(0,) * 13).run()
    assert plain + result.time_steps > 2 * search  # 1,937 + 160 and 728


def test_when_the_modules_ahead_break_an_invariant_no_later_hold_is_tried(
        monkeypatch, rounds_played):
    # random:51 with a stand-in invariant that module 1's move in round 11 breaks:
    # every run with module 1 stops there. A hold that starts a module after that
    # round cannot help (its run is the same up to there), so each module tries
    # only the holds that start it by round 11; module 4 cannot start by then: it
    # and any behind it hold 0 without a run of their own. The plain way tries
    # every hold up to the rounds the modules ahead ran, plus one
    bmap = find_bridge_cells(random_surface(51), "hexbot")
    unheld = Engine(bmap, holds=(0, 0, 0, 0)).run()
    stop = next(m.dst for m in unheld.rounds[10] if m.module == 1)
    check = Engine.check

    def breaking(self, rnd, actions):
        if any(m.ident == 1 and rolled.dst == stop for m, rolled in actions):
            return Violation(rnd, "stand-in", [1], ["roll"], f"module 1 enters {stop}")
        return check(self, rnd, actions)
    monkeypatch.setattr(Engine, "check", breaking)
    rounds_played[0] = 0
    assert defined_holds(bmap) == (0, 0, 0, 0)
    plain, rounds_played[0] = rounds_played[0], 0
    result = traverse(bmap)
    search = rounds_played[0]
    assert result.holds == (0, 0, 0, 0)
    assert result.status == "violation" and result.violation.round == 11
    assert result == Engine(bmap, holds=(0, 0, 0, 0)).run()
    assert plain + result.time_steps > 5 * search  # 390 + 10 and 40


def test_a_hold_whose_run_deadlocks_is_taken_and_the_run_reports_the_deadlock():
    # module 8 of 8 crosses the way of one ahead for every hold up to 10; from 11
    # on it crosses nothing and stops on a Bridge cell with nobody behind it to
    # pass. A hold of 0 (none helps) would have the run report the crossing
    bmap = rigid(40, n=8, width=48, pockets=8)
    result = traverse(bmap)
    assert result.holds[7] == 11
    assert result.status == "deadlock" and "waiting: 8:bridge@" in result.reason
    for hold, status in ((0, "violation"), (10, "violation"), (12, "deadlock")):
        holds = (*result.holds[:7], hold)
        assert Engine(bmap, holds=holds).run().status == status


@pytest.mark.parametrize("max_rounds", [5, 15, 16, 40])
def test_the_holds_are_computed_with_the_runs_max_rounds(max_rounds):
    # random:51: module 3 unheld crosses module 2's way in round 16; in a run cut
    # before that round nothing crosses and nothing is held
    bmap = find_bridge_cells(random_surface(51), "hexbot")
    holds = {5: (0, 0, 0, 0), 15: (0, 0, 0, 0), 16: (0, 0, 1, 0), 40: (0, 0, 1, 1)}[max_rounds]
    assert start_holds(bmap, max_rounds=max_rounds) == holds
    assert defined_holds(bmap, max_rounds=max_rounds) == holds
    result = traverse(bmap, max_rounds=max_rounds)
    assert result.holds == Engine(bmap, max_rounds=max_rounds).holds == holds
    assert result == Engine(bmap, holds=holds, max_rounds=max_rounds).run()
    assert result.status == "deadlock" and f"after {max_rounds} rounds" in result.reason


def test_every_engine_of_the_search_has_the_runs_limits(monkeypatch):
    made = []
    init = Engine.__init__

    def recording(self, bmap, **options):
        init(self, bmap, **options)
        made.append((self.stall_rounds, self.max_rounds))
    monkeypatch.setattr(Engine, "__init__", recording)
    bmap = find_bridge_cells(random_surface(51), "hexbot")
    assert traverse(bmap, stall_rounds=30, max_rounds=400).status == "reached"
    assert len(made) > 1 and set(made) == {(30, 400)}
    made.clear()
    Engine(bmap, stall_rounds=31, max_rounds=401)
    assert len(made) > 1 and set(made) == {(31, 401)}
    made.clear()
    assert start_holds(bmap, stall_rounds=32) == (0, 0, 1, 1)
    assert len(made) > 1 and {stall for stall, _ in made} == {32}
