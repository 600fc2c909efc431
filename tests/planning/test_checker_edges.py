"""The independent checker at its edges: every rule of a step rejects a move
that breaks it, also when the rest of the move (and the step) is legal."""

from hexbot.planning.checker import check_plan
from hexbot.planning.configuration import Configuration, is_connected
from hexbot.planning.generate import random_blob
from hexbot.planning.hexlattice import neighbors
from hexbot.planning.moves import Move
from hexbot.planning.plan import Step
from hexbot.protocol.rotation_geometry import ROTATIONS

# a bar of three on the x axis: (0,0) (1,0) (2,0), ids 1, 2, 3 (reading order)
BAR = Configuration.from_cells([(0, 0), (1, 0), (2, 0)])


def rotations(config: Configuration, free=frozenset()):
    """Every Table 4-3 rotation whose substrate is occupied and whose end and
    swept cells are empty (cells in ``free`` count as empty): geometry only."""
    def taken(c):
        return c in config and c not in free

    for cell in sorted(config.cells):
        for rule in ROTATIONS:
            sub, goal, swept = rule.at(cell)
            if taken(sub) and not taken(goal) and not any(taken(c) for c in swept):
                yield Move(config[cell].id, cell, goal, rule.joint, rule.direction, sub,
                           config[sub].id)


def footprint(move: Move) -> set:
    return {move.src, move.dst, *move.swept()}


def after(config: Configuration, moves) -> frozenset:
    return (config.cells - {m.src for m in moves}) | {m.dst for m in moves}


def blobs():
    for seed in range(60):
        yield Configuration.from_cells(random_blob(8 + seed % 10, seed, 0.2))


def first_pair(accept):
    """The first (config, a, b) of the blobs with ``accept(config, a, b)``."""
    for config in blobs():
        for a in rotations(config):
            for b in rotations(config, free={a.src}):
                if a.module != b.module and accept(config, a, b):
                    return config, a, b
    raise AssertionError("no such pair in the blobs")


def test_a_disconnected_initial_configuration_is_rejected():
    two_pieces = Configuration.from_cells([(0, 0), (1, 0), (5, 5), (6, 5)])
    report = check_plan(two_pieces, two_pieces.cells, [])
    assert not report.ok and "not one piece" in report.problem


def test_a_plan_that_ends_with_a_module_off_the_goal_is_rejected():
    report = check_plan(BAR, frozenset({(0, 0), (1, 0)}), [])
    assert not report.ok
    report = check_plan(BAR, frozenset({(0, 0), (1, 0), (2, 0), (3, 0)}), [])
    assert not report.ok and "short of the goal" in report.problem


def test_a_move_naming_another_module_at_its_start_is_rejected():
    move = next(rotations(BAR))
    other = next(m.id for c, m in BAR.items() if c != move.src and m.id != move.substrate_module)
    wrong = Move(other, move.src, move.dst, move.joint, move.direction, move.substrate,
                 move.substrate_module)
    report = check_plan(BAR, after(BAR, [move]), [Step([wrong])])
    assert not report.ok and report.problem == f"step 1: module {other} is not at {move.src}"


def test_a_move_over_the_wrong_substrate_cell_or_module_is_rejected():
    move = next(m for m in rotations(BAR) if m.src == (2, 0))  # over (1, 0), module 2
    end = after(BAR, [move])
    wrong_cell = Move(move.module, move.src, move.dst, move.joint, move.direction, (0, 0),
                      BAR[(0, 0)].id)
    report = check_plan(BAR, end, [Step([wrong_cell])])
    assert not report.ok and "step 1:" in report.problem and "over" in report.problem
    wrong_module = Move(move.module, move.src, move.dst, move.joint, move.direction,
                        move.substrate, BAR[(0, 0)].id)
    report = check_plan(BAR, end, [Step([wrong_module])])
    assert not report.ok and "is not module 1" in report.problem
    assert check_plan(BAR, end, [Step([move])]).ok  # the move as it is


def test_a_move_onto_a_cell_held_by_a_module_that_stays_is_rejected():
    # the end cell is taken; the swept cells are free
    move = next(rotations(BAR))
    blocked = Configuration.from_cells([*BAR.cells, move.dst])
    ids = {c: m.id for c, m in blocked.items()}
    step = Step([Move(ids[move.src], move.src, move.dst, move.joint, move.direction,
                      move.substrate, ids[move.substrate])])
    assert not any(c in blocked for c in move.swept())
    report = check_plan(blocked, blocked.cells - {move.src}, [step])
    assert not report.ok and report.steps == 0
    assert report.problem.startswith("step 1:") and f"cell {move.dst} is occupied" in report.problem


def test_a_substrate_that_moves_in_the_same_step_is_rejected():
    def fits(config, a, b):
        return (a.substrate == b.src and b.substrate != a.src
                and not footprint(a) & footprint(b)
                and is_connected(config.cells - {a.src, b.src}))

    config, a, b = first_pair(fits)
    report = check_plan(config, after(config, [a, b]), [Step([a, b])])
    assert not report.ok and f"substrate {a.substrate} is empty or moving" in report.problem


def test_a_move_into_the_cell_another_mover_leaves_in_the_step_is_rejected():
    # b ends on (or sweeps) the cell a starts from: the two bodies would collide
    def fits(config, a, b):
        rest = footprint(a) - {a.src}
        return (a.src in footprint(b) - {b.src} and b.src not in footprint(a)
                and not rest & footprint(b)
                and {a.substrate, b.substrate}.isdisjoint({a.src, b.src})
                and is_connected(config.cells - {a.src, b.src}))

    config, a, b = first_pair(fits)
    for order in ([a, b], [b, a]):
        report = check_plan(config, after(config, order), [Step(order)])
        assert not report.ok and f"both need cell {a.src}" in report.problem


def test_a_two_move_step_that_splits_the_rest_is_rejected_whichever_moves_first():
    # a: a leaf module rolling over its one neighbour; b: a module whose leaving
    # cuts the configuration in two
    def fits(config, a, b):
        leaf = sum(n in config for n in neighbors(a.src)) == 1
        return (leaf and not footprint(a) & footprint(b)
                and {a.substrate, b.substrate}.isdisjoint({a.src, b.src})
                and is_connected(config.cells - {a.src})
                and not is_connected(config.cells - {b.src}))

    config, a, b = first_pair(fits)
    for order in ([a, b], [b, a]):
        report = check_plan(config, after(config, order), [Step(order)])
        assert not report.ok and "fall apart" in report.problem


def test_a_module_given_two_moves_in_one_step_is_rejected_not_a_crash():
    # (fixed in this audit: the replay deleted the start cell twice, a KeyError)
    first, second = [m for m in rotations(BAR) if m.src == (2, 0)][:2]
    for step in (Step([first, first]), Step([first, second])):
        report = check_plan(BAR, after(BAR, [first]), [step])
        assert not report.ok
        assert report.problem == "step 1: the module at (2, 0) is given two moves in one step"


def test_the_plans_own_step_check_also_refuses_a_module_with_two_moves():
    # plan.check_step (the thesis modes' check) let it pass: two moves of one
    # module never "share a cell" with another module
    from hexbot.planning.plan import check_step

    first, second = [m for m in rotations(BAR) if m.src == (2, 0)][:2]
    for step in (Step([first, first]), Step([first, second])):
        problems = check_step(BAR, step)
        assert "the module at (2, 0) is given 2 moves in one step" in problems
    assert check_step(BAR, Step([first])) == []
