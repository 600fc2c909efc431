"""A serial link that survives its port: open, read in a thread, reconnect.

Any pyserial URL or device works the same (``/dev/ttyUSB0``, a pty path,
``socket://host:port``, ``rfc2217://``, ``loop://``, and the embedded
simulator's ``hexbot-sim://``): the link calls ``serial.serial_for_url``.
Like ``serial.threaded.ReaderThread`` the thread only moves bytes; what
they mean is the business of the callback (the host's channel: parser,
journal, logs). When the port fails the link reports ``LOST``, keeps
retrying every ``retry_s`` seconds and reports ``CONNECTED`` again when the
port is back; nothing else in the host has to care.

A *stepped* simulated port (``hexbot-sim://...?speed=0``) has no time of its
own: virtual time moves only when someone waits. Such a link reads no thread
at all; the session's clock advances the simulator and calls :meth:`Link.pump`,
so the same session gives the same trace.
"""

from __future__ import annotations

import enum
import errno
import os
import termios
import threading
from collections.abc import Callable
from dataclasses import dataclass

import serial

from hexbot.errors import LinkUnavailableError
from hexbot.hil_sim import urlhandler
from hexbot.host.port_lock import busy_reason
from hexbot.protocol.simulation import SimulatorAccess
from hexbot.protocol.timing import BAUD_IR

_PARITY = {"N": serial.PARITY_NONE, "E": serial.PARITY_EVEN, "O": serial.PARITY_ODD,
           "M": serial.PARITY_MARK, "S": serial.PARITY_SPACE}
_STOP = {1: serial.STOPBITS_ONE, 1.5: serial.STOPBITS_ONE_POINT_FIVE, 2: serial.STOPBITS_TWO}


@dataclass(frozen=True)
class PortSettings:
    """What the thesis' port configuration window asked for: port, baud,
    parity, data bits, stop bits."""

    url: str
    baud: int = BAUD_IR
    parity: str = "N"
    data_bits: int = 8
    stop_bits: float = 1

    def __post_init__(self) -> None:
        if not self.url:
            raise LinkUnavailableError("no port given")
        if self.parity not in _PARITY:
            raise LinkUnavailableError(f"parity must be one of {''.join(_PARITY)}, "
                                       f"got {self.parity!r}")
        if self.data_bits not in (5, 6, 7, 8):
            raise LinkUnavailableError(f"data bits must be 5..8, got {self.data_bits}")
        if self.stop_bits not in _STOP:
            raise LinkUnavailableError(f"stop bits must be 1, 1.5 or 2, got {self.stop_bits}")
        if self.baud <= 0:
            raise LinkUnavailableError(f"baud must be positive, got {self.baud}")

    @property
    def frame(self) -> str:
        """``8N1`` style summary."""
        stop = int(self.stop_bits) if self.stop_bits != 1.5 else 1.5
        return f"{self.data_bits}{self.parity}{stop}"

    def describe(self) -> str:
        return f"{self.url} {self.baud} {self.frame}"

    def open(self, timeout: float) -> serial.SerialBase:
        """Open the port; LinkUnavailableError (with the cause) if it cannot."""
        urlhandler.register()
        try:
            # pyserial's rfc2217:// client has no write time-out (its writes go
            # to a socket); every other port gets one.
            writes = {} if self.url.startswith("rfc2217://") else {"write_timeout": 2.0}
            return serial.serial_for_url(
                self.url, baudrate=self.baud, parity=_PARITY[self.parity],
                bytesize=self.data_bits, stopbits=_STOP[self.stop_bits], timeout=timeout,
                exclusive=True, **writes,  # exclusive: two readers would split the bytes
            )
        except (serial.SerialException, OSError, ValueError) as exc:
            raise cannot_open(self.url, exc) from exc


def _errno_of(exc: BaseException) -> int | None:
    """The OS error number behind a failed open. pyserial wraps it: in the
    exception's own ``errno`` (posix devices), in the exception it was raised
    from (sockets, rfc2217), or in a ``termios.error`` (not a tty)."""
    for e in (exc, exc.__cause__, exc.__context__):
        if e is None:
            continue
        number = getattr(e, "errno", None)
        if number is None and isinstance(e, termios.error) and e.args:
            number = e.args[0]
        if isinstance(number, int) and number > 0:
            return number
    return None


def cannot_open(url: str, exc: BaseException) -> LinkUnavailableError:
    """The error of a port that did not open: ``cannot open URL: reason``."""
    return LinkUnavailableError(f"cannot open {url}: {open_failure(url, exc)}")


