"""Waiting for a simulated cluster to boot: by module id, not by silence
(the firmware staggers its id-bearing boot texts in per-id slots)."""

import threading
import time
from dataclasses import dataclass

from hexbot.host.commands import _listening_id, wait_until_booted
from hexbot.protocol.parser import parse_all


@dataclass
class Seen:  # the part of host.Observed that the wait reads
    event: object


class Journal:
    """Unit-test double of Host's event journal."""

    def __init__(self) -> None:
        self.events: list[Seen] = []
        self.lock = threading.Lock()

    def since(self, mark: int) -> list[Seen]:
        with self.lock:
            return self.events[mark:]

    def hear(self, data: bytes) -> None:
        with self.lock:
            self.events += [Seen(e) for e in parse_all(data)]


def listening(ident: int) -> bytes:
    return f"\n\r\n\rCOMM. LISTENING ID={ident:02d} FW=0.1.0\n\r".encode()


def test_listening_id_is_read_from_the_boot_text():
    (ev,) = parse_all(listening(7))
    assert _listening_id(ev) == 7
    (other,) = parse_all(b"\n\r\n\rCTR. BOARD READY ID=07\n\r")
    assert _listening_id(other) is None


def test_waits_through_a_silent_slot_until_every_id_has_booted():
    journal = Journal()
    journal.hear(listening(1))

    def late_module() -> None:  # id 3 speaks after a silent slot (no id 2)
        time.sleep(0.3)
        journal.hear(listening(3))

    threading.Thread(target=late_module).start()
    seen = wait_until_booted(journal, quiet=0.05, timeout=10.0, expected={1, 3})
    assert seen == 2  # it did not stop at the silence after module 1


def test_gives_up_at_the_timeout_when_a_module_never_boots():
    journal = Journal()
    journal.hear(listening(1))
    assert wait_until_booted(journal, timeout=0.2, expected={1, 2}) == 1
