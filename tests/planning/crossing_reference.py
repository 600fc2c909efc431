"""The crossing search in Python: the reference the C search
(``planning/_crossing.c``) is compared with, state for state.

It is the search journey.crossing ran in Python until session 16; it builds its
own index of the window from ``journey._DISCS`` cells, so it shares no table
with the C side except the rules themselves (robust._OPEN12, windows._LEAVABLE).
"""

from __future__ import annotations

import heapq

from hexbot.planning.hexlattice import neighbors
from hexbot.planning.journey import _DISCS, _FAR
from hexbot.planning.robust import _AROUND12, _OPEN12, _RULES
from hexbot.planning.windows import _LEAVABLE


class _Index:
    def __init__(self, radius: int):
        geometry = _DISCS[radius]
        cells, size = geometry.cells, geometry.size
        index = {c: i for i, c in enumerate(cells)}
        window = cells[:size]
        inside = set(window)
        self.cells, self.size, self.center = cells, size, index[(0, 0)]
        self.ring6 = [tuple(index[n] for n in neighbors(c)) for c in window]
        self.ring12 = [tuple(index[(x + dx, y + dy)] for dx, dy in _AROUND12) for x, y in window]
        self.near = [sum(1 << index[n] for n in (c, *neighbors(c))) for c in window]
        goals = {goal for _, _, goal, _ in _RULES}
        self.goal_bit = [{g: 1 << index[(x + g[0], y + g[1])] for g in goals
                          if (x + g[0], y + g[1]) in inside} for x, y in window]


_INDEX: dict[int, _Index] = {}


def _leaves(whole: int, ring: tuple[int, ...]) -> bool:
    return _LEAVABLE[sum((whole >> r & 1) << k for k, r in enumerate(ring))]


def reference_crossing(occupied, traveller, radius, steps, fixed, max_states):
    """(hops, arrived) or None, as journey.crossing (no ``failed`` memory)."""
    geometry = _INDEX.get(radius) or _INDEX.setdefault(radius, _Index(radius))
    cells, size = geometry.cells, geometry.size
    tx, ty = traveller
    absolute = [(tx + x, ty + y) for x, y in cells]
    bits = [c in occupied for c in absolute]
    start = sum(1 << i for i in range(size) if bits[i])
    outside = sum(1 << i for i in range(size, len(cells)) if bits[i])
    bound = steps.get(traveller, _FAR)
    home = start & ~(1 << geometry.center)
    pinned = sum(1 << i for i in range(size) if absolute[i] == fixed)
    whole = outside | start
    movable = {start: sum(1 << i for i in range(size)
                          if start >> i & 1 and _leaves(whole, geometry.ring6[i])) & ~pinned}
    parent: dict[int, tuple | None] = {start: None}
    cost = {start: 0}
    heap = [(1, 0, start)]
    tie = 0
    while heap and len(parent) < max_states:
        _, _, state = heapq.heappop(heap)
        whole = outside | state
        free = movable.get(state)
        if free is None:
            before = parent[state][0]
            changed = before ^ state
            src = (changed & -changed).bit_length() - 1
            dst = changed.bit_length() - 1
            around = geometry.near[src] | geometry.near[dst]
            free = movable[before] & ~around
            check = around & state & ~pinned
            while check:
                low = check & -check
                check ^= low
                if _leaves(whole, geometry.ring6[low.bit_length() - 1]):
                    free |= low
            movable[state] = free
        while free:
            low = free & -free
            free ^= low
            i = low.bit_length() - 1
            mask = sum((whole >> r & 1) << k for k, r in enumerate(geometry.ring12[i]))
            for rule, sub, goal in _OPEN12[mask]:
                target = geometry.goal_bit[i].get(goal)
                if target is None:
                    continue
                after = state ^ low ^ target
                if after in parent:
                    continue
                parent[after] = (state, i, target, rule, sub)
                cost[after] = cost[state] + 1
                away = (home & ~after).bit_count()
                if away == 0:
                    arrived = absolute[(after & ~home).bit_length() - 1]
                    if steps.get(arrived, _FAR) < bound:
                        return _hops(parent, after, absolute), arrived
                tie += 1
                heapq.heappush(heap, (cost[after] + away + 1, tie, after))
    return None


def _hops(parent, state, absolute):
    hops = []
    while parent[state] is not None:
        state, i, target, rule, (sx, sy) = parent[state]
        x, y = absolute[i]
        hops.append(((x, y), absolute[target.bit_length() - 1], rule, (x + sx, y + sy)))
    return hops[::-1]
