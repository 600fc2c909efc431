"""Localization faults (firmware mutation audit, session 32): a module that
heard nobody keeps NOT_HEARD as its last error; only a whole MSG1 with a
side 1..6 localizes."""

from __future__ import annotations

import pytest
from fwsim import Bench

from hexbot.protocol import frames, parser
from hexbot.protocol.codes import ErrorCode


def test_a_localize_that_heard_nobody_is_the_last_error_in_status(single: Bench):
    (err,) = single.command("Localize")
    assert isinstance(err, parser.ErrorReply), err
    assert (err.code, err.reason) == (66, ErrorCode.NOT_HEARD)
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.NOT_HEARD and not sta.localized




BYTE_S = 10 / 300


def hear_during_localize(bench: Bench, msg1: bytes, seconds: float = 3.0) -> list:
    """Send Localize, then feed ``msg1`` back to back into the module's IR
    receiver (whatever side it listens on) for ``seconds``; the replies."""
    mark = bench.send(frames.encode_pc(frames.make("Localize")))
    bench.run(11 * BYTE_S + 0.05)  # the frame itself
    for k in range(int(seconds / BYTE_S)):
        bench.sim.deliver(1, msg1[k % len(msg1)], False)
        bench.run(BYTE_S)
    done = bench.session.wait_for(
        lambda o: isinstance(o.event, (parser.Ack, parser.ErrorReply)), mark, 30.0)
    assert done is not None
    return [o.event for o in bench.session.host.since(mark)]


@pytest.mark.parametrize("msg1, learned", [
    (b"*+01-014", True),   # a neighbour's MSG1: side 4
    (b"*+01-010", False),  # side 0: no side, corruption
    (b"*+01-017", False),  # side 7
    (b"*+0A-014", False),  # not a digit
])
def test_only_a_whole_msg1_with_a_side_1_to_6_localizes(single: Bench, msg1, learned):
    events = hear_during_localize(single, msg1)
    replies = [e for e in events if isinstance(e, (parser.Ack, parser.ErrorReply))]
    if learned:
        assert isinstance(replies[-1], parser.Ack) and replies[-1].code == 66, events
        (pos,) = [e for e in events if isinstance(e, parser.PositionReport)]
        assert (pos.x, pos.y) == (1, -1)
    else:
        assert isinstance(replies[-1], parser.ErrorReply), events
        assert replies[-1].reason == ErrorCode.NOT_HEARD
