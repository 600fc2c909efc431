"""Rules of the rotation model (docs/plant-model.md) that no test reached
before session 32's mutation audit of the plant: each one a verdict a user
of verify=plant would otherwise be misled by (the substrate alone freeing
the far vertex, joint leads and holds at their bounds, every swept cell,
polarity, turned substrates, splits of a cluster that started in pieces)."""

import pytest
from test_plant import Rig, joints, magnets, single_event, thesis_ccw, thesis_cw

from hexbot.hil_sim.geometry import to_body, wrap
from hexbot.hil_sim.plant import Plant


def _pair(rig, mobile_joints, substrate_joints, sub_sides=("s1", "s2"), mobile_sides=("s3", "s4"),
          onset=80, end=216):
    """Mobile CW about its J4 (default): joints set at 0, magnets from onset to end."""
    rig.at(0, 2, j=joints(*mobile_joints))
    rig.at(0, 1, j=joints(*substrate_joints))
    rig.at(onset, 2, m=magnets(**{mobile_sides[0]: "-", mobile_sides[1]: "-"}))
    rig.at(onset, 1, m=magnets(**{sub_sides[0]: "-", sub_sides[1]: "+"}))
    rig.at(end, 2, j=joints(), m=magnets())
    rig.at(end, 1, j=joints(), m=magnets())


# --- far vertex: the substrate alone may release it (the listing's CCW does) ---

@pytest.mark.parametrize("direction", ["CW", "CCW"])
def test_the_substrate_alone_may_free_the_far_vertex(direction):
    # CW about the mobile's J4: far vertex = mobile J5 / substrate J1 (pivot J2).
    # CCW about the mobile's J5: far vertex = mobile J4 / substrate J2 (pivot J1).
    rig = Rig()
    if direction == "CW":
        _pair(rig, (), (1,))
    else:
        _pair(rig, (), (2,), sub_sides=("s1", "s6"), mobile_sides=("s4", "s5"))
    event = single_event(rig.finish())
    assert event["event"] == "moved", event
    assert event["direction"] == direction


def test_a_substrate_that_opens_only_its_pivot_joint_latches_the_mobile():
    rig = Rig()
    _pair(rig, (), (2,))  # substrate's J2 is at the pivot, J1 (far) stays latched
    event = single_event(rig.finish())
    assert event["reason"] == "latched joint" and "J1" in event["detail"]
    assert rig.plant.bodies[2].cell == (-1, 1)


# --- far joint lead: opened with the magnets is too late ---

def test_far_joint_opened_with_the_magnets_is_a_timing_refusal():
    rig = Rig()
    rig.at(0, 1, j=joints(2))  # substrate pivot open, far J1 latched
    rig.at(80, 2, j=joints(5), m=magnets(s3="-", s4="-"))  # mobile's far J5 opens only now
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(216, 2, j=joints(), m=magnets())
    rig.at(216, 1, j=joints(), m=magnets())
    event = single_event(rig.finish())
    assert event["reason"] == "timing" and "far joint opened less than" in event["detail"]
    assert rig.plant.bodies[2].cell == (-1, 1)


def test_far_joint_opened_exactly_the_lead_before_the_magnets_moves():
    rig = Rig()
    rig.at(40, 2, j=joints(5))  # 40 ms = Timing.joint_lead before the onset
    rig.at(80, 2, m=magnets(s3="-", s4="-"))
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(216, 2, j=joints(), m=magnets())
    rig.at(216, 1, m=magnets())
    assert single_event(rig.finish())["event"] == "moved"


# --- free path: every swept cell counts ---

@pytest.mark.parametrize("cell", [(-1, 2), (-2, 2), (0, 2)])  # sides 2, 1, ring beyond goal
def test_each_swept_cell_blocks_the_rotation(cell):
    rig = Rig(extra=[cell])
    thesis_cw(rig)
    event = single_event(rig.finish())
    assert (event["event"], event["reason"]) == ("refused", "occupied cell")
    assert event["cells"] == [list(cell)]
    assert rig.plant.bodies[2].cell == (-1, 1)


# --- polarity: the substrate must attract towards the goal ---

def test_a_substrate_attracting_away_from_the_goal_is_wrong_polarity():
    rig = Rig()
    thesis_cw(rig, substrate_sides=(1, 6))  # repels the mobile, but pulls towards side 6
    events = rig.finish()
    reasons = {e["reason"] for e in events if e["module"] == 2}
    assert reasons == {"wrong polarity"}  # the mobile's refusal and the unused substrate pulse
    assert not [e for e in events if e["event"] == "moved"]
    assert rig.plant.bodies[2].cell == (-1, 1)


# --- the most telling reason, whichever direction gave it ---

def test_a_fixed_module_ccw_is_refused_as_fixed_to_base():
    rig = Rig(mobile_fixed=True)
    thesis_ccw(rig)  # CW about the same vertex finds nobody: "no substrate" ranks lower
    assert single_event(rig.finish())["reason"] == "fixed to base"


# --- a substrate pulse that nobody used says whom it pushed ---

def test_an_unused_substrate_pulse_names_the_module_it_pushed():
    rig = Rig()
    thesis_cw(rig, mobile_joint=2)
    events = rig.finish()
    (lonely,) = [e for e in events if e.get("substrate") == 1 and "direction" not in e]
    assert (lonely["module"], lonely["reason"]) == (2, "wrong polarity")


