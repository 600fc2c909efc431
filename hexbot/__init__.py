"""HexBot toolchain: protocol, HIL simulator, host console and planners.

The subpackages live in the repository's top-level folders:
``hexbot.protocol`` (protocol/), ``hexbot.hil_sim`` (hil_sim/),
``hexbot.host`` (host/) and ``hexbot.planning`` (planning/).
"""

__version__ = "0.1.0"
