"""The rotation model: Table 3-1 sequences move the mobile, every refusal has a reason."""

import pytest

from hexbot.hil_sim.geometry import Rotation, distance, neighbor, to_global
from hexbot.hil_sim.plant import NEG, OFF, POS, Plant
from hexbot.protocol.simulation import verdict_from_record

MS = 1000  # cycles per millisecond at 1 MHz


def joints(*open_):
    return tuple(j in open_ for j in range(1, 7))


def magnets(**sides):
    """magnets(s3="-", s4="-") -> body-side polarity tuple."""
    values = {"-": NEG, "+": POS}
    return tuple(values[sides[f"s{s}"]] if f"s{s}" in sides else OFF for s in range(1, 7))


class Rig:
    """The pair scenario: substrate 1 at the origin (fixed), mobile 2 at (-1, 1)."""

    def __init__(self, extra=(), mobile_fixed=False):
        self.events = []
        self.plant = Plant(1e6, emit=lambda c, e: self.events.append({"cycle": c, **e}))
        self.plant.add(1, (0, 0), 0, fixed=True)
        self.plant.add(2, (-1, 1), 0, fixed=mobile_fixed)
        for i, cell in enumerate(extra, start=3):
            self.plant.add(i, cell, 0)
        self.state = {m: [joints(), magnets()] for m in self.plant.bodies}

    def at(self, ms, module, j=None, m=None):
        if j is not None:
            self.state[module][0] = j
        if m is not None:
            self.state[module][1] = m
        self.plant.set_outputs(module, ms * MS, *self.state[module])

    def finish(self, ms=2000):
        self.plant.step(ms * MS)
        return self.events


def thesis_cw(rig, mobile_start=0, substrate_start=0, mobile_joint=4, substrate_sides=(1, 2)):
    """Table 3-1, CW about joint i (mobile) with the thesis timings."""
    i = mobile_joint
    w = lambda k: (k - 1) % 6 + 1  # noqa: E731
    t = mobile_start
    rig.at(t, 2, j=joints(w(i + 1)))
    rig.at(t + 80, 2, m=magnets(**{f"s{w(i - 1)}": "-", f"s{w(i)}": "-"}))
    rig.at(t + 125, 2, j=joints(w(i + 1), w(i)))
    rig.at(t + 215, 2, j=joints())
    rig.at(t + 216, 2, m=magnets())
    t = substrate_start
    near, far = substrate_sides
    rig.at(t, 1, j=joints(near, far))
    rig.at(t + 80, 1, m=magnets(**{f"s{near}": "-", f"s{far}": "+"}))
    rig.at(t + 120, 1, j=joints())
    rig.at(t + 216, 1, m=magnets())


def thesis_ccw(rig):
    """Table 3-1, CCW about joint i = 5 of the mobile; the substrate's side 1 faces it."""
    rig.at(0, 2, j=joints(5, 4))
    rig.at(0, 1, j=joints())
    rig.at(80, 2, m=magnets(s4="-", s5="-"))
    rig.at(80, 1, m=magnets(s1="-", s6="+"))
    rig.at(120, 2, j=joints(4))
    rig.at(125, 1, j=joints(6, 1))
    rig.at(215, 2, j=joints())
    rig.at(215, 1, j=joints())
    rig.at(216, 2, m=magnets())
    rig.at(216, 1, m=magnets())


def single_event(events):
    assert len(events) == 1, events
    return events[0]


def test_thesis_cw_about_joint_4_lands_on_the_goal_turned_120_degrees():
    rig = Rig()
    thesis_cw(rig)
    event = single_event(rig.finish())
    assert event["event"] == "moved"
    assert (event["from"], event["to"], event["orientation"]) == ([-1, 1], [0, 1], 2)
    assert event["direction"] == "CW" and event["substrate"] == 1
    assert rig.plant.bodies[2].cell == (0, 1) and rig.plant.module_at((-1, 1)) is None


def test_thesis_ccw_about_joint_5_lands_on_the_other_side():
    rig = Rig()
    thesis_ccw(rig)
    event = single_event(rig.finish())
    assert event["event"] == "moved"
    assert (event["to"], event["orientation"], event["direction"]) == ([-1, 0], 4, "CCW")


