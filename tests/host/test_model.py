"""Cluster model, joint conversion, capture reading: no I/O."""

from __future__ import annotations

import pytest

from hexbot.errors import ScenarioError
from hexbot.host.capture import CaptureWriter, read_capture
from hexbot.host.cluster import ClusterModel
from hexbot.protocol import parser, wire


def _feed(model: ClusterModel, data: bytes) -> None:
    for ev in parser.parse_all(data):
        model.apply("ir", ev, 1.0)


def test_model_tracks_acks_errors_status_and_localization():
    model = ClusterModel()
    _feed(model, parser.reply_ack(69, "M", 3) + parser.reply_error(1, 1, "M", 3))
    row = model.module(3)
    assert row.last_ack == 69 and row.last_error == "1:ARG_RANGE"
    report = (wire.PREAMBLE + b"LOCALIZED\n\rSide: 4\n\rYref: 2\n\rPos: +01-01\n\r")
    _feed(model, report)
    assert [(c.x, c.y, c.yref, c.module_id) for c in model.cells()] == [(1, -1, 2, None)]
    _feed(model, parser.reply_status(3, "M", True, 1, -1, 2, 0, prefix_role="M"))
    assert model.cells()[0].module_id == 3
    assert model.module(3).position == (1, -1) and model.module(3).orientation == 2
    assert model.module(3).last_error == ""


def test_reply_without_id_invents_no_module_and_boot_tail_names_by_id():
    """Defect 2 of issue 13: a legacy-mode reply (no id: every module answers
    at once, replies may collide) made a row named ``S``/``M``."""
    model = ClusterModel()
    _feed(model, parser.reply_ack(20, "S") + parser.reply_ack(20, "M")
          + wire.PREAMBLE + b"COMM. BOARD READY ID=07\n\r")
    assert list(model.modules) == ["07"]
    assert model.module(7).boot == "ID=07"


def test_status_with_id_0_makes_no_module():
    """Defect 3: two STA replies ANDed on the IR link gave ``STA id 0`` (a
    comm board without its control board sends id 0 too: no row either)."""
    model = ClusterModel()
    _feed(model, parser.reply_status(0, "M", False, 0, 0, 0, 0, prefix_role="M"))
    assert model.modules == {}


def test_a_module_that_moved_leaves_an_empty_cell():
    """Defect 2: after a move and a new localization the old cell was drawn
    ``/??\\`` and counted as placed."""
    model = ClusterModel()
    for ident, (x, y) in ((1, (0, 0)), (2, (0, 1))):
        _feed(model, parser.reply_status(ident, "M", True, x, y, 0, 0, prefix_role="M"))
    model.moved(2)
    _feed(model, wire.PREAMBLE + b"LOCALIZED\n\rSide: 4\n\rYref: 2\n\rPos: -01+01\n\r"
          + parser.reply_ack(66, "M", 2))
    assert [(c.x, c.y, c.module_id) for c in model.cells()] == [(-1, 1, 2), (0, 0, 1)]


def test_capture_round_trip_and_errors(tmp_path):
    w = CaptureWriter(tmp_path / "c.hbcap")
    w.record("ir", "tx", b"*F")
    w.record("ir", "rx", b"\n\r")
    w.record("ir", "state", text="lost read failed")
    w.close()
    recs = list(read_capture(tmp_path / "c.hbcap"))
    assert [(r.kind, r.data, r.text) for r in recs] == [
        ("tx", b"*F", ""), ("rx", b"\n\r", ""), ("state", b"", "lost read failed")]
    # a half-written last line (killed writer) is skipped, not an error
    with (tmp_path / "c.hbcap").open("a") as f:
        f.write("9.000 ir rx 0a0")
    assert len(list(read_capture(tmp_path / "c.hbcap"))) == 3
    bad = tmp_path / "bad.hbcap"
    bad.write_text("# hexbot-capture 1\n1.0 ir rx zz\n2.0 ir rx 00\n")
    with pytest.raises(ScenarioError, match=r"bad.hbcap:2: bad hex data"):
        list(read_capture(bad))
    (tmp_path / "x.hbcap").write_text("hello\n")
    with pytest.raises(ScenarioError, match="not a hexbot capture"):
        list(read_capture(tmp_path / "x.hbcap"))
    # a paced replay would wait for ever on a time that is not a number
    for stamp in ("nan", "inf", "-1.0"):
        (tmp_path / "t.hbcap").write_text(f"# hexbot-capture 1\n{stamp} ir rx 41\n1.0 ir rx 42\n")
        with pytest.raises(ScenarioError, match=rf"t.hbcap:2: bad time stamp '{stamp}'"):
            list(read_capture(tmp_path / "t.hbcap"))


