"""ISP access to the boards of a simulated cluster (``hexbot.hil_sim._avr``).

:class:`ClusterBoardBackend` hands the chip model a copy of one MCU's
memory when RESET goes low and, when RESET goes high again, writes back
whatever was programmed and resets the MCU, which then runs the new image.
Differences from the hardware, by necessity of the Cluster API: the MCU keeps
running its old image while it is "held in reset", and the lock bits live
here (the Cluster keeps no lock byte).

:func:`open_cluster_isp` is the one call the simulator needs to give every
module board its STK500v2 pty; :meth:`ClusterIsp.ports_json` is the
``"isp"`` entry of the JSON line of ``hexbot sim --pty``.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Mapping
from contextlib import nullcontext
from dataclasses import dataclass
from functools import partial
from typing import Any

from hexbot.errors import FlashingError
from hexbot.hil_sim.isp.chip import Atmega162Isp
from hexbot.hil_sim.isp.memory import EEPROM_SIZE, FLASH_SIZE, Atmega162Memory
from hexbot.hil_sim.isp.pty_server import IspPtyServer
from hexbot.hil_sim.isp.stk500v2 import Stk500v2Programmer

CLUSTER_METHODS = ("read_flash", "write_flash", "read_eeprom", "write_eeprom",
                   "fuses", "set_fuses", "signature", "reset")


def missing_cluster_methods(cluster: Any) -> list[str]:
    """The ISP methods (memories, fuses, signature, reset) that this Cluster object lacks (an
    out-of-date build of the extension, or another object passed by mistake)."""
    return [name for name in CLUSTER_METHODS if not callable(getattr(cluster, name, None))]


def _fit(data: bytes, size: int) -> bytearray:
    return bytearray(bytes(data[:size]).ljust(size, b"\xff"))


class ClusterBoardBackend:
    def __init__(self, cluster: Any, mcu: int, lock: threading.Lock | None = None,
                 on_reset: Callable[[], None] | None = None) -> None:
        missing = missing_cluster_methods(cluster)
        if missing:
            raise FlashingError(
                f"the simulator's Cluster lacks ISP methods: {', '.join(missing)}; "
                "rebuild the extension with `pip install -e .`")
        self.cluster = cluster
        self.mcu = mcu
        self.lock_bits = 0xFF
        self._guard = lock if lock is not None else nullcontext()
        self.on_reset = on_reset
        self.sessions = 0

    def acquire(self) -> Atmega162Memory:
        with self._guard:
            low, high, ext = self.cluster.fuses(self.mcu)
            return Atmega162Memory(
                flash=_fit(self.cluster.read_flash(self.mcu), FLASH_SIZE),
                eeprom=_fit(self.cluster.read_eeprom(self.mcu), EEPROM_SIZE),
                lfuse=low, hfuse=high, efuse=ext, lock=self.lock_bits,
                signature=bytes(self.cluster.signature(self.mcu)),
            )

    def release(self, memory: Atmega162Memory, changed: bool) -> None:
        with self._guard:
            if changed:
                self.cluster.write_flash(self.mcu, bytes(memory.flash))
                self.cluster.write_eeprom(self.mcu, 0, bytes(memory.eeprom))
                self.cluster.set_fuses(self.mcu, memory.lfuse, memory.hfuse, memory.efuse)
                self.lock_bits = memory.lock
            self.cluster.reset(self.mcu)  # RESET released: the MCU starts over
            if self.on_reset is not None:
                self.on_reset()
            self.sessions += 1


@dataclass
class ClusterIsp:
    server: IspPtyServer
    layout: dict[str, dict[str, str]]  # module id -> board -> pty path

    def ports_json(self) -> dict[str, dict[str, str]]:
        return {module: dict(boards) for module, boards in self.layout.items()}

    def fds(self) -> list[int]:
        """File descriptors to include in a select() that should wake on ISP input."""
        return self.server.fds()

    def poll(self, timeout: float = 0.0) -> int:
        return self.server.poll(timeout)

    def close(self) -> None:
        self.server.close()

    def __enter__(self) -> ClusterIsp:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def open_cluster_isp(
    cluster: Any,
    boards: Mapping[Any, Mapping[str, int]],
    lock: threading.Lock | None = None,
    on_reset: Callable[[Any, str, int], None] | None = None,
) -> ClusterIsp:
    """One STK500v2 pty per board: ``boards`` maps a module id to
    ``{"comm": mcu index, "control": mcu index}``. Serve them with
    ``result.server.poll(0)`` from the simulator loop (or ``.start()`` with a
    ``lock`` the loop also holds around ``Cluster.run``). ``on_reset(module,
    board, mcu)`` runs after each programmed MCU is reset."""
    server = IspPtyServer()
    layout: dict[str, dict[str, str]] = {}
    try:
        for module, mcus in boards.items():
            for board, mcu in mcus.items():
                hook = partial(on_reset, module, board, mcu) if on_reset else None
                chip = Atmega162Isp(ClusterBoardBackend(cluster, mcu, lock, hook))
                path = server.add(f"{module}/{board}", Stk500v2Programmer(chip))
                layout.setdefault(str(module), {})[board] = path
    except BaseException:
        server.close()
        raise
    return ClusterIsp(server, layout)


def open_simulator_isp(sim: Any, lock: threading.Lock | None = None) -> ClusterIsp:
    """ISP ports for every module of a ``hexbot.hil_sim.Simulator``.

    Integration with ``hexbot sim --pty`` (hil_sim/cli_sim.py)::

        isp = stack.enter_context(open_simulator_isp(sim))
        print(json.dumps({**bridge.names(), "isp": isp.ports_json()}), flush=True)
        # in the loop, beside bridge.pump_in():  isp.poll()
        # and in its select():  bridge.fds() + isp.fds()

    Polling from the simulator's own loop keeps every Cluster access on one
    thread; a programmed MCU restarts at the next slice.
    """
    boards = {mid: {"comm": module.comm.index, "control": module.control.index}
              for mid, module in sorted(sim.modules.items())}

    # The core re-applies external pin levels (DIP switches) on reset, so a
    # reprogrammed control board reads its module id without help.
    return open_cluster_isp(sim.cluster, boards, lock)
