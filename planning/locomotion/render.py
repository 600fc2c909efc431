"""Pictures of a run: the final state (PNG), every round (GIF), or ASCII text."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from hexbot.errors import ScenarioError
from hexbot.extras import require
from hexbot.planning.locomotion.engine import Engine

Cell = tuple[int, int]

# Colours by state name; unknown states get a grey.
COLOURS = {
    "static": (40, 70, 160),
    "active": (220, 40, 40),
    "cork": (240, 200, 30),
    "opener": (20, 20, 20),
    "STOPA": (40, 70, 160),
    "ACTIV": (220, 40, 40),
    "HEADD": (60, 200, 220),
    "PIVOT": (230, 120, 200),
    "SUPER": (240, 200, 30),
    "PERFE": (200, 0, 200),
}
OBSTACLE_RGB = (150, 150, 150)
EMPTY_RGB = (250, 250, 250)
ASCII = {"static": "o", "active": "A", "cork": "C", "opener": "P",
         "STOPA": "o", "ACTIV": "A", "HEADD": "H", "PIVOT": "V", "SUPER": "U", "PERFE": "F"}


@dataclass
class Recorder:
    """Keeps module positions and states each round (``on_round`` callback)."""

    every: int = 1
    last_only: bool = False  # a PNG needs the final frame only
    max_frames: int = 400  # past twice this, every other frame goes and `every` doubles
    frames: list[tuple[np.ndarray, np.ndarray]] = field(default_factory=list)
    rounds: list[int] = field(default_factory=list)  # the round of each frame
    states: list[str] = field(default_factory=list)
    box: list[int] = field(default_factory=list)  # x0, y0, x1, y1 over every round seen
    obstacles: set[Cell] = field(default_factory=set)

    def __call__(self, engine: Engine) -> None:
        self._engine = engine  # the last round is drawn even if it falls between frames
        if engine.round % self.every:
            return
        self._capture(engine)

    def close(self) -> None:
        """Add the run's last round if the thinning skipped it."""
        engine = getattr(self, "_engine", None)
        if engine is not None and (not self.rounds or self.rounds[-1] != engine.round):
            self._capture(engine)

    def _capture(self, engine: Engine) -> None:
        w = engine.world
        self.states = engine.rs.states
        frame = (w.xy().copy(), w.state.copy())
        lo, hi = frame[0].min(axis=0), frame[0].max(axis=0)
        if not self.box:
            self.box = [int(lo[0]), int(lo[1]), int(hi[0]), int(hi[1])]
        else:
            self.box = [min(self.box[0], int(lo[0])), min(self.box[1], int(lo[1])),
                        max(self.box[2], int(hi[0])), max(self.box[3], int(hi[1]))]
        if self.last_only:
            self.frames, self.rounds = [frame], [engine.round]
            return
        self.frames.append(frame)
        self.rounds.append(engine.round)
        if len(self.frames) > 2 * self.max_frames:  # long runs: keep memory bounded
            self.frames, self.rounds = self.frames[::2], self.rounds[::2]
            self.every *= 2


def _bounds(box: list[int], pad: int = 2) -> tuple[int, int, int, int]:
    return box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad


def ascii_map(positions: list[Cell], states: list[str], obstacles: list[Cell]) -> str:
    """The lattice around the robot as text: top row first."""
    xs = [p[0] for p in positions]
    ys = [p[1] for p in positions]
    x0, x1, y0, y1 = min(xs) - 2, max(xs) + 2, min(ys) - 2, max(ys) + 2
    cells = {c: "#" for c in obstacles if x0 <= c[0] <= x1 and y0 <= c[1] <= y1}
    for p, s in zip(positions, states, strict=True):
        cells[p] = ASCII.get(s, s[:1].upper())
    return "\n".join(
        "".join(cells.get((x, y), ".") for x in range(x0, x1 + 1)) for y in range(y1, y0 - 1, -1)
    )


GRID_RGB = (215, 215, 215)
HEADER_PX = 18  # the band above the lattice: round counter and legend


def _annotate(Image, ImageDraw, lattice, round_no: int, total: int,
              legend: list[tuple[str, tuple[int, int, int]]]):
    """The lattice picture under a header: ``round k/N`` and a swatch per state."""
    width = max(lattice.width, 90 + 70 * len(legend))
    out = Image.new("RGB", (width, lattice.height + HEADER_PX), EMPTY_RGB)
    out.paste(lattice, (0, HEADER_PX))
    draw = ImageDraw.Draw(out)
    draw.text((4, 3), f"round {round_no}/{total}", fill=(0, 0, 0))
    x = 90
    for name, rgb in legend:
        draw.rectangle((x, 4, x + 9, 13), fill=rgb, outline=(0, 0, 0))
        draw.text((x + 13, 3), name, fill=(0, 0, 0))
        x += 70
    return out


def save(path: str, rec: Recorder, obstacles: list[Cell], cell_px: int = 0) -> None:
    """PNG: the last frame. GIF: one frame per recorded round. Each picture
    has the lattice grid, a round counter and a legend of the states shown."""
    Image = require("PIL.Image", "plot", "--render (PNG, GIF)")
    ImageDraw = require("PIL.ImageDraw", "plot", "--render (PNG, GIF)")
    suffix = Path(path).suffix.lower()
    if suffix not in (".png", ".gif"):
        raise ScenarioError(f"--render: {path!r} must end in .png or .gif")
    rec.close()
    if not rec.frames:
        raise ScenarioError("nothing was recorded")
    x0, y0, x1, y1 = _bounds(rec.box)
    w, h = x1 - x0 + 1, y1 - y0 + 1
    px = cell_px or max(2, min(16, 1200 // max(w, h)))
    base = np.zeros((h, w, 3), dtype=np.uint8)
    base[:] = EMPTY_RGB
    for x, y in obstacles:
        if x0 <= x <= x1 and y0 <= y <= y1:
            base[y1 - y, x - x0] = OBSTACLE_RGB
    palette = np.array(
        [COLOURS.get(s, (120, 120, 120)) for s in rec.states], dtype=np.uint8
    )

    shown = sorted({int(v) for _, st in rec.frames for v in np.unique(st)})
    legend = [("obstacle", OBSTACLE_RGB)] + [(rec.states[k], tuple(int(c) for c in palette[k]))
                                             for k in shown]
    total = rec.rounds[-1] if rec.rounds else 0

    def frame(xy: np.ndarray, st: np.ndarray, round_no: int) -> Image.Image:
        img = base.copy()
        img[y1 - xy[:, 1], xy[:, 0] - x0] = palette[st]
        big = np.kron(img, np.ones((px, px, 1), dtype=np.uint8))
        if px >= 4:  # the lattice grid: one line between cells
            big[::px, :] = np.where(big[::px, :] == EMPTY_RGB, GRID_RGB, big[::px, :])
            big[:, ::px] = np.where(big[:, ::px] == EMPTY_RGB, GRID_RGB, big[:, ::px])
        return _annotate(Image, ImageDraw, Image.fromarray(big), round_no, total, legend)

    rounds = rec.rounds or list(range(len(rec.frames)))
    try:
        if suffix == ".png":
            frame(*rec.frames[-1], rounds[-1]).save(path)
        else:
            images = [frame(*f, r) for f, r in zip(rec.frames, rounds, strict=True)]
            images[0].save(
                path, save_all=True, append_images=images[1:], duration=80, loop=0
            )
    except OSError as exc:
        raise ScenarioError(f"--render: cannot write {path}: {exc}") from exc
