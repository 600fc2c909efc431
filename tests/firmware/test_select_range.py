"""The edges of the legacy Select's id range: the highest id is reached, and
an invalid further id refuses the whole Select (firmware mutation audit,
session 32)."""

from __future__ import annotations

import pytest
from fwsim import Bench, pc_frame, scenario_file

from hexbot.protocol import parser
from hexbot.protocol.codes import ErrorCode


def test_select_reaches_the_highest_legacy_id(images, tmp_path):
    # Select names ids 1..63 (docs/protocol.md): 63 itself is selectable,
    # in the first place and further down the list.
    bench = Bench.boot(scenario_file(tmp_path, [(63, (0, 0), 0)]))
    bench.drain()
    (ack,) = bench.command("Select", 63)
    assert isinstance(ack, parser.Ack) and (ack.code, ack.module) == (69, 63), ack
    (ack,) = bench.command("LOn")
    assert (ack.code, ack.module) == (44, 63)
    bench.drain()
    bench.send(pc_frame(69, 5, 63))  # module 5 is absent: only 63 answers, in slot 1
    bench.run(2.0)
    assert [(r.code, r.module) for r in bench.replies()] == [(69, 63)]





@pytest.mark.parametrize("ids", [(2, 0), (2, 64), (2, 5, 6, 7, 0)],
                         ids=["further-0", "further-64", "fifth-0"])
def test_an_invalid_further_id_refuses_the_whole_select(images, ids):
    # Further ids are 1..63 or 'N': 0 there is no "all", it is corruption.
    # Nobody answers, the previous selection stays, the error is recorded.
    bench = Bench.boot("flower7")
    bench.command("Select", 4)
    bench.drain()
    bench.send(pc_frame(69, *ids))
    bench.run(4.0)
    assert bench.replies() == []
    (ack,) = bench.command("LOn")
    assert (ack.code, ack.module) == (44, 4)
    (sta,) = bench.command("Status")
    assert sta.error == ErrorCode.ARG_RANGE
