"""The simulator keeps running while avrdude reprograms one of its boards
through the ISP pty, polled from the simulation loop as ``hexbot sim --pty``
does; the module then boots the new firmware."""

from __future__ import annotations

import re
import threading
import time

import pytest

from hexbot.hil_sim.isp.cluster import open_simulator_isp
from tests.flash.marks import needs_avrdude

pytest.importorskip("hexbot.hil_sim._avr", reason="simulator extension not built")
pytestmark = needs_avrdude


def test_module_boots_new_firmware_flashed_while_the_simulation_runs(firmware_build,
                                                                     hexbot_flash):
    from hexbot.hil_sim import Simulator

    build = firmware_build("loop-3")
    try:
        sim = Simulator.from_name("single")
    except Exception as exc:  # the scenario's own images are not built
        pytest.skip(f"scenario images unavailable: {exc}")
    text = bytearray()
    stop = threading.Event()

    with open_simulator_isp(sim) as isp:
        def loop() -> None:  # the only thread that touches the simulator
            while not stop.is_set():
                isp.poll(0.002)
                sim.run(0.01)
                text.extend(sim.debug_read(1))

        runner = threading.Thread(target=loop)
        runner.start()
        try:
            result = hexbot_flash("--board", "control", "--port", isp.ports_json()["1"]["control"],
                                  "--build-dir", str(build))
            assert result.code == 0, result.err
            deadline = time.monotonic() + 30
            while b"FW=loop-3" not in text and time.monotonic() < deadline:
                time.sleep(0.05)
        finally:
            stop.set()
            runner.join()
    boots = bytes(text).decode("ascii", "replace")
    versions = re.findall(r"CTR\. BOARD READY ID=01 FW=(\S+)", boots)
    # first the scenario's own image, then, after the ISP session, the new one
    assert len(versions) >= 2 and versions[0] != "loop-3" and versions[-1] == "loop-3"
