"""Every simulated module's board outputs, live, as Wokwi shows a board's
pins: joint solenoids, magnet poles, status LEDs, cell, facing and role.

The state comes from the simulator's typed interface
(``SimulatorAccess.actuators()`` and ``placements()``); a real serial port
has none, so on hardware the view says so instead of showing stale or
empty rows."""

from __future__ import annotations

from collections.abc import Mapping

from textual.app import ComposeResult
from textual.containers import Vertical
from textual.widgets import DataTable, Static

from hexbot.host.cluster import ClusterModel
from hexbot.protocol.simulation import Placement, SimulatorAccess

COLUMNS = ("id", "cell", "facing", "role", "joints open", "magnets", "joint LEDs",
           "side LEDs")
# Magnet polarity codes of the simulator (hil_sim.plant): 1 +, -1 -, 0 off, 2 both lines.
POLE_MARK = {1: "+", -1: "-", 0: "·", 2: "!"}
LEGEND = ("joints and joint LEDs: the side number when open / lit, · when not; "
          "magnets: + positive, - negative, ! both lines on (a fault), · off; "
          "side LEDs: + positive, - negative, ± both lit")
UNAVAILABLE = ("Board view: no simulator behind this port. On real modules the "
               "pins cannot be read from the PC; use Status (t) for what a module "
               "reports about itself.")


def marks(values: list[int]) -> str:
    """``[0, 1, 0, 0, 0, 1]`` -> ``·2···6``: the index of what is on."""
    return "".join(str(k) if on else "·" for k, on in enumerate(values, 1))


def side_leds(pos: list[int], neg: list[int]) -> str:
    return "".join({(1, 1): "±", (1, 0): "+", (0, 1): "-"}.get((p, n), "·")
                   for p, n in zip(pos, neg, strict=True))


def board_rows(sim: SimulatorAccess, model: ClusterModel | None,
               placements: Mapping[int, Placement] | None = None) -> list[tuple[str, ...]]:
    """One row per module; ``placements``: where the plant has them, in the
    localization's frame (default: the plant's own, the scenario's)."""
    placements = sim.placements() if placements is None else placements
    rows = []
    for ident in sim.module_ids():
        out = sim.actuators(ident)
        place = placements.get(ident)
        known = model.module(ident) if model is not None else None
        rows.append((
            str(ident),
            f"({place.cell[0]:+d},{place.cell[1]:+d})" if place else "-",
            str(place.orientation) if place else "-",
            known.role if known is not None else "-",
            marks(out["joints"]),
            "".join(POLE_MARK.get(p, "?") for p in out["magnets"]),
            marks(out.get("led_joints", [0] * 6)),
            side_leds(out.get("led_pos", [0] * 6), out.get("led_neg", [0] * 6)),
        ))
    return rows


class BoardsView(Vertical):
    """The table of board outputs and a one-line legend (or why there is none)."""

    def compose(self) -> ComposeResult:
        yield Static(LEGEND, id="boards-note")
        yield DataTable(id="boards-table", zebra_stripes=True, cursor_type="row")

    def on_mount(self) -> None:
        self.query_one(DataTable).add_columns(*COLUMNS)

    @property
    def note(self) -> str:
        return str(self.query_one("#boards-note", Static).render())

    def rows(self) -> list[tuple[str, ...]]:
        table = self.query_one(DataTable)
        return [tuple(str(c) for c in table.get_row_at(i)) for i in range(table.row_count)]

    def refresh_from(self, sim: SimulatorAccess | None, model: ClusterModel | None,
                     placements: Mapping[int, Placement] | None = None) -> None:
        table = self.query_one(DataTable)
        note = self.query_one("#boards-note", Static)
        if sim is None:
            table.display = False
            note.update(UNAVAILABLE)
            return
        rows = board_rows(sim, model, placements)
        table.display = True
        note.update(LEGEND)
        if rows == self.rows():
            return  # unchanged: keep the cursor and spare the redraw
        cursor = table.cursor_row
        table.clear()
        for row in rows:
            table.add_row(*row, key=row[0])
        if rows:
            table.move_cursor(row=min(cursor, len(rows) - 1))
