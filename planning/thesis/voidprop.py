"""Layer 3: void propagation (``HexVPT`` and ``HexVP``).

Each potential void sends a wavefront over empty cells that touch an
immobile module; the first mobile electron the wave reaches (earliest time
step, then MATLAB scan order) is that void's partner. ``HexVP`` pairs the
void with the earliest partner overall, removes both, and repeats.

Listing defect: ``HexVPT`` recomputes the mobile electrons from scratch, so
``HexVP`` can give one electron to two voids. ``exclude_assigned=True``
(the default) lets the wave skip electrons already paired; ``False`` keeps
the listing's behaviour. A void whose wave reaches no electron is never
paired (the listing would index row 0 and stop with an error).
"""

from __future__ import annotations

from dataclasses import dataclass

from hexbot.planning.hexlattice import Cell, column_major_key, neighbors
from hexbot.planning.thesis.layers import (
    find_ve,
    immobile_modules,
    mobile_electrons,
    potential_voids,
)

Cells = frozenset[Cell]


@dataclass(frozen=True)
class Pair:
    """One row of ``PVME``: a potential void, its mobile electron, the wave time."""

    void: Cell
    electron: Cell
    time: int


def propagate(
    current: Cells, mobile: list[Cell], void: Cell, targets: set[Cell] | None = None
) -> list[tuple[Cell, int]]:
    """``HexVPT``: (electron, time step) in the order the wave meets them.

    Mobile electrons count as empty cells (the listing's ``I = I - ME``); a
    cell joins the wave when it is empty and touches an immobile module
    (``HexIMS``). The wave stops when every target was met or it dies out.
    """
    fixed = immobile_modules(current, mobile)
    targets = set(mobile) if targets is None else set(targets)
    hits: list[tuple[Cell, int]] = []
    found: set[Cell] = set()
    reached = {void}
    frontier = [void]
    t = 1
    while frontier and not targets <= found:
        new: set[Cell] = set()
        for node in frontier:
            for n in neighbors(node):
                if n in fixed:
                    continue
                if n not in reached and any(m in fixed for m in neighbors(n)):
                    new.add(n)
                if n in targets:
                    hits.append((n, t))
                    found.add(n)
        reached |= new
        frontier = sorted(new, key=column_major_key)
        t += 1
    return hits


def pair_voids(current: Cells, goal: Cells, exclude_assigned: bool = True) -> list[Pair]:
    """``HexVP``: pair potential voids with mobile electrons, earliest first."""
    _, electrons = find_ve(current, goal)
    mobile = mobile_electrons(electrons, current)
    open_voids = potential_voids(current, goal, mobile)
    free = set(mobile)
    pairs: list[Pair] = []
    while free and open_voids:
        best: tuple[int, int, Cell] | None = None  # (time, index, electron)
        for index, void in enumerate(open_voids):
            targets = free if exclude_assigned else set(mobile)
            hits = propagate(current, mobile, void, targets)
            if hits and (best is None or hits[0][1] < best[0]):
                best = (hits[0][1], index, hits[0][0])
        if best is None:
            break
        time, index, electron = best
        void = open_voids.pop(index)
        pairs.append(Pair(void, electron, time))
        free.discard(electron)
    return pairs