def test_rotated_module_uses_its_body_sides():
    # After the CW move (orientation 2) the substrate is on the mobile's body side 3
    # (global side 5): a second CW about body joint 3 goes on round it to (1, 0), with
    # the substrate's side 2 facing the mobile and side 3 facing the goal.
    rig = Rig()
    thesis_cw(rig)
    rig.finish(1000)
    rig.events.clear()
    thesis_cw(rig, 2000, 2000, mobile_joint=3, substrate_sides=(2, 3))
    event = single_event(rig.finish(4000))
    assert event["event"] == "moved" and event["to"] == [1, 0] and event["orientation"] == 4


def test_occupied_goal_is_refused():
    rig = Rig(extra=[(0, 1)])
    thesis_cw(rig)
    event = single_event(rig.finish())
    assert (event["event"], event["reason"]) == ("refused", "occupied cell")
    assert event["cells"] == [[0, 1]]
    assert rig.plant.bodies[2].cell == (-1, 1)


def test_occupied_swept_cell_is_refused():
    rig = Rig(extra=[(-1, 2)])  # the mobile's side 2, swept by CW about joint 4
    thesis_cw(rig)
    assert single_event(rig.finish())["reason"] == "occupied cell"


def test_wrong_joint_index_finds_no_substrate():
    rig = Rig()
    thesis_cw(rig, mobile_joint=2)  # pivot between sides 1 and 2: nobody on either
    events = rig.finish()
    assert [e["reason"] for e in events if e["module"] == 2][0] == "no substrate"
    assert rig.plant.bodies[2].cell == (-1, 1)


def test_wrong_polarity_is_refused():
    rig = Rig()
    thesis_cw(rig)
    rig.plant.bodies[1].pulses[-1].magnets = magnets(s1="+", s2="-")  # swapped lines
    events = rig.finish()
    assert events[0]["reason"] == "wrong polarity"


def test_onsets_too_far_apart_are_a_timing_refusal():
    rig = Rig()
    thesis_cw(rig, mobile_start=0, substrate_start=60)
    event = single_event(rig.finish())
    assert event["reason"] == "timing" and "onsets" in event["detail"]


def test_magnets_released_too_early_are_a_timing_refusal():
    rig = Rig()
    rig.at(0, 2, j=joints(5))
    rig.at(0, 1, j=joints(1, 2))
    rig.at(80, 2, m=magnets(s3="-", s4="-"))
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(130, 2, m=magnets())
    rig.at(130, 1, m=magnets())
    assert single_event(rig.finish())["reason"] == "timing"


def test_far_joint_left_closed_latches_the_mobile():
    rig = Rig()
    thesis_cw(rig)
    rig.plant.bodies[2].joint_log.clear()  # the mobile never opened J5 ...
    rig.plant.bodies[1].joint_log.clear()  # ... nor the substrate its J1 at the same vertex
    event = single_event(rig.finish())
    assert event["reason"] == "latched joint" and "J5" in event["detail"]


def test_no_pin_left_at_the_pivot_is_refused():
    rig = Rig()
    rig.at(0, 2, j=joints(5, 4))  # the mobile opens its pivot J4 as well ...
    rig.at(0, 1, j=joints(1, 2))  # ... and the substrate its J2 at the same vertex
    rig.at(80, 2, m=magnets(s3="-", s4="-"))
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(215, 2, j=joints(), m=magnets())
    rig.at(215, 1, j=joints(), m=magnets())
    assert single_event(rig.finish())["reason"] == "no axle"