def test_a_capture_cut_in_the_middle_of_a_character_keeps_its_records(tmp_path):
    note = "0.000 host note simulator scenario /home/u/r\u00e9glage.toml\n".encode()
    good = b"# hexbot-capture 1\n" + note + b"0.100 ir rx 4d30313a2041434b450a0d\n"
    cut = tmp_path / "cut.hbcap"
    cut.write_bytes(good + note[:45])  # the writer killed inside the two bytes of the e-acute
    assert note[:45].endswith(b"\xc3")
    records = list(read_capture(cut))
    assert [r.kind for r in records] == ["note", "rx"]
    cut.write_bytes(good.replace(b"0.100", b"0.1\xc3"))  # not the last line: still refused
    with pytest.raises(ScenarioError, match="not UTF-8"):
        list(read_capture(cut))


def test_ack_after_report_names_the_placement():
    model = ClusterModel()
    _feed(model, wire.PREAMBLE + b"LOCALIZED\n\rSide: 4\n\rYref: 0\n\rPos: -01+01\n\r"
          + parser.reply_ack(66, "M", 2))
    assert [(c.x, c.y, c.module_id) for c in model.cells()] == [(-1, 1, 2)]
    assert model.module(2).position == (-1, 1) and model.module(2).localized


def test_a_mavlink_localization_report_reads_as_the_legacy_one():
    """--framing mavlink: HEXBOT_LOCALIZED replaces the four lines of the
    legacy report; it gave one event, so `expect text LOCALIZED` never saw it
    and the model placed nobody (docs/protocol.md: the workflows run
    unchanged in either framing)."""
    import io

    from hexbot.protocol import hexbot_mavlink
    from hexbot.protocol.mavlink_codec import FramedParser

    out = io.BytesIO()
    mav = hexbot_mavlink.MAVLink(out, srcSystem=2, srcComponent=1)
    mav.send(hexbot_mavlink.MAVLink_hexbot_localized_message(4, 2, -1, 1))
    mav.send(hexbot_mavlink.MAVLink_hexbot_ack_message(66, 1, 0, 0))
    events = FramedParser().feed(out.getvalue())
    legacy = parser.parse_all(wire.PREAMBLE + b"LOCALIZED\n\rSide: 4\n\rYref: 2\n\rPos: -01+01\n\r"
                              + parser.reply_ack(66, "M", 2))
    # the legacy report's kinds of event, in its order (MavAck is an Ack...)
    assert all(isinstance(mav, type(old)) for mav, old in zip(events, legacy, strict=True))
    text, side, yref, pos, ack = events
    assert (text.phrase, side.side, yref.yref, (pos.x, pos.y), ack.code) == (
        "LOCALIZED", 4, 2, (-1, 1), 66)
    assert pos.mav is not None and pos.mav.name == "HEXBOT_LOCALIZED"  # shown beside it
    model = ClusterModel()
    for ev in events:
        model.apply("ir", ev, 1.0)
    assert [(c.x, c.y, c.yref, c.side, c.module_id) for c in model.cells()] == [
        (-1, 1, 2, 4, 2)]


def test_a_status_reply_says_the_modules_role_even_no_role():
    # the module's own word: 'S' after a Ref, '-' when it has none
    model = ClusterModel()
    _feed(model, parser.reply_status(3, "S", True, 0, 0, 0, 0, prefix_role="S"))
    assert model.module(3).role == "S"
    _feed(model, parser.reply_status(3, "-", False, 0, 0, 0, 0, prefix_role="M"))
    assert model.module(3).role == "-" and not model.module(3).localized
