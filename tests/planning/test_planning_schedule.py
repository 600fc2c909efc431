"""The list schedule runs in C (planning/_schedule.c); it must give the steps
the Python schedule gave (tests/planning/schedule_reference.py), step for step:
the bench compares makespans across sessions, and the checker has accepted
these schedules."""

import pytest

from hexbot.bench.planning import make_pair
from hexbot.planning import journey
from hexbot.planning import schedule as scheduling
from hexbot.planning.budget import BudgetExhausted, Deadline
from hexbot.planning.canonical import via_strip
from hexbot.planning.configuration import Configuration
from hexbot.planning.local import FLOWS, forward
from hexbot.planning.moves import Move
from hexbot.planning.schedule import schedule_parallel
from tests.planning.schedule_reference import reference_schedule


def _same(ours, theirs) -> bool:
    if ours is None or theirs is None:
        return ours is theirs
    return [step.moves for step in ours] == [step.moves for step in theirs]


def _strip_plan(family: str, n: int, seed: int):
    a, b = make_pair(family, n, seed)
    start = Configuration.from_cells(a)
    return start, via_strip(start, frozenset(b))


def _flow_plan(seed: int, monkeypatch):
    """A journey flow's serial plan without its relays (it jams the list
    schedule for seed 2: every ready move a cut vertex)."""
    monkeypatch.setattr(journey, "relay", lambda *args: None)
    a, b = make_pair("blob", 100, seed)
    start = Configuration.from_cells(a)
    return start, forward(start, b, FLOWS[0][1], 10**6, None, Deadline(60), "local")


@pytest.mark.parametrize("fine", [True, False])
@pytest.mark.parametrize("window", [20_000, 50, 7])
@pytest.mark.parametrize("pair", [("scramble", 100, 0), ("blob", 100, 1)])
def test_the_c_schedule_gives_the_python_schedules_steps(pair, window, fine, monkeypatch):
    start, serial = _strip_plan(*pair)
    monkeypatch.setattr(scheduling, "FINE_MOVES", len(serial) if fine else 0)
    ours = schedule_parallel(start, serial, window=window)
    assert ours is not None
    assert _same(ours, reference_schedule(start, serial, window=window, fine=fine))


@pytest.mark.parametrize("seed", [0, 2])
def test_the_c_schedule_jams_where_the_python_schedule_jams(seed, monkeypatch):
    start, serial = _flow_plan(seed, monkeypatch)
    ours = schedule_parallel(start, serial)
    assert _same(ours, reference_schedule(start, serial))
    assert (ours is None) == (seed == 2)  # both outcomes seen


def test_the_c_schedule_gives_up_when_the_deadline_passes():
    start, serial = _strip_plan("blob", 100, 3)
    with pytest.raises(BudgetExhausted, match="parallel schedule"):
        schedule_parallel(start, serial, Deadline(0.0))


def test_the_c_schedule_refuses_a_move_no_rotation_makes():
    start, serial = _strip_plan("blob", 30, 0)
    bad = serial[0]
    serial[0] = Move(bad.module, bad.src, bad.dst, 9, bad.direction, bad.substrate,
                     bad.substrate_module)
    with pytest.raises(ValueError, match="no rotation about joint 9"):
        schedule_parallel(start, serial)


def test_the_c_schedule_refuses_a_move_off_its_rotations_substrate():
    start, serial = _strip_plan("blob", 30, 1)
    bad = serial[0]
    x, y = bad.substrate
    serial[0] = Move(bad.module, bad.src, bad.dst, bad.joint, bad.direction, (x + 5, y),
                     bad.substrate_module)
    with pytest.raises(ValueError, match="not on its rotation's substrate"):
        schedule_parallel(start, serial)


def test_a_move_that_would_split_the_rest_is_reported_not_recursed_on():
    # (0, 0) holds (0, 1) and (1, -1) together; its rotation about (0, 1) is
    # open, but no schedule runs it, and halving a plan of one move cannot
    # help (it used to recurse until Python's stack ran out)
    start = Configuration.from_cells({(0, 0), (0, 1), (1, -1)})
    move = Move(start[(0, 0)].id, (0, 0), (-1, 1), 2, "CW", (0, 1), start[(0, 1)].id)
    with pytest.raises(ValueError, match=rf"move 1 of module {move.module} from \(0, 0\)"):
        scheduling.schedule_in_pieces(start, [move])
