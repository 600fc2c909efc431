"""What a simulated port offers beyond bytes: the optional, typed interface.

A serial port opened on the embedded simulator (``hexbot-sim://`` URL, see
:mod:`hexbot.hil_sim.sim_serial`) carries one extra attribute,
``hexbot_sim``, that satisfies :class:`SimulatorAccess`. Host code that
never looks at it cannot tell the simulator from hardware; code that wants
the plant's verdict on a rotation, the true positions or the actuator
states asks for it here, through types that both sides import from the
protocol (the host never imports the simulator).

Plant verdicts are the simulator's judgement of a rotation: the module
moved (where to, facing where) or the plant refused it (why). Refusal
reasons are ranked: when both directions of a rotation fail, the most
telling reason is reported (a partner that tried beats nobody there).
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

Cell = tuple[int, int]


class RefusalReason(enum.Enum):
    """Why the plant did not move a module, most telling first."""

    FIXED_TO_BASE = "fixed to base"
    OCCUPIED_CELL = "occupied cell"
    LATCHED_JOINT = "latched joint"
    NO_AXLE = "no axle"
    TIMING = "timing"
    WRONG_POLARITY = "wrong polarity"
    NO_SUBSTRATE = "no substrate"

    @property
    def rank(self) -> int:
        """0 for the most telling reason."""
        return list(RefusalReason).index(self)


@dataclass(frozen=True)
class Moved:
    """A rotation happened: ``module`` left ``src`` for ``dst``."""

    t: float  # simulated seconds
    module: int
    src: Cell
    dst: Cell
    orientation: int  # Yref after the move
    joint: int  # body-frame joint of the mobile module it turned about
    substrate: int | None = None
    split: tuple[int, ...] = ()  # modules the move left apart from the mover's group

    def describe(self) -> str:
        apart = (f"; module(s) {', '.join(map(str, self.split))} no longer touch it"
                 if self.split else "")
        return (f"module {self.module} moved {self.src} -> {self.dst} "
                f"facing {self.orientation}{apart}")


@dataclass(frozen=True)
class Refused:
    """The plant refused a rotation of ``module`` (None: a substrate pushed
    on a side where nobody is)."""

    t: float
    module: int | None
    reason: RefusalReason
    detail: str
    substrate: int | None = None

    def describe(self) -> str:
        who = f"module {self.module}" if self.module is not None else "no module"
        return f"refused {who}: {self.reason.value} ({self.detail})"


PlantVerdict = Moved | Refused


def verdict_from_record(record: dict[str, Any]) -> PlantVerdict | None:
    """The typed verdict of one simulator event record (its JSON trace form);
    None for records that are not plant verdicts (bus events and the like)."""
    kind = record.get("event")
    if kind == "moved":
        return Moved(float(record["t"]), int(record["module"]), _cell(record["from"]),
                     _cell(record["to"]), int(record["orientation"]), int(record["joint"]),
                     record.get("substrate"), tuple(int(m) for m in record.get("split", ())))
    if kind == "refused":
        return Refused(float(record["t"]), record.get("module"),
                       RefusalReason(record["reason"]), str(record.get("detail", "")),
                       record.get("substrate"))
    return None


def _cell(value: Any) -> Cell:
    x, y = value
    return (int(x), int(y))


@dataclass(frozen=True)
class Placement:
    """Where the plant has a module: its cell and orientation (Yref)."""

    cell: Cell
    orientation: int


@runtime_checkable
class SimulatorAccess(Protocol):
    """The simulator-only knowledge of a simulated port (``port.hexbot_sim``).

    ``stepped`` ports (speed 0) advance virtual time only when asked: a
    reader's ``read`` or :meth:`advance`. Paced ports (speed > 0) run on
    their own thread at ``speed`` times real time.
    """

    scenario: str
    seed: int
    speed: float
    base: int | None  # the module bolted to the base (it never moves)
    image_notes: tuple[str, ...]  # firmware images built from another protocol schema

    @property
    def stepped(self) -> bool: ...

    def now(self) -> float:
        """Simulated seconds since reset."""

    def advance(self, seconds: float) -> None:
        """Stepped ports: run the cluster ``seconds`` of virtual time now."""

    def module_ids(self) -> list[int]: ...

    def placements(self) -> dict[int, Placement]:
        """The plant's truth: every module's cell and orientation."""

    def verdicts(self, since: int = 0) -> list[PlantVerdict]:
        """Plant verdicts from index ``since`` on (a growing list)."""

    def subscribe(self, callback: Callable[[PlantVerdict], None]) -> None:
        """Call ``callback`` for every later verdict (from the simulating thread)."""

    def on_advance(self, callback: Callable[[], None]) -> None:
        """Call ``callback`` whenever virtual time advanced (from the simulating thread)."""

    def actuators(self, module_id: int) -> dict[str, list[int]]:
        """Joints open (J1..J6) and magnet polarity per side of a control board;
        the comm board's status LEDs lit (``led_joints``, ``led_pos``,
        ``led_neg``, 1..6)."""

    def uart1_url(self, module_id: int) -> str:
        """A URL that opens module ``module_id``'s control-board UART1 debug port
        on this same simulated cluster."""
