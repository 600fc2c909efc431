"""ISP on the simulator's boards: avrdude reprograms an MCU of a running
Cluster, which then boots the new image."""

from __future__ import annotations

import pytest

from hexbot.errors import FlashingError
from hexbot.hil_sim.isp.cluster import (
    ClusterBoardBackend,
    missing_cluster_methods,
    open_cluster_isp,
)
from tests.flash.marks import needs_avrdude

_avr = pytest.importorskip("hexbot.hil_sim._avr", reason="simulator extension not built")
pytestmark = needs_avrdude

BOOT_CYCLES = 200_000  # 0.2 s at 1 MHz: "HELLO x\n\r" at 4800 baud needs ~25 ms


def debug_text(cluster, mcu: int) -> str:
    target = cluster.cycle + BOOT_CYCLES
    while cluster.cycle < target:  # run() stops early after each watched byte
        cluster.run(target)
    return bytes(b for _, _, b in cluster.uart_take(mcu, 1)).decode("ascii", "replace")


@pytest.fixture
def board(images):
    elf, _ = images("old")
    cluster = _avr.Cluster(1000)
    assert missing_cluster_methods(cluster) == []
    mcu = cluster.add_mcu(str(elf), "control1")
    cluster.watch_uart(mcu, 1)
    isp = open_cluster_isp(cluster, {1: {"control": mcu}})
    isp.server.start()
    yield cluster, mcu, isp.ports_json()["1"]["control"]
    isp.server.close()


def test_reflashed_board_boots_the_new_image(board, images, hexbot_flash):
    cluster, mcu, port = board
    assert "HELLO old" in debug_text(cluster, mcu)
    _, new_hex = images("new-2")
    result = hexbot_flash("--board", "control", "--image", str(new_hex), "--port", port,
                          "--fuses")
    assert result.code == 0, result.err
    assert "found an ATmega162" in result.out
    assert "HELLO new-2" in debug_text(cluster, mcu)
    assert cluster.fuses(mcu) == (0x62, 0xD9, 0xFF)


def test_simulated_board_with_another_signature_is_refused(board, images, hexbot_flash):
    cluster, mcu, port = board
    cluster.set_signature(mcu, bytes.fromhex("1e9502"))
    _, new_hex = images("new-2")
    result = hexbot_flash("--image", str(new_hex), "--port", port)
    assert result.code == 1 and "signature 1E 95 02" in result.err
    assert "HELLO old" in debug_text(cluster, mcu)  # nothing was written


def test_an_object_without_the_isp_methods_is_refused_clearly():
    with pytest.raises(FlashingError, match="lacks ISP methods: read_flash"):
        ClusterBoardBackend(object(), 0)
