"""Is the robot still one edge-connected piece after a round?

A full search every round would cost O(n) Python work per round, too slow for
10,000 modules over 10,000 rounds. Most rounds are cheap to certify instead:

  1. every moved module lands next to a module that did not move, so the old
     robot plus the landing cells is connected;
  2. no two vacated cells touch (8-neighbourhood), so each vacated cell can be
     judged on its own ring of 8 neighbours;
  3. each vacated cell is *simple*: its edge neighbours are joined within its
     ring (one run of occupied ring cells holds all of them), so emptying it
     cannot cut a path.

If the certificate fails, a breadth-first search decides. The certificate is
sufficient, never necessary, so the answer is always exact.
"""

from __future__ import annotations

from collections import deque

import numpy as np

# Ring order: E, NE, N, NW, W, SW, S, SE. Consecutive ring cells share an edge;
# even positions are the edge neighbours of the centre.
RING: tuple[tuple[int, int], ...] = (
    (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1),
)


def _ring_components(mask: int) -> int:
    """Runs of occupied ring cells that contain an edge neighbour."""
    bits = [(mask >> i) & 1 for i in range(8)]
    if all(bits):
        return 1
    start = bits.index(0)
    runs, in_run, has_edge = 0, False, False
    for k in range(1, 9):
        i = (start + k) % 8
        if bits[i]:
            if not in_run:
                in_run, has_edge = True, False
            has_edge |= i % 2 == 0
        elif in_run:
            runs += has_edge
            in_run = False
    if in_run:
        runs += has_edge
    return runs


SIMPLE = np.array([_ring_components(m) <= 1 for m in range(256)], dtype=bool)


def ring_offsets(height: int) -> np.ndarray:
    return np.array([dx * height + dy for dx, dy in RING], dtype=np.int64)


def certify(
    flat: np.ndarray, height: int, vacated: np.ndarray, landed: np.ndarray
) -> bool:
    """True when the certificate above proves the robot connected.

    ``flat`` is the grid after the round (codes >= 2 are modules); ``vacated``
    and ``landed`` are the flat cells left and entered by the movers.
    """
    ring = ring_offsets(height)
    edges = ring[0::2]
    is_landed = np.zeros(flat.size, dtype=bool)
    is_landed[landed] = True
    neigh = landed[:, None] + edges[None, :]
    anchored = ((flat[neigh] >= 2) & ~is_landed[neigh]).any(axis=1)
    if not anchored.all():
        return False
    is_vacated = np.zeros(flat.size, dtype=bool)
    is_vacated[vacated] = True
    around = vacated[:, None] + ring[None, :]
    if is_vacated[around].any():
        return False
    mask = ((flat[around] >= 2).astype(np.int64) << np.arange(8)).sum(axis=1)
    return bool(SIMPLE[mask].all())


def connected(flat: np.ndarray, height: int, cells: np.ndarray) -> bool:
    """Breadth-first search over the module cells (codes >= 2)."""
    if cells.size <= 1:
        return True
    todo = set(cells.tolist())
    start = todo.pop()
    queue = deque([start])
    steps = (1, -1, height, -height)
    while queue:
        c = queue.popleft()
        for s in steps:
            n = c + s
            if n in todo:
                todo.remove(n)
                queue.append(n)
    return not todo


def components(flat: np.ndarray, height: int, cells: np.ndarray) -> list[list[int]]:
    """The connected pieces (flat cells), largest first, for violation reports."""
    todo = set(cells.tolist())
    pieces: list[list[int]] = []
    steps = (1, -1, height, -height)
    while todo:
        start = todo.pop()
        piece, queue = [start], deque([start])
        while queue:
            c = queue.popleft()
            for s in steps:
                n = c + s
                if n in todo:
                    todo.remove(n)
                    piece.append(n)
                    queue.append(n)
        pieces.append(piece)
    return sorted(pieces, key=len, reverse=True)
