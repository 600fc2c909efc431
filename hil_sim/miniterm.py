"""pyserial's miniterm with ``hexbot-sim://`` URLs registered.

    python -m hexbot.hil_sim.miniterm "hexbot-sim://pair?speed=1" 300

Everything else is miniterm's own (``--help``); any other URL or device works too.
"""

from serial.tools import miniterm

from hexbot.hil_sim import urlhandler

if __name__ == "__main__":
    urlhandler.register()
    miniterm.main()
