"""One row per module: id, role, localized, position, orientation, last
ACK, last error (the VB GUI showed only the last ACK and the role letter)."""

from __future__ import annotations

from textual.widgets import DataTable

from hexbot.host.cluster import ClusterModel
from hexbot.host.describe import code_name

COLUMNS = ("id", "role", "localized", "position", "yref", "last ACK", "last error", "boot")


def module_rows(model: ClusterModel) -> list[tuple[str, ...]]:
    rows = []
    for key in sorted(model.modules, key=lambda k: (not k.isdigit(), k)):
        m = model.modules[key]
        rows.append((
            m.label, m.role, "yes" if m.localized else "no",
            f"({m.position[0]:+d},{m.position[1]:+d})" if m.position else "-",
            "-" if m.orientation is None else str(m.orientation),
            "-" if m.last_ack is None else code_name(m.last_ack),
            m.last_error or "-", m.boot or "-",
        ))
    return rows


class ModulesView(DataTable):
    def on_mount(self) -> None:
        self.cursor_type = "row"
        self.zebra_stripes = True
        self.add_columns(*COLUMNS)

    def refresh_from(self, model: ClusterModel) -> None:
        rows = module_rows(model)
        cursor = self.cursor_row  # keep the user's place across refreshes
        self.clear()
        for row in rows:
            self.add_row(*row, key=row[0])
        if rows:
            self.move_cursor(row=min(cursor, len(rows) - 1))
