"""Layer 4: the MDP of one mobile electron (``MDP_State`` .. ``MDP_NRL``).

States: empty cells (mobile electrons count as empty) touching one to three
immobile modules. Rewards: +1 at the potential void, -1 at the other mobile
electrons, -0.04 elsewhere. Actions: move to a neighbouring state or stay;
transitions are deterministic. Value iteration updates the states in MATLAB
order, in place, until the largest increase of a sweep is at most 0.001 or
500 sweeps; the values are then normalised by their maximum.

Listing defects, and what is done here:

* ``MDP_VI`` takes the maximum over the first two or three entries of the
  action list only (and would index cell (0, 0) for a state whose only
  action is to stay). ``action_limit=None`` (default) uses every action, as
  the Bellman equation (4.11) says; ``action_limit=3`` keeps the listing.
* ``MDP_NRL`` loops with ``i`` but indexes with ``j``; the loop variable is
  used. Cells that are not states keep value 0, so, as in the listing, a
  neighbour that is not a state can be recommended when the electron's own
  value is negative; layer 5 then finds no rotation and the planner stalls.
"""

from __future__ import annotations

from hexbot.planning.configuration import occupied_neighbors
from hexbot.planning.hexlattice import Cell, column_major_key, neighbors
from hexbot.planning.thesis.layers import find_ve, mobile_electrons

Cells = frozenset[Cell]

STEP_REWARD = -0.04
GOAL_REWARD = 1.0
OTHER_ELECTRON_REWARD = -1.0
DISCOUNT = 0.7
TOLERANCE = 0.001
MAX_SWEEPS = 500


def mdp_states(current: Cells, goal: Cells) -> frozenset[Cell]:
    """``MDP_State``."""
    _, electrons = find_ve(current, goal)
    fixed = current - set(mobile_electrons(electrons, current))
    candidates = {n for c in fixed for n in neighbors(c) if n not in fixed}
    return frozenset(c for c in candidates if occupied_neighbors(fixed, c) <= 3)


def mdp_reward(current: Cells, goal: Cells, electron: Cell, void: Cell) -> dict[Cell, float]:
    """``MDP_Reward``: cells absent from the result have reward 0."""
    reward = {s: STEP_REWARD for s in mdp_states(current, goal)}
    reward[void] = GOAL_REWARD
    _, electrons = find_ve(current, goal)
    for other in mobile_electrons(electrons, current):
        if other != electron:
            # the listing subtracts 0.96, so a state holding an electron ends at -1
            reward[other] = reward.get(other, 0.0) - (GOAL_REWARD + STEP_REWARD)
    return reward


def mdp_actions(cell: Cell, states: frozenset[Cell]) -> list[Cell]:
    """``MDP_Action``: neighbouring states in side order, then staying put."""
    return [n for n in neighbors(cell) if n in states] + [cell]


def value_iteration(
    current: Cells,
    goal: Cells,
    electron: Cell,
    void: Cell,
    discount: float = DISCOUNT,
    action_limit: int | None = None,
) -> tuple[dict[Cell, float], int]:
    """``MDP_VI``: (normalised values, sweeps done). Values of non-states are 0."""
    states = mdp_states(current, goal)
    reward = mdp_reward(current, goal, electron, void)
    order = sorted(states, key=column_major_key)
    actions = {s: mdp_actions(s, states) for s in order}
    if action_limit is not None:
        actions = {s: a[:action_limit] for s, a in actions.items()}
    values: dict[Cell, float] = dict.fromkeys(order, 0.0)
    sweeps = 0
    while True:
        sweeps += 1
        increase = 0.0  # the listing's abs(max(max(U - U_old))) over a zero-padded matrix
        for s in order:
            new = reward.get(s, 0.0) + discount * max(values.get(a, 0.0) for a in actions[s])
            increase = max(increase, new - values[s])
            values[s] = new
        if increase <= TOLERANCE or sweeps >= MAX_SWEEPS:
            break
    top = max([0.0, *values.values()])
    if top > 0:
        values = {s: v / top for s, v in values.items()}
    else:
        # MATLAB divides by zero here: every comparison in MDP_NRL fails, the electron stays
        values = {s: float("nan") for s in values}
    return values, sweeps


def next_location(
    current: Cells,
    goal: Cells,
    electron: Cell,
    void: Cell,
    discount: float = DISCOUNT,
    action_limit: int | None = None,
) -> Cell:
    """``MDP_NRL``: the neighbour with the highest value above the electron's own."""
    values, _ = value_iteration(current, goal, electron, void, discount, action_limit)
    best_cell, best = electron, values.get(electron, 0.0)
    if best != best:  # NaN: see value_iteration
        return electron
    for n in neighbors(electron):
        v = values.get(n, 0.0)
        if v > best:
            best_cell, best = n, v
    return best_cell
