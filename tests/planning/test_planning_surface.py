"""Surface segments: where a module can roll with every other module fixed."""

from collections import deque

from hexbot.planning.generate import parallelogram
from hexbot.planning.hexlattice import distance
from hexbot.planning.middle import ball
from hexbot.planning.surface import border, rolling_distances, surface_segments
from hexbot.protocol.rotation_geometry import ROTATIONS

#: A 7-module shape whose border splits: a one-cell inlet cuts off three cells.
INLET = {(-1, -1), (-1, 0), (-1, 1), (0, 0), (0, 1), (1, -1), (1, 1)}


def rolls_from(occupied, start):
    """Cells a module at ``start`` can reach, straight from Table 4-3's rows."""
    seen, queue = {start}, deque([start])
    while queue:
        cell = queue.popleft()
        for rule in ROTATIONS:
            sub, goal, swept = rule.at(cell)
            if sub in occupied and goal not in occupied and goal not in seen \
                    and not any(c in occupied for c in swept):
                seen.add(goal)
                queue.append(goal)
    return seen


def test_a_module_rolls_all_around_smooth_shapes():
    for shape in (parallelogram(10, 3), ball((0, 0), 100), frozenset((x, 0) for x in range(10))):
        segments = surface_segments(shape)
        assert len(segments) == 1
        assert segments[0] == border(shape)


def test_rolling_along_a_flat_side_takes_one_rotation_per_cell():
    bar = {(x, 0) for x in range(10)}
    dist = rolling_distances(bar, [(0, 1)])
    assert [dist[(x, 1)] for x in range(10)] == [distance((0, 1), (x, 1)) for x in range(10)]
    # around the end of the bar and back along the underside
    assert dist[(9, -1)] > distance((0, 1), (9, -1))


def test_a_one_cell_inlet_cuts_the_border_and_no_rotation_crosses_it():
    segments = surface_segments(INLET)
    sizes = [len(s) for s in segments]
    assert sizes == [11, 3, 1, 1]
    big, small = segments[0], segments[1]
    for cell in small:
        assert not rolls_from(INLET, cell) & big
    for cell in big:
        assert rolls_from(INLET, cell) & border(INLET) == big
    # the inlet cells themselves: four occupied sides, no rotation leaves them
    for lone in segments[2:]:
        (cell,) = lone
        assert rolls_from(INLET, cell) == {cell}


def test_the_bench_blobs_are_rough_and_the_ball_is_not():
    from hexbot.bench.planning import make_pair

    start, goal = make_pair("blob", 100, 0)
    for shape in (start, goal):
        segments = surface_segments(shape)
        assert len(segments) > 1
        assert len(segments[0]) < len(border(shape))
    assert len(surface_segments(ball((0, 0), 100))) == 1
