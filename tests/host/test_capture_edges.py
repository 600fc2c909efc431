"""The .hbcap capture at its edges (a mutation audit): what the writer puts
on disk while the session runs (every record at once, one line each,
millisecond stamps, in time order) and what the reader refuses."""

from __future__ import annotations

import threading
import time

import pytest

from hexbot.errors import ScenarioError
from hexbot.host.capture import CaptureWriter, read_capture


def _capture(tmp_path, body, name="c.hbcap"):
    path = tmp_path / name
    path.write_text(f"# hexbot-capture 2\n# start 2026-11-28T00:00:00.000+00:00\n{body}",
                    encoding="utf-8")
    return path


@pytest.mark.parametrize("stamp", ["nan", "inf", "-1.000"])
def test_a_cut_whose_stamp_is_no_time_is_refused_with_its_line(tmp_path, stamp):
    # a replay stamps the garbage it cuts at this text: nan or a negative
    # time would be shown as the time of a reply
    capture = _capture(tmp_path, f"1.000 ir cut {stamp}\n2.000 ir rx 41\n")
    with pytest.raises(ScenarioError, match=r"c.hbcap:3: a cut needs the time stamp"):
        list(read_capture(capture))


def test_every_record_is_on_disk_before_the_writer_closes(tmp_path):
    # a killed console loses nothing already written: each record is flushed
    writer = CaptureWriter(tmp_path / "live.hbcap")
    try:
        writer.record("ir", "tx", b"*F")
        writer.record("ir", "rx", b"\n\r")
        assert [r.kind for r in read_capture(tmp_path / "live.hbcap")] == ["tx", "rx"]
    finally:
        writer.close()


def test_a_note_with_line_breaks_stays_one_record(tmp_path):
    # a warning's text may hold a newline; the file must stay one record a line
    writer = CaptureWriter(tmp_path / "n.hbcap")
    writer.record("host", "note", text="port lost:\nread failed\tagain")
    writer.record("ir", "rx", b"A")
    writer.close()
    records = list(read_capture(tmp_path / "n.hbcap"))
    assert [(r.kind, r.text) for r in records] == [("note", "port lost: read failed again"),
                                                   ("rx", "")]


def test_stamps_keep_milliseconds(tmp_path):
    times = iter([0.0, 0.007, 1.25])
    writer = CaptureWriter(tmp_path / "ms.hbcap", clock=lambda: next(times))
    writer.record("ir", "rx", b"A")
    writer.record("ir", "rx", b"B")
    writer.close()
    assert [r.t for r in read_capture(tmp_path / "ms.hbcap")] == [0.007, 1.25]


def test_records_written_at_once_by_two_threads_stay_in_time_order(tmp_path):
    # the reader thread and the sender stamp and write concurrently: a record
    # stamped later must not be written first. The first stamp is taken
    # slowly; the second thread's record comes in while it is taken.
    stamps = [1.0, 2.0]
    slow = threading.Event()

    def clock():
        t = stamps.pop(0) if stamps else 0.0
        if t == 1.0:
            slow.set()
            time.sleep(0.3)
        return t

    writer = CaptureWriter(tmp_path / "o.hbcap", clock=lambda: 0.0)
    writer.use_clock(clock)
    first = threading.Thread(target=writer.record, args=("ir", "rx", b"A"))
    first.start()
    assert slow.wait(10)
    writer.record("ir", "tx", b"B")
    first.join(10)
    writer.close()
    times = [r.t for r in read_capture(tmp_path / "o.hbcap")]
    assert times == sorted(times) == [1.0, 2.0]