def open_failure(url: str, exc: BaseException) -> str:
    """Why a port did not open, in one short phrase. pyserial's own text
    repeats the port and the errno ("could not open port X: [Errno 2] No such
    file or directory: 'X'"); the user needs the cause and, for the usual
    ones, what to do."""
    number = _errno_of(exc)
    if number == errno.EWOULDBLOCK:  # pyserial: the exclusive flock is taken
        return busy_reason(url)
    if number is None:
        return str(exc)
    text = os.strerror(number)
    if number == errno.ENOTTY:
        return f"not a serial port ({text})"
    if number == errno.EACCES and url.startswith("/dev/"):
        return f"{text} (is your user in the group that owns {url}, often 'dialout'?)"
    return text


class LinkState(enum.Enum):
    CLOSED = "closed"  # not started, or stopped by the user
    CONNECTING = "connecting"
    CONNECTED = "connected"
    LOST = "lost"  # failed; retrying


DataCallback = Callable[[bytes], None]
StateCallback = Callable[[LinkState, str], None]
IdleCallback = Callable[[], None]


#: why a lost pty is not opened again (the link's state detail says it)
PTY_GONE = ("a pseudo-terminal is not opened again: its number goes to the next one "
            "opened; start its simulator and this command again")


class Link:
    """One port, one reader thread. Callbacks run in that thread.

    ``on_idle`` is called when a read returned nothing (every ``poll_s``);
    the channel uses it to flush a half reply after a quiet period.
    """

    def __init__(self, settings: PortSettings, on_data: DataCallback,
                 on_state: StateCallback | None = None, on_idle: IdleCallback | None = None,
                 *, retry_s: float = 1.0, poll_s: float = 0.05) -> None:
        self.settings = settings
        self._on_data = on_data
        self._on_state = on_state or (lambda state, detail: None)
        self._on_idle = on_idle or (lambda: None)
        self.retry_s = retry_s
        self.poll_s = poll_s
        self._port: serial.SerialBase | None = None
        self._lock = threading.Lock()  # guards _port for writers
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._state_changed = threading.Condition()
        self.state = LinkState.CLOSED
        self.detail = ""
        self.bytes_in = 0
        self.bytes_out = 0

    # --- public API -------------------------------------------------------

    def start(self, wait_s: float = 0.0) -> Link:
        """Start the reader thread; optionally wait until connected (raises
        LinkUnavailableError with the last failure if it does not happen).
        A stepped simulated port is opened here, at once, and gets no thread."""
        if self._port is not None and self.stepped:
            return self
        if self._port is None and self.in_process:
            self._open_now()  # in-process: there or not, no point in retrying
            if self.stepped:
                return self
        if self._thread is None or not self._thread.is_alive():
            self._stop.clear()
            self._thread = threading.Thread(target=self._run, name=f"link {self.settings.url}",
                                            daemon=True)
            self._thread.start()
        if wait_s > 0:
            with self._state_changed:
                self._state_changed.wait_for(lambda: self.state is LinkState.CONNECTED, wait_s)
            if self.state is not LinkState.CONNECTED:
                raise LinkUnavailableError(self.detail or f"cannot open {self.settings.url}")
        return self

    def _open_now(self) -> None:
        self._set_state(LinkState.CONNECTING, self.settings.describe())
        try:
            port = self.settings.open(0)
        except LinkUnavailableError as exc:
            self._set_state(LinkState.LOST, str(exc))
            raise
        with self._lock:
            self._port = port
        self._set_state(LinkState.CONNECTED, self.settings.describe())

    @property
    def simulator(self) -> SimulatorAccess | None:
        """The simulator-only interface of the open port, if it has one."""
        access = getattr(self._port, "hexbot_sim", None)
        return access if isinstance(access, SimulatorAccess) else None

    def unread(self) -> int:
        """Bytes waiting at the open port for the reader (0 when closed).
        Without the port lock: a waiter calls it holding the host's
        condition, and a port dropped under the lock notifies that condition
        (the other lock order)."""
        port = self._port
        if port is None:
            return 0
        try:
            return port.in_waiting
        except (serial.SerialException, OSError, TypeError, AttributeError, ValueError):
            return 0  # closed meanwhile: the reader finds out and says so

    @property
    def stepped(self) -> bool:
        """True for a port whose virtual time moves only when pumped."""
        access = self.simulator
        return access is not None and access.stepped

    def pump(self) -> None:
        """Stepped ports: hand what the port holds to the data callback."""
        with self._lock:
            port = self._port
            if port is None:
                return
            try:
                waiting = port.in_waiting
                data = port.read(waiting) if waiting else b""
            except (serial.SerialException, OSError) as exc:
                self._drop_locked(f"read failed: {exc}")
                return
        self._deliver(data)

    def _deliver(self, data: bytes) -> None:
        """Bytes to the data callback; nothing read: the idle callback."""
        if data:
            self.bytes_in += len(data)
            self._on_data(data)
        else:
            self._on_idle()

    @property
    def connected(self) -> bool:
        return self.state is LinkState.CONNECTED

    @property
    def in_process(self) -> bool:
        """Whether this is the embedded simulator's port (``hexbot-sim://``)."""
        return self.settings.url.startswith(urlhandler.SCHEME + "://")

    @property
    def retries(self) -> bool:
        """Whether a lost port is opened again. Not an in-process simulator:
        opening its URL again would silently start a fresh cluster. Nor a
        pseudo-terminal: once its other end closed, its number goes to the
        next one opened, another program's terminal (a monitor that retried
        printed a stranger's avrdude traffic as garbage)."""
        return not self.in_process and not self.pseudo_terminal

    @property
    def pseudo_terminal(self) -> bool:
        """Whether the port is a pty's slave (``/dev/pts/N``, or a link to one:
        ``hexbot sim --pty``, socat)."""
        return os.path.realpath(self.settings.url).startswith("/dev/pts/")

    def write(self, data: bytes) -> None:
        """Write all bytes now; LinkUnavailableError if the port is not open
        or fails (the reader thread then reconnects)."""
        with self._lock:
            port = self._port
            if port is None:
                raise LinkUnavailableError(f"{self.settings.url} is not connected"
                                           + (f" ({self.detail})" if self.detail else ""))
            try:
                port.write(data)
                port.flush()
            except (serial.SerialException, OSError) as exc:
                self._drop_locked(f"write failed: {exc}")
                raise LinkUnavailableError(f"{self.settings.url}: write failed: {exc}") from exc
        self.bytes_out += len(data)

    def close(self) -> None:
        """Stop the thread and close the port. Idempotent."""
        self._stop.set()
        with self._lock:
            self._drop_locked(None)
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)
        self._thread = None
        self._set_state(LinkState.CLOSED, "")

    def __enter__(self) -> Link:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- reader thread -----------------------------------------------------

    def _set_state(self, state: LinkState, detail: str) -> None:
        if state is self.state and detail == self.detail:
            return
        with self._state_changed:
            self.state, self.detail = state, detail
            self._state_changed.notify_all()
        self._on_state(state, detail)

    def _drop_locked(self, why: str | None) -> None:
        port, self._port = self._port, None
        if port is not None:
            try:
                port.close()
            except (serial.SerialException, OSError):
                pass  # closing a dead port may fail; it is gone either way
        if why is not None and not self._stop.is_set():
            self._set_state(LinkState.LOST, why)

    def _run(self) -> None:
        while not self._stop.is_set():
            with self._lock:
                port = self._port  # opened by start() already
            if port is None:
                if self.state is not LinkState.LOST:
                    self._set_state(LinkState.CONNECTING, self.settings.describe())
                try:
                    port = self.settings.open(self.poll_s)
                except LinkUnavailableError as exc:
                    self._set_state(LinkState.LOST, str(exc))
                    self._stop.wait(self.retry_s)
                    continue
                with self._lock:
                    self._port = port
                self._set_state(LinkState.CONNECTED, self.settings.describe())
            port.timeout = self.poll_s
            self._read_until_failure(port)
            if not self.retries:
                if self.pseudo_terminal and self.state is LinkState.LOST:
                    self._set_state(LinkState.LOST, f"{self.detail}; {PTY_GONE}")
                return  # lost for good: the state says why
            if not self._stop.is_set():
                self._stop.wait(self.retry_s)

    def _read_until_failure(self, port: serial.SerialBase) -> None:
        while not self._stop.is_set():
            try:
                data = port.read(max(1, port.in_waiting))
            except (serial.SerialException, OSError, TypeError, AttributeError) as exc:
                # TypeError/AttributeError: pyserial raises them when the port
                # is closed under a blocked read by close() from another thread.
                with self._lock:
                    if self._port is port:
                        self._drop_locked(f"read failed: {exc}")
                return
            self._deliver(data)
            with self._lock:
                if self._port is not port:
                    return
