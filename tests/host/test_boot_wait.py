"""Waiting for a simulated cluster to boot: by module id, not by silence
(the firmware staggers its id-bearing boot texts in per-id slots)."""

from hexbot.host.session import listening_id
from hexbot.protocol import timing
from hexbot.protocol.parser import parse_all


def listening(ident: int) -> bytes:
    return f"\n\r\n\rCOMM. LISTENING ID={ident:02d} FW=0.1.0\n\r".encode()


def test_listening_id_is_read_from_the_boot_text():
    (ev,) = parse_all(listening(7))
    assert listening_id(ev) == 7
    (other,) = parse_all(b"\n\r\n\rCTR. BOARD READY ID=07\n\r")
    assert listening_id(other) is None


def scenario(tmp_path, ids):
    lines = ['name = "gaps"', "seed = 1", f"base = {ids[0]}"]
    for n, ident in enumerate(ids):
        lines += ["[[module]]", f"id = {ident}", f"position = [{n}, 0]", "orientation = 0"]
    path = tmp_path / "gaps.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_waits_through_silent_slots_until_every_id_has_booted(tmp_path, open_session):
    # ids 1 and 6: slots 2..5 stay silent, longer than any quiet period
    session = open_session(scenario(tmp_path, [1, 6]), boot=False)
    heard = session.wait_booted({1, 6}, quiet=0.5)
    assert heard == {1, 6}
    # module 6 speaks in its own slot, the sixth: the wait did not stop before it
    slot = timing.boot_slot_ticks() * timing.TICK_S
    assert session.now() > timing.BOOT_FIRST_SLOT_TICKS * timing.TICK_S + 5 * slot


def test_gives_up_at_the_timeout_when_a_module_never_boots(tmp_path, open_session):
    session = open_session(scenario(tmp_path, [1]), boot=False)
    assert session.wait_booted({1, 2}, timeout=10.0) == {1}
    assert 10.0 <= session.now() < 10.1
