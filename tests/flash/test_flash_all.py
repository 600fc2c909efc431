"""``hexbot flash --all``: rebuild the firmware with a new version string,
reflash every board of a simulated cluster, and see the modules boot it."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.flash.marks import needs_avr_gcc, needs_avrdude

pytest.importorskip("hexbot.hil_sim._avr", reason="simulator extension not built")

FIRMWARE = Path(__file__).resolve().parents[2] / "firmware"
pytestmark = [
    needs_avrdude,
    needs_avr_gcc,
    pytest.mark.skipif(
        not (FIRMWARE / "build" / "comm.elf").exists()
        or not (FIRMWARE / "build" / "control.elf").exists(),
        reason="the scenario's images firmware/build/*.elf are not built (make -C firmware)",
    ),
]


def test_flash_all_rebuilds_and_every_module_boots_the_new_version(tmp_path, hexbot_flash):
    result = hexbot_flash("--all", "--scenario", "pair", "--build-dir", str(tmp_path / "build"),
                          "--firmware-version", "isp-test-7")
    assert result.code == 0, result.err
    assert result.out.count("programmed with comm.hex") == 2
    assert result.out.count("programmed with control.hex") == 2
    boot_lines = [ln for ln in result.out.splitlines() if "control debug port" in ln]
    assert len(boot_lines) == 2
    # each module boots the new image and still reads its own DIP switches
    assert "CTR. BOARD READY ID=01 FW=isp-test-7" in boot_lines[0]
    assert "CTR. BOARD READY ID=02 FW=isp-test-7" in boot_lines[1]
    # and the PC hears every comm board's boot text in its slot (the last
    # slot ends seconds after reset: timing.boot_seconds)
    heard = result.out.split("PC transceiver heard", 1)[1]
    assert "COMM. LISTENING ID=01 FW=isp-test-7" in heard
    assert "COMM. LISTENING ID=02 FW=isp-test-7" in heard
    assert "every module booted FW=isp-test-7: 1, 2" in result.out


def test_flash_all_fails_naming_the_modules_that_did_not_boot(tmp_path, hexbot_flash, images,
                                                              firmware_build, monkeypatch):
    from hexbot.host.flash import cluster

    # the real comm image, and a control image that never answers the comm
    # board's handshake: the modules never send COMM. LISTENING with their id
    build = tmp_path / "build"
    build.mkdir()
    (build / "comm.hex").write_bytes((firmware_build("isp-test-8") / "comm.hex").read_bytes())
    (build / "control.hex").write_bytes(images("not-a-control-board")[1].read_bytes())
    monkeypatch.setattr(cluster, "build_firmware", lambda *args, **kwargs: None)
    result = hexbot_flash("--all", "--scenario", "pair", "--build-dir", str(build),
                          "--firmware-version", "isp-test-8")
    assert result.out.count("programmed with control.hex") == 2
    assert result.code == 1
    assert "not every module booted FW=isp-test-8" in result.err
    assert "module 1 (no COMM. LISTENING with its id), 2 (no COMM. LISTENING" in result.err


def test_ctrl_c_while_a_board_is_written_says_it_may_be_half_programmed(tmp_path):
    import os
    import signal
    import subprocess
    import sys

    hexbot = Path(sys.executable).with_name("hexbot")
    proc = subprocess.Popen([str(hexbot), "flash", "--all", "--scenario", "pair",
                             "--build-dir", str(tmp_path / "build")],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        for line in proc.stdout:
            if line.startswith("erasing and writing"):  # the chip is being erased
                os.killpg(proc.pid, signal.SIGINT)
                break
        out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    assert proc.returncode == 130, err
    assert out.startswith("stopped while writing: the comm board on "), out
    assert "may hold a part of comm.hex or nothing; flash it again" in out
    assert err == "hexbot flash: interrupted (Ctrl-C)\n"
