"""The idle path (docs/firmware.md, "The idle path"): between inputs the
boards sleep through the 10 ms ticks at a few dozen cycles each, and the
watchdog still resets a main loop that stops coming back."""

from __future__ import annotations

import subprocess

from fwsim import BUILD, Bench, scenario_file

from hexbot.hil_sim.plant import OFF
from hexbot.protocol import frames
from hexbot.protocol.codes import ErrorCode
from hexbot.protocol.timing import TICK_TRUE_S

#: Awake cycles per idle tick: the tick interrupt and one check of the
#: sleep loop (about 50); the whole main loop every tick cost 240-280.
IDLE_CYCLES_PER_TICK_MAX = 70


def awake_per_tick(bench: Bench, seconds: float,
                   module_id: int = 1) -> dict[str, tuple[float, float]]:
    """Per board: (awake cycles, SLEEPs) per tick over ``seconds`` of idle."""
    cluster = bench.sim.cluster
    module = bench.sim.modules[module_id]
    boards = {"comm": module.comm.index, "control": module.control.index}
    before = {b: cluster.sleep_stats(i) for b, i in boards.items()}
    bench.run(seconds)
    out = {}
    for board, index in boards.items():
        a, b = before[board], cluster.sleep_stats(index)
        cycles = b["cycle"] - a["cycle"]
        ticks = cycles / (bench.sim.hz * TICK_TRUE_S)
        awake = cycles - (b["slept_cycles"] - a["slept_cycles"])
        out[board] = (awake / ticks, (b["sleeps"] - a["sleeps"]) / ticks)
    return out


def test_idle_boards_sleep_through_the_ticks(single: Bench):
    cost = awake_per_tick(single, 2.0)
    for board, (awake, sleeps) in cost.items():
        assert awake < IDLE_CYCLES_PER_TICK_MAX, (board, cost)
        assert 0.95 < sleeps < 1.05, (board, cost)  # every tick still counts time
    single.command("Status")  # and the module still answers at once


def symbol_address(elf: str, name: str) -> int:
    out = subprocess.run(["avr-nm", elf], check=True, capture_output=True, text=True).stdout
    return next(int(line.split()[0], 16) for line in out.splitlines()
                if line.split()[-1] == name)


def test_watchdog_resets_a_main_loop_that_stops_coming_back(single: Bench):
    single.run(3.0)  # long sleeps feed the watchdog often enough: no reset
    assert b"READY" not in single.debug_read(1)
    cluster, control = single.sim.cluster, single.sim.modules[1].control.index
    # The control board's main loop hangs on its next pass (links_due, only
    # called there and in sequences, spins: rjmp .-2) with interrupts on:
    # ticks and UART bytes go on, the loop never sleeps or comes back.
    at = symbol_address(str(BUILD / "control.elf"), "links_due")
    flash = bytearray(cluster.read_flash(control))
    flash[at:at + 2] = (0xCFFF).to_bytes(2, "little")
    cluster.write_flash(control, bytes(flash))
    single.run(1.0)
    assert b"READY" not in single.debug_read(1)
    single.run(1.5)  # watchdog 2 s (WDTO_2S) after the last feed
    # reset: the boot text again (the patch stays in flash, so it hangs again)
    assert b"CTR. BOARD READY" in single.debug_read(1)


def magnets_on(bench: Bench) -> bool:
    """Any magnet of module 1's control board energised (PORTx, read from the core)."""
    _, magnets = bench.actuators()
    return any(m != OFF for m in magnets)


def test_a_half_frame_expires_on_its_tick_while_the_board_sleeps(single: Bench):
    # The control board's error path (a half board frame: everything off)
    # runs at the tick the inter-byte time-out names, 3 ticks (> 30 ms,
    # <= 40 ms) after the last byte, although no byte wakes the board then.
    single.debug_write(1, b"*\x0b\x02NNN#")  # SxP(2)
    single.run(0.05)
    assert magnets_on(single)
    single.debug_write(1, b"*\x01\x02NN")  # half a frame: 5 bytes, 10.4 ms at 4800 baud
    single.run(0.0104 + 0.029)
    assert magnets_on(single)  # not abandoned early
    single.run(0.013)
    assert not magnets_on(single)  # abandoned within the 4th tick


def test_after_a_half_pc_frame_expires_the_comm_board_sleeps_again(single: Bench):
    single.send(b"*\x01\x03NN")  # half a frame, then silence
    single.run(0.6)  # > its inter-byte time-out: abandoned
    awake, _ = awake_per_tick(single, 2.0)["comm"]
    assert awake < IDLE_CYCLES_PER_TICK_MAX, awake
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.BAD_FRAME


def test_a_reply_slot_minutes_away_is_waited_asleep(images, tmp_path):
    # Select(0) gives id 200 rank 199; its Localize reply waits 199 x 4
    # slots (8 min). A due tick more than 32,767 ticks ahead looked past to
    # the signed compare, and the comm board polled awake for 2.5 minutes.
    sc = scenario_file(tmp_path, [(200, (0, 0), 0)])
    bench = Bench.boot(sc)
    bench.send(frames.encode_pc(frames.make("Select", 0)))
    bench.run(125.0)  # its own ACK slot: 199 x 0.6 s
    assert b"ACK" in bench.drain()
    bench.send(frames.encode_pc(frames.make("Localize")))
    bench.run(60.0)  # past the localization window, into the reply wait
    awake, _sleeps = awake_per_tick(bench, 5.0, module_id=200)["comm"]
    assert awake < IDLE_CYCLES_PER_TICK_MAX, awake
