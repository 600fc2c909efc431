"""The toolchain's exceptions: one base class and one subclass per cause.

Library code raises these; only the CLI turns them into exit codes.
"""


class HexBotError(Exception):
    """Base class of every error the toolchain raises on purpose."""


class LinkUnavailableError(HexBotError):
    """A serial port or simulator link cannot be opened or was lost
    (unplugged adapter, missing pty, refused socket)."""


class HexBotTimeoutError(HexBotError, TimeoutError):
    """An expected reply (ACK, boot text, event) did not arrive in time."""


class FrameError(HexBotError, ValueError):
    """A frame cannot be encoded or decoded: wrong length, delimiters,
    unknown function code, argument out of range."""


class FlashingError(HexBotError):
    """avrdude failed, the device signature is wrong, or the requested fuses
    are dangerous."""


class ScenarioError(HexBotError, ValueError):
    """A scenario, configuration, rule or map file is invalid; the message
    names the file, the line and the problem."""


class MissingExtraError(HexBotError, ImportError):
    """An optional dependency is not installed: drawing plans or rendering
    locomotion runs without the ``plot`` extra. The message names the
    ``pip install`` that brings it; the ImportError is kept as the cause."""
