"""Waiting for a simulated cluster to boot: by module id, not by silence
(the firmware staggers its id-bearing boot texts in per-id slots)."""

from pathlib import Path

from hexbot.host.session import LEGACY, listening_id
from hexbot.protocol import timing
from hexbot.protocol.mavlink_codec import Framing
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


# --- more than eight modules: ids 8 apart share a boot slot ---------------------------
#
# Their texts go out at the same time and their bytes AND on the IR link into
# one well-formed text with a wrong id: 1 and 9 read "ID=01", 2 and 10
# "ID=00", 6 and 14 "ID=04". Such a text names a module whose own text was
# lost, or none; a Status addressed to each module (MAVLink target_system,
# no Select) tells who is up.

FIRMWARE = Path(__file__).resolve().parents[2] / "firmware" / "build"


def row(tmp_path, ids, *, dead=(), base=None):
    """``ids`` in a row; the comm boards of ``dead`` run another firmware
    (rf12.elf): they never say a word on the IR link."""
    lines = ['name = "row"', "seed = 1", f"base = {base or ids[0]}"]
    for n, ident in enumerate(ids):
        lines += ["[[module]]", f"id = {ident}", f"position = [{n}, 0]", "orientation = 0"]
        if ident in dead:
            lines.append(f'firmware = {{ comm = "{FIRMWARE / "rf12.elf"}" }}')
    path = tmp_path / "row.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def test_collided_boot_texts_count_for_nobody_and_a_status_finds_them_up(tmp_path,
                                                                        open_session):
    ids = list(range(1, 11))  # 1 and 9 share slot 0, 2 and 10 slot 1
    session = open_session(row(tmp_path, ids), boot=False)
    heard = session.wait_booted(ids)
    # "ID=01" came (1 and 9 together), but module 1's own text was lost too
    assert heard == set(range(3, 9))
    # the wait ended with the last slot, not at its time-out (slots + 5 s)
    assert session.now() < timing.boot_seconds(ids) + 1.0
    assert session.confirm_booted([1, 2, 9, 10]) == {1, 2, 9, 10}
    # asked without a Select: every module is still in legacy mode
    assert session.selection is LEGACY and session.host.framing is Framing.LEGACY


def test_a_text_that_reads_as_another_slots_id_is_not_that_module(tmp_path, open_session):
    # 6 and 14 collide into "ID=04" in slot 5; module 4 (slot 3) is dead
    session = open_session(row(tmp_path, [4, 6, 14], dead={4}, base=6), boot=False)
    assert session.wait_booted([4, 6, 14]) == set()
    assert session.confirm_booted([4, 6, 14]) == {6, 14}


def test_the_cli_counts_a_big_cluster_booted_and_warns_of_nobody(tmp_path, log_dir,
                                                                 cli_status):
    # the audit's case: blob:20 warned that module 12 sent no boot text,
    # and then select 12 and status passed
    script = tmp_path / "s.hbs"
    script.write_text("select 12\nstatus\n")
    code, err = cli_status("run", script, "--scenario", "blob:20")
    assert code == 0, err
    assert "blob:20, 20 of 20 modules booted in " in err
    assert "warning" not in err


def test_the_cli_names_exactly_the_silent_module_of_a_big_cluster(tmp_path, log_dir,
                                                                  cli_status):
    ids = list(range(1, 11))
    script = tmp_path / "s.hbs"
    script.write_text("select 1\nselect 9\n")
    code, err = cli_status("run", script, "--scenario", row(tmp_path, ids, dead={9}))
    assert "9 of 10 modules booted in " in err
    warnings = [line for line in err.splitlines() if line.startswith("warning:")]
    assert warnings == [
        # the image's mark says so as the simulator loads it ...
        f"warning: {FIRMWARE / 'rf12.elf'}: it is the rf12 board's firmware, not the comm "
        "board's",
        # ... and the boot wait names the module that did not come up
        "warning: module(s) 9: no COMM. LISTENING text of theirs heard whole and no answer "
        "to a Status: not booted, or out of reach; steps addressed to them will fail"]
    assert code == 3 and "s.hbs:2: select 9" in err  # a step to it fails
    assert "may still be running Status" not in err  # the boot's question is not owed


def test_a_collided_id_00_boot_text_is_no_module_without_an_id(tmp_path, open_session):
    # 2 and 10 collide into "ID=00" at boot. A comm board without an id says
    # that too, and then a STA with id 0 is its reply; here a STA with id 0 is
    # replies that collided, and must stay a garbled reply for the session
    from hexbot.host.session import OutcomeKind
    from hexbot.protocol import frames

    ids = list(range(1, 11))
    session = open_session(row(tmp_path, ids), boot=False)
    session.boot(ids)
    out = session.exchange(frames.make("Status"))  # legacy: all ten answer at once
    assert out.kind is OutcomeKind.GARBLED, out


def test_on_hardware_a_text_a_collision_could_say_is_asked_for(tmp_path, open_session):
    # the same cluster behind a pty, as real modules are: no boot clock, so
    # "ID=04" may be 6 and 14 at once; module 4 is asked, and does not answer
    from hexbot.host.session import collision_ids
    from hexbot.host.simproc import SimProcess

    ids = [4, 6, 14]
    assert collision_ids(ids) == {4}
    with SimProcess(str(row(tmp_path, ids, dead={4}, base=6)), speed=0) as sim:
        session = open_session(sim.ports.ir, boot=False)
        # the simulator runs free: its slots are over long before 10 s
        heard = session.wait_booted(ids, timeout=10.0)
        assert 4 not in heard
        assert session.confirm_booted(sorted(set(ids) - heard)) == {6, 14}


def test_collision_ids_are_the_digit_wise_and_of_ids_that_share_a_slot():
    from hexbot.host.session import collision_ids

    assert collision_ids(range(1, 9)) == set()  # eight slots, eight modules
    assert collision_ids(range(1, 11)) == {1}  # 1 & 9 read 01; 2 & 10 read 00: nobody
    # 06 & 14 = 04, 06 & 22 = 02, 14 & 22 = 00 and all three 00: nobody
    assert collision_ids([6, 14, 22]) == {2, 4}


def test_on_hardware_a_collided_id_00_text_is_no_module_without_an_id(tmp_path,
                                                                       open_session):
    # the same ten modules behind a pty: 2 and 10 read "ID=00" at boot, and
    # a STA with id 0 later is replies that collided, not an id-less module
    from hexbot.host.session import OutcomeKind
    from hexbot.host.simproc import SimProcess
    from hexbot.protocol import frames

    ids = list(range(1, 11))
    with SimProcess(str(row(tmp_path, ids)), speed=0) as sim:
        session = open_session(sim.ports.ir, boot=False)
        session.wait_booted(ids, timeout=10.0)  # the free-running slots are over by then
        out = session.exchange(frames.make("Status"))  # legacy: all ten answer at once
    assert out.kind is OutcomeKind.GARBLED, out