def test_an_unused_substrate_pulse_towards_nobody_is_no_substrate():
    rig = Rig()
    rig.at(80, 1, m=magnets(s4="-", s5="+"))  # side 4 of module 1: empty cell
    rig.at(216, 1, m=magnets())
    (event,) = rig.finish()
    assert (event["module"], event["reason"]) == (None, "no substrate")


def test_an_unused_substrate_pulse_of_a_turned_module_names_its_global_neighbour():
    rig = Rig()
    rig.plant.bodies[1].orientation = 3  # body side 4 is global side 1: module 2
    rig.at(80, 1, m=magnets(s4="-", s5="+"))
    rig.at(216, 1, m=magnets())
    (event,) = rig.finish()
    assert (event["module"], event["reason"]) == (2, "wrong polarity")


# --- body joint 1 and body side pairs across 6|1 ---

def test_a_rotation_about_body_joint_1_moves():
    rig = Rig()
    rig.plant.bodies[2].orientation = 3  # body J1 is global joint 4
    thesis_cw(rig, mobile_joint=1)
    event = single_event(rig.finish())
    assert event["event"] == "moved", event
    assert (event["to"], event["orientation"], event["joint"]) == ([0, 1], 5, 1)


@pytest.mark.parametrize("orientation", [1, 2, 4, 5])
def test_a_turned_mobile_frees_the_far_vertex_with_its_own_body_joint(orientation):
    # CW about global joint 4 (substrate on global side 4, goal (0, 1)); only the
    # mobile releases the far vertex, with the body joint that lies there.
    body_joint = to_body(4, orientation)
    rig = Rig()
    rig.plant.bodies[2].orientation = orientation
    _pair(rig, (wrap(body_joint + 1),), (),
          mobile_sides=(f"s{wrap(body_joint - 1)}", f"s{body_joint}"))
    event = single_event(rig.finish())
    assert event["event"] == "moved", event
    assert (event["to"], event["orientation"]) == ([0, 1], (orientation + 2) % 6)


@pytest.mark.parametrize("orientation", [1, 2, 4])
def test_a_turned_substrate_uses_its_body_sides(orientation):
    # Global side 1 of the substrate faces the mobile, global side 2 the goal.
    rig = Rig()
    rig.plant.bodies[1].orientation = orientation
    near, far = ((1 - 1 - orientation) % 6 + 1, (2 - 1 - orientation) % 6 + 1)
    thesis_cw(rig, substrate_sides=(near, far))
    event = single_event(rig.finish())
    assert event["event"] == "moved", event
    assert (event["to"], event["orientation"]) == ([0, 1], 2)


# --- splits: only a new one ---

def test_a_scenario_that_starts_in_pieces_reports_no_split_for_an_ordinary_move():
    rig = Rig(extra=[(5, 5)])  # module 3 lies apart from the start
    thesis_cw(rig)
    (moved,) = [e for e in rig.finish() if e["event"] == "moved"]
    assert "split" not in moved


def test_a_far_joint_that_closes_again_too_soon_latches_the_mobile():
    rig = Rig()
    rig.at(0, 2, j=joints(5))  # the only free far joint ...
    rig.at(80, 2, m=magnets(s3="-", s4="-"))
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(90, 2, j=joints())  # ... closes 10 ms after the onset (30 ms needed)
    rig.at(216, 2, m=magnets())
    rig.at(216, 1, m=magnets())
    event = single_event(rig.finish())
    assert event["reason"] == "latched joint"
    assert rig.plant.bodies[2].cell == (-1, 1)


def test_a_substrate_that_lets_go_early_is_a_timing_refusal_however_long_the_mobile_holds():
    rig = Rig()
    rig.at(0, 2, j=joints(5))
    rig.at(80, 2, m=magnets(s3="-", s4="-"))
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(130, 1, m=magnets())  # 50 ms together
    rig.at(216, 2, j=joints(), m=magnets())
    event = single_event(rig.finish())
    assert event["reason"] == "timing" and "held together 50 ms" in event["detail"]
    assert rig.plant.bodies[2].cell == (-1, 1)


def test_the_split_names_the_pieces_left_behind_whatever_order_the_modules_were_added():
    # As test_plant's split test, but the module left alone (3, at (-2, 1)) is
    # added first: the split must still name it, not the mobile's own group.
    rig = Rig.__new__(Rig)
    rig.events = []
    rig.plant = Plant(1e6, emit=lambda c, e: rig.events.append({"cycle": c, **e}))
    rig.plant.add(3, (-2, 1), 0)
    rig.plant.add(1, (0, 0), 0, fixed=True)
    rig.plant.add(2, (-1, 1), 0)
    rig.state = {m: [joints(), magnets()] for m in rig.plant.bodies}
    thesis_cw(rig)
    (moved,) = [e for e in rig.finish() if e["event"] == "moved"]
    assert moved["split"] == [3]


def test_a_mobile_pattern_with_a_stray_positive_side_moves_nothing():
    rig = Rig()
    rig.at(0, 2, j=joints(5))
    rig.at(80, 2, m=magnets(s3="-", s4="-", s6="+"))  # not "all others off"
    rig.at(80, 1, m=magnets(s1="-", s2="+"))
    rig.at(216, 2, j=joints(), m=magnets())
    rig.at(216, 1, m=magnets())
    events = rig.finish()
    assert not [e for e in events if e["event"] == "moved"], events
    assert rig.plant.bodies[2].cell == (-1, 1)
