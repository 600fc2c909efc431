"""The strip route's searches in Python: the reference the C searches
(``planning/_strip.c``) are compared with, path for path.

They are the searches canonical.to_strip ran in Python until session 17,
written over the generic ``robust._moves_from`` (the rotations open at a cell,
in ROTATIONS order) instead of canonical's own mask table, so the two sides
share only Table 4-3 itself.
"""

from __future__ import annotations

from collections import deque

from hexbot.planning.configuration import articulation_points
from hexbot.planning.robust import _moves_from, _single_arc, unwind
from hexbot.planning.surface import rolling_distances

FARTHEST = 4


def path_to(occupied, start, target):
    """Breadth-first rotations of the module at ``start`` (counted as absent) to ``target``."""
    parent = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        for rule, sub, goal in _moves_from(cell, occupied, start):
            if goal in parent:
                continue
            parent[goal] = (cell, rule, sub)
            if goal == target:
                return unwind(parent, goal)
            queue.append(goal)
    return None


def distances_to(occupied, target):
    """Rotations from each cell a module rolls to ``target`` from, every module fixed."""
    return rolling_distances(occupied, [target])


def first_steps(occupied, cell):
    return [goal for _, _, goal in _moves_from(cell, occupied, cell)]


def nearest(occupied, cells, target):
    dist = distances_to(occupied, target)
    out = []
    for k, cell in enumerate(cells):
        near = [dist[g] for g in first_steps(occupied, cell) if g in dist]
        if near:
            out.append((min(near), k))
    return out


def pick_mover(occupied, order, target, farthest=0):
    """canonical._pick_mover as it was in Python."""
    for k in range(min(farthest, FARTHEST)):
        path = path_to(occupied, order[k], target)
        if path:
            return k, path
    reach = distances_to(occupied, target)
    likely, unsure = [], []
    for k, cell in enumerate(order):
        if not any(g in reach for g in first_steps(occupied, cell)):
            continue
        likely.append(k)
        if k < farthest or _single_arc(occupied, cell):
            path = path_to(occupied, cell, target)
            if path:
                return k, path
        else:
            unsure.append(k)
    cuts = articulation_points(occupied)
    for k in unsure:
        if order[k] not in cuts:
            path = path_to(occupied, order[k], target)
            if path:
                return k, path
    tried = set(likely)
    for k, cell in enumerate(order):
        if k not in tried and cell not in cuts:
            path = path_to(occupied, cell, target)
            if path:
                return k, path
    return None
