"""pyserial's entry for ``hexbot-sim://`` URLs (see :mod:`hexbot.hil_sim.sim_serial`)."""

from hexbot.hil_sim.sim_serial import Serial

__all__ = ["Serial"]
