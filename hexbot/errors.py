"""The toolchain's exceptions: one base class and one subclass per cause.

Library code raises these; only the CLI turns them into exit codes
(``exit_status``: 1 a refusal or failure, 2 a usage error, 3 a time-out,
4 a lost or missing port, 130 cancelled), so a script can tell "the module said no"
from "nobody answered" from "the cable is out".
"""


class HexBotError(Exception):
    """Base class of every error the toolchain raises on purpose."""

    exit_status = 1


class UsageError(HexBotError):
    """Options that do not fit together or a value argparse cannot check on
    its own (an empty seed range, a log folder that cannot be created):
    exit 2 like argparse's own usage errors, before any port opens."""

    exit_status = 2


class LinkUnavailableError(HexBotError):
    """A serial port or simulator link cannot be opened or was lost
    (unplugged adapter, missing pty, refused socket)."""

    exit_status = 4


class HexBotTimeoutError(HexBotError, TimeoutError):
    """An expected reply (ACK, boot text, event) did not arrive in time."""

    exit_status = 3


class CommandRefusedError(HexBotError):
    """A module answered a command with ERR, the unused-code ACK ``N`` or the
    control board's time-out ``~``; or a workflow's check refused to go on
    (unknown orientation, a move the plant refused or that was not verified)."""


class CancelledError(HexBotError):
    """The user cancelled a running exchange or workflow."""

    exit_status = 130


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


class Terminated(BaseException):  # noqa: N818 - named after the signal's meaning, like KeyboardInterrupt
    """SIGTERM, raised in the main thread while a command runs (``hexbot.cli``),
    so that its cleanup runs (``finally`` blocks, temporary folders, a JUnit
    file, the Dask cluster), as on Ctrl-C. A BaseException, like
    KeyboardInterrupt: ``except Exception`` does not swallow it."""
