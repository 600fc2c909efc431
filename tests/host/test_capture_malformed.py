"""Captures `hexbot replay` refuses (docs/console.md, the capture format):
a record earlier than the one above it, a port or a link state no session
writes. Before, each replayed with exit 0 (a byte at 5.0 s was re-stamped
by one at 1.0 s; `usb` was replayed though `--port usb` is refused). What
the capture writer produces still reads: several ports, equal times, and a
simulated session's set-up stamped before the simulation's clock ran."""

from __future__ import annotations

import pytest

from hexbot.errors import ScenarioError
from hexbot.host.capture import CaptureWriter, read_capture
from hexbot.host.link import LinkState


def _capture(tmp_path, body, name="c.hbcap"):
    path = tmp_path / name
    path.write_text(f"# hexbot-capture 2\n# start 2026-11-28T00:00:00.000+00:00\n"
                    f"# port ir /dev/pts/3 300 8N1\n{body}", encoding="utf-8")
    return path


@pytest.mark.parametrize(("body", "problem"), [
    ("5.0 ir rx 41\n1.0 ir rx 42\n",
     "5: time 1.000 is before 5.000 on line 4: records must not go back in time"),
    ("0.500 ir tx 2a\n0.500 debug rx 41\n0.499 sim note late\n",
     "6: time 0.499 is before 0.500 on line 5: records must not go back in time"),
    ("0.001 usb rx 41\n", "4: unknown port 'usb' (a capture's ports are ir, debug, host, sim)"),
    ("0.001 IR rx 41\n", "4: unknown port 'IR' (a capture's ports are ir, debug, host, sim)"),
    ("0.001 ir state exploded\n",
     "4: unknown link state 'exploded' (expected closed, connecting, connected, lost)"),
    ("0.001 ir state\n0.002 ir rx 41\n",
     "4: unknown link state '' (expected closed, connecting, connected, lost)"),
], ids=["rx back", "note back", "usb", "IR", "exploded", "no state"])
def test_a_malformed_record_stops_the_replay_naming_its_line(tmp_path, cli_status, body,
                                                              problem):
    path = _capture(tmp_path, body)
    code, err = cli_status("replay", path)
    assert (code, err) == (1, f"hexbot replay: error: {path}:{problem}\n")


def test_what_the_writer_produces_reads_and_only_the_set_up_may_go_back(tmp_path):
    # a simulated session: the host's notes are stamped by the wall clock
    # until the simulation's clock takes over at its 0 (before session 36
    # the `connecting` lines too); every port, every link state, equal times
    wall = iter([0.004, 0.006, 0.009])
    sim = iter([0.0, 0.0, 0.08, 0.08, 0.08, 0.09, 0.1, 0.2, 0.2, 0.2])
    writer = CaptureWriter(tmp_path / "s.hbcap", clock=lambda: 0.0)
    writer.use_clock(lambda: next(wall))
    writer.record("host", "note", text="framing legacy")
    writer.record("host", "note", text="simulator scenario pair")
    writer.record("ir", "state", text="connecting hexbot-sim://pair 300 8N1")
    writer.use_clock(lambda: next(sim))
    writer.record("ir", "state", text="connected hexbot-sim://pair 300 8N1")
    writer.record("debug", "state", text="connecting hexbot-sim://@1/uart1/1 4800 8N1")
    writer.record("ir", "rx", b"\n")
    writer.record("debug", "rx", b"A")
    writer.record("ir", "tx", b"*F")
    writer.record("sim", "note", text="M1 moved")
    writer.record("ir", "cut", text="0.090")
    writer.record("debug", "state", text="lost read failed")
    writer.record("debug", "state", text="closed")
    writer.record("ir", "state", text="closed")
    writer.close()
    records = list(read_capture(tmp_path / "s.hbcap"))
    assert [r.t for r in records] == [0.004, 0.006, 0.009, 0.0, 0.0, 0.08, 0.08, 0.08, 0.09,
                                      0.1, 0.2, 0.2, 0.2]
    assert {r.text.split()[0] for r in records if r.kind == "state"} == {
        s.value for s in LinkState}
    # from the first byte on, nothing goes back: not a note, not a state
    with (tmp_path / "s.hbcap").open("a", encoding="utf-8") as f:
        f.write("0.150 ir state connected again\n0.300 ir rx 41\n")
    with pytest.raises(ScenarioError, match=r"s.hbcap:16: time 0.150 is before 0.200 on "
                                            r"line 15: records must not go back in time$"):
        list(read_capture(tmp_path / "s.hbcap"))


def test_a_half_written_last_line_is_still_skipped_not_refused(tmp_path):
    # a killed writer: what is cut is skipped, whatever the cut makes it look like
    for tail in ("0.300 ir state conn", "0.300 de", "0.1"):
        path = _capture(tmp_path, f"0.200 ir rx 41\n{tail}")
        assert [r.t for r in read_capture(path)] == [0.2]
    with pytest.raises(ScenarioError, match=r"c.hbcap:5: unknown link state 'conn'"):
        list(read_capture(_capture(tmp_path, "0.200 ir rx 41\n0.300 ir state conn\n")))
