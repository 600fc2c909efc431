"""``hexbot traverse`` exits 1 whenever the modules do not all reach their
goals: a deadlock as well as a broken invariant (module docstring of
planning/traversal/cli.py), and --execute then sends nothing."""

from __future__ import annotations

from hexbot.planning.traversal.engine import Result

# The chain ends over a slot one cell wide and two deep: under the deformable
# model the modules deadlock there (no module moves for 8n + 40 rounds).
SLOT = """\
. . . . . . . . . . . .
. M M M . . . . G G G .
S S S S . S S S S S S S
S S S S . S S S S S S S
S S S S S S S S S S S S
"""


def test_a_deadlock_exits_1_with_the_reason(cli_status, tmp_path):
    slot = tmp_path / "slot.txt"
    slot.write_text(SLOT)
    code, err = cli_status("traverse", slot)
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
