"""pyserial URL handlers of the toolchain: ``hexbot-sim://`` (the simulator).

pyserial finds a scheme's handler as ``<package>.protocol_<scheme>`` in the
packages of ``serial.protocol_handler_packages``; :func:`register` adds this
package there. The host registers it before it opens any port; a script of
your own calls it once::

    from hexbot.hil_sim import urlhandler
    urlhandler.register()
    port = serial.serial_for_url("hexbot-sim://pair?speed=0", timeout=1)

The handler module imports nothing heavy: the simulator (and its C
extension) loads when a port opens, and a failure there is a
``SerialException`` naming the cause, not "protocol not known".
"""

from __future__ import annotations

import serial

SCHEME = "hexbot-sim"


def register() -> None:
    """Make ``serial.serial_for_url`` accept ``hexbot-sim://`` URLs (idempotent)."""
    if __name__ not in serial.protocol_handler_packages:
        serial.protocol_handler_packages.append(__name__)
