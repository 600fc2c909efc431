"""What the host knows about the cluster, built only from parsed replies.

A module is known by its id once it speaks in addressed mode (``M03:``)
or reports its status. A reply without an id (legacy mode, thesis prefix
``M:``: every module answers at once and the replies may have collided)
cannot be attributed and changes no row: the terminals show it, the model
does not invent a module from it. Localization reports carry no prefix at
all: each complete report (``LOCALIZED``, ``Side``, ``Yref``, ``Pos``) becomes a :class:`Placement`,
named by the ACK 66 the firmware sends right after it, or by a later
status reply at the same position.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from hexbot.host.describe import error_name
from hexbot.protocol.codes import Role, lookup, moves_the_module
from hexbot.protocol.parser import (
    Ack,
    ErrorReply,
    Event,
    PositionReport,
    SideReport,
    StatusReport,
    Text,
    YrefReport,
)
from hexbot.protocol.wire import (
    BOOT_ID_TAIL,
    MAX_MODULE_ID,
    TEXT_COMM_LISTENING,
    TEXT_COMM_READY,
    TEXT_CTR_READY,
    TEXT_LOCALIZED,
)

LOCALIZE_CODE = lookup("Localize").code


@dataclass
class ModuleState:
    key: str  # "03" for id 3
    module_id: int | None = None
    role: str = "-"
    localized: bool = False
    #: ``position`` is the place a plan put it, taken as given: a status check
    #: of a rotation cannot see a place (not shown as localized)
    assumed: bool = False
    position: tuple[int, int] | None = None
    orientation: int | None = None  # Yref 0..5
    last_ack: int | None = None
    last_error: str = ""
    last_seen: float = 0.0
    boot: str = ""  # tail of its last boot text (id, firmware version)

    @property
    def label(self) -> str:
        return f"{self.module_id:02d}" if self.module_id is not None else self.key


@dataclass
class Placement:
    """A localization report: where a module placed itself."""

    x: int
    y: int
    yref: int
    side: int | None
    t: float
    module_id: int | None = None


@dataclass
class _PendingReport:
    side: int | None = None
    yref: int | None = None


@dataclass
class ClusterModel:
    modules: dict[str, ModuleState] = field(default_factory=dict)
    placements: dict[tuple[int, int], Placement] = field(default_factory=dict)
    _pending: dict[str, _PendingReport] = field(default_factory=dict)
    _unnamed: dict[str, tuple[int, int]] = field(default_factory=dict)

    def module(self, module_id: int) -> ModuleState | None:
        return self.modules.get(f"{module_id:02d}")

    def _row(self, role: str | None, module_id: int | None) -> ModuleState | None:
        """The row of ``module_id``; None for a reply without an id (or with
        id 0: a comm board without its control board, or collided replies)."""
        if not module_id:
            return None
        key = f"{module_id:02d}"
        row = self.modules.get(key)
        if row is None:
            row = self.modules[key] = ModuleState(key=key, module_id=module_id)
        if role is not None:
            row.role = role
        return row

    def apply(self, port: str, ev: Event, t: float = 0.0) -> bool:  # noqa: C901
        """Update from one event; True if anything visible changed."""
        if isinstance(ev, Ack):
            row = self._row(ev.role, ev.module)
            if row is None:
                return True
            row.last_ack, row.last_seen = ev.code, t
            if moves_the_module(ev.code, ev.role):
                # however the rotation was sent (a workflow, the composer, a
                # script's post): its place and Yref are stale from here on
                row.localized = row.assumed = False
            # The firmware sends its localization report just before its
            # ACK 66: the ACK names the module that placed itself.
            unnamed = self._unnamed.pop(port, None)
            if ev.code == LOCALIZE_CODE and ev.module is not None and unnamed is not None:
                p = self.placements.get(unnamed)
                if p is not None and p.module_id is None:
                    self._name_placement(p.x, p.y, p.yref, ev.module, t)
                    row.position, row.orientation, row.localized = unnamed, p.yref, True
            return True
        if isinstance(ev, ErrorReply):
            row = self._row(ev.role, ev.module)
            if row is not None:
                row.last_error, row.last_seen = f"{ev.code}:{error_name(ev.reason)}", t
            return True
        if isinstance(ev, StatusReport):
            row = self._row(ev.role, ev.module_id)  # its own word, '-' (no role) too
            if row is None:
                return True
            row.localized = ev.localized
            if ev.localized:
                row.assumed = False
            row.last_seen = t
            row.last_error = "" if ev.error == 0 else error_name(ev.error)
            if ev.localized:
                row.position, row.orientation = (ev.x, ev.y), ev.yref
                self._name_placement(ev.x, ev.y, ev.yref, ev.module_id, t)
            return True
        return self._apply_report(port, ev, t)

    def _apply_report(self, port: str, ev: Event, t: float) -> bool:
        if isinstance(ev, Text):
            if ev.phrase == TEXT_LOCALIZED:
                self._pending[port] = _PendingReport()
            elif ev.phrase in (TEXT_COMM_READY, TEXT_CTR_READY) and ev.tail:
                ident = _id_from_tail(ev.tail)
                if ident is not None:
                    row = self._row(None, ident)
                    assert row is not None
                    row.boot, row.last_seen = ev.tail, t
                    return True
            elif ev.phrase == TEXT_COMM_LISTENING.rstrip() and ev.tail:
                ident = _id_from_tail(ev.tail)
                row = self._row(None, ident) if ident is not None else None
                if row is not None:  # (re)booted: it forgot its role and place
                    row.role, row.localized = Role.MOBILE.letter, False
                    row.boot, row.last_seen = ev.tail, t
                    return True
            return False
        pending = self._pending.get(port)
        if pending is None:
            return False
        if isinstance(ev, SideReport):
            pending.side = ev.side
        elif isinstance(ev, YrefReport):
            pending.yref = ev.yref
        elif isinstance(ev, PositionReport):
            del self._pending[port]
            self.placements[(ev.x, ev.y)] = Placement(
                ev.x, ev.y, pending.yref if pending.yref is not None else 0, pending.side, t)
            self._unnamed[port] = (ev.x, ev.y)
            return True
        return False

    def _name_placement(self, x: int, y: int, yref: int, module_id: int, t: float) -> None:
        for cell, p in list(self.placements.items()):
            if p.module_id == module_id and cell != (x, y):
                del self.placements[cell]  # it moved away: the cell is empty now
        p = self.placements.get((x, y))
        if p is None:
            self.placements[(x, y)] = Placement(x, y, yref, None, t, module_id)
        else:
            p.module_id, p.yref = module_id, yref

    def moved(self, module_id: int) -> None:
        """The module rotated: where it is and how it faces are stale until
        it reports again (the firmware forgets its position too)."""
        row = self.module(module_id)
        if row is not None:
            row.localized = row.assumed = False

    def assume(self, module_id: int, cell: tuple[int, int], orientation: int) -> None:
        """Take the plan's place of the module as given (it stays not
        localized): the next rotations aim from it, a localization judges it."""
        row = self.module(module_id)
        if row is not None:
            row.position, row.orientation, row.assumed = cell, orientation, True

    def placed(self, module_id: int, cell: tuple[int, int], orientation: int) -> None:
        """A check (the simulator's plant, or a localization) put the module here."""
        row = self.module(module_id)
        if row is None:
            return
        row.position, row.orientation, row.localized = cell, orientation, True
        self._name_placement(cell[0], cell[1], orientation, module_id, row.last_seen)

    def cells(self) -> list[Placement]:
        """Every occupied lattice cell the host knows, sorted by position."""
        return [self.placements[k] for k in sorted(self.placements)]


def _id_from_tail(tail: str) -> int | None:
    key = BOOT_ID_TAIL.strip()
    for word in tail.split():
        if word.upper().startswith(key):
            digits = word[len(key):]
            if digits.isdigit() and 1 <= int(digits) <= MAX_MODULE_ID:
                return int(digits)  # 0: the comm board has no id before the handshake
    return None
