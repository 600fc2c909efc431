"""``hexbot traverse`` exits 1 whenever the modules do not all reach their
goals: a deadlock as well as a broken invariant (module docstring of
planning/traversal/cli.py), and --execute then sends nothing."""

from __future__ import annotations

from hexbot.planning.traversal.engine import Result

# The chain's front module stands at the edge of a slot one cell wide and
# two deep: the modules behind roll over it and cross the slot before anyone
# holds its Bridge cell; the front module then entered it last and waited for
# ever for n - 1 passes (a deadlock, found by session 33's audit). Refused now.
SLOT = """\
. . . . . . . . . . . .
. M M M . . . . G G G .
S S S S . S S S S S S S
S S S S . S S S S S S S
S S S S S S S S S S S S
"""


def test_a_pocket_that_begins_at_the_chain_is_refused(cli_status, tmp_path):
    slot = tmp_path / "slot.txt"
    slot.write_text(SLOT)
    code, err = cli_status("traverse", slot)
    assert code == 1
    assert err.strip() == (
        f"hexbot traverse: error: {slot}: the SINGLE pocket at [4, 2] begins at the module "
        "in [3, 3]: the modules behind it would cross the pocket before its bridge forms; "
        "start the chain at least one cell before the pocket")


def test_the_same_slot_with_the_chain_one_cell_back_is_crossed(cli_status, tmp_path):
    slot = tmp_path / "slot.txt"
    slot.write_text(SLOT.replace(". M M M . . . .", "M M M . . . . ."))
    for model in ("deformable", "hexbot"):
        code, err = cli_status("traverse", slot, "--motion", model)
        assert code == 0, err


def test_a_deadlock_exits_1_with_the_reason(cli_status, monkeypatch):
    # no map of the bank or of random:0..999 deadlocks (docs/traversal.md), so
    # the rounds are stubbed: the exit status is the CLI's
    from hexbot.planning.traversal import cli

    def deadlocked(bmap, **_options):
        return Result("deadlock", [], {}, reason="no module moved for 64 rounds")

    monkeypatch.setattr(cli, "traverse", deadlocked)
    code, err = cli_status("traverse", "hil-flat")
    assert code == 1
    assert err.startswith("hexbot traverse: deadlock: no module moved for 64 rounds")


def test_execute_sends_nothing_when_the_rounds_deadlock(cli_status, monkeypatch):
    # a run that deadlocks (stubbed: no small map deadlocks rigid modules)
    # must not reach the cluster: no session is opened
    from hexbot.host import cli_common
    from hexbot.planning.traversal import cli

    def deadlocked(bmap, **_options):
        return Result("deadlock", [], {}, reason="no module moved for 104 rounds")

    def no_session(*_args, **_kwargs):
        raise AssertionError("a session was opened")

    monkeypatch.setattr(cli, "traverse", deadlocked)
    monkeypatch.setattr(cli_common, "session", no_session)
    code, err = cli_status("traverse", "hil-flat", "--execute")
    assert code == 1 and err.strip() == (
        "hexbot traverse: deadlock, nothing executed: no module moved for 104 rounds")