def listing_sequence(rig, mobile, substrate, i, t=(8, 4, 9)):
    """The Appendix A listing's MCW/MCCW and SCW/SCCW, as the firmware runs them."""
    w = lambda k: (k - 1) % 6 + 1  # noqa: E731
    t1, t2, t3 = (10 * x for x in t)
    if mobile == "CW":
        rig.at(0, 2, j=joints(i, w(i + 1)))
        rig.at(t1, 2, m=magnets(**{f"s{i}": "-", f"s{w(i - 1)}": "-"}))
        rig.at(t1 + t2, 2, j=joints())
        rig.at(t1 + t2 + t3, 2, m=magnets())
        rig.at(0, 1, j=joints(w(i - 1)))
        rig.at(t1, 1, m=magnets(**{f"s{w(i - 3)}": "-", f"s{w(i - 2)}": "+"}))
        rig.at(t1 + t2, 1, j=joints(w(i - 1), w(i - 2)))
        rig.at(t1 + t2 + t3, 1, j=joints(), m=magnets())
    else:
        rig.at(0, 2, j=joints(w(i + 1)))
        rig.at(t1, 2, m=magnets(**{f"s{i}": "-", f"s{w(i - 1)}": "-"}))
        rig.at(t1 + t2, 2, j=joints(w(i + 1), i))
        rig.at(t1 + t2 + t3, 2, j=joints(), m=magnets())
        rig.at(0, 1, j=joints(w(i - 3), w(i - 4)))
        rig.at(t1, 1, m=magnets(**{f"s{w(i - 4)}": "-", f"s{w(i - 5)}": "+"}))
        rig.at(t1 + t2, 1, j=joints())
        rig.at(t1 + t2 + t3, 1, m=magnets())


@pytest.mark.parametrize("direction,joint,goal,orientation", [("CW", 4, [0, 1], 2),
                                                               ("CCW", 5, [-1, 0], 4)])
def test_listing_sequences_rotate_too(direction, joint, goal, orientation):
    rig = Rig()
    listing_sequence(rig, direction, direction, joint)
    event = single_event(rig.finish())
    assert event["event"] == "moved", event
    assert (event["to"], event["orientation"]) == (goal, orientation)


def test_module_fixed_to_the_base_never_moves():
    rig = Rig(mobile_fixed=True)
    thesis_cw(rig)
    assert single_event(rig.finish())["reason"] == "fixed to base"


@pytest.mark.parametrize("delay_ms", [0, 10, 20])
def test_onsets_within_tolerance_still_move(delay_ms):
    rig = Rig()
    thesis_cw(rig, mobile_start=0, substrate_start=delay_ms)
    assert single_event(rig.finish())["event"] == "moved"


def test_next_deadline_is_when_a_finished_pulse_may_be_judged():
    rig = Rig()
    assert rig.plant.next_deadline(0) is None
    rig.at(0, 2, m=magnets(s3="-", s4="-"))
    assert rig.plant.next_deadline(0) is None  # held on: its end wakes the loop
    rig.at(100, 2, m=magnets())
    wait = round(rig.plant.timing.resolve_wait * 1e6)
    assert rig.plant.next_deadline(100 * MS) == 100 * MS + wait
    rig.plant.step(100 * MS + wait)  # judged: refused, nobody pushed
    assert rig.plant.next_deadline(100 * MS + wait) is None
    assert [e["event"] for e in rig.events] == ["refused"]


def test_geometry_version_counts_moves():
    rig = Rig()
    thesis_cw(rig)
    before = rig.plant.geometry_version
    rig.finish()
    assert [e["event"] for e in rig.events] == ["moved"]
    assert rig.plant.geometry_version == before + 1


def test_a_rotation_that_leaves_a_module_alone_says_the_cluster_split():
    # Module 3 touches only the mobile module 2: when 2 rotates away, the
    # mechanics let it, and the trace must say 3 is left on its own.
    rot = Rotation(to_global(4, 0), "CW")
    taken = {rot.goal_cell((-1, 1)), *rot.swept_cells((-1, 1)), (0, 0)}
    third = next(c for c in (neighbor((-1, 1), s) for s in range(1, 7))
                 if c not in taken and all(distance(c, o) > 1
                                           for o in [(0, 0), rot.goal_cell((-1, 1))]))
    rig = Rig(extra=[third])
    thesis_cw(rig)
    (moved,) = [e for e in rig.finish() if e["event"] == "moved"]
    assert moved["split"] == [3]
    verdict = verdict_from_record({**moved, "t": 0.0})
    assert verdict.split == (3,) and "module(s) 3 no longer touch it" in verdict.describe()


def test_an_ordinary_rotation_splits_nothing():
    rig = Rig()
    thesis_cw(rig)
    (moved,) = [e for e in rig.finish() if e["event"] == "moved"]
    assert "split" not in moved
