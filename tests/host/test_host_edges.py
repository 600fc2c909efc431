"""Session 36's mutation audit of host/host.py, each test failing on its
mutant: the restart warnings a user gets from status replies."""

from __future__ import annotations

from hexbot.host.host import IR, Host
from hexbot.protocol.codes import ErrorCode
from hexbot.protocol.header import SCHEMA_HASH
from hexbot.protocol.parser import StatusReport


def status(error: int) -> StatusReport:
    return StatusReport(raw=b"", module_id=3, role="M", error=error, schema=SCHEMA_HASH)


def test_a_restart_is_told_once_per_restart_not_per_status():
    host = Host()
    host.observe(0.0, IR, status(ErrorCode.WATCHDOG_RESET))
    host.observe(1.0, IR, status(ErrorCode.WATCHDOG_RESET))  # the same restart, asked again
    assert host.warnings == ["module 3: its comm board restarted (watchdog): role, place "
                             "and selection are lost"]
    host.observe(2.0, IR, status(ErrorCode.NONE))  # cleared by a command since
    host.observe(3.0, IR, status(ErrorCode.WATCHDOG_RESET))  # a second restart
    assert len(host.warnings) == 2


def test_a_debug_port_gets_board_frames_whatever_the_ir_framing():
    # a control board's UART1 speaks board frames only; MAVLink is the IR link's
    from hexbot.host.host import DEBUG
    from hexbot.protocol import frames
    from hexbot.protocol.mavlink_codec import Framing

    host = Host()
    host.set_framing(Framing.MAVLINK)
    command = frames.make("Status")
    assert host.encode(command, DEBUG) == frames.encode_pc(command)
    assert host.encode(command, IR) != frames.encode_pc(command)


def test_a_rotation_that_splits_the_cluster_is_a_warning_however_it_was_sent(
        open_session, tmp_path):
    # the pair plus module 3 at (-2, 1), touching only the mobile module 2:
    # a rotation sent by hand (the composer, a script's post) gets no
    # workflow's check, the user is told by the host
    from hexbot.host import workflows
    from hexbot.host.session import select
    from hexbot.protocol.rotation import combined_rotation, direction_of

    scenario = tmp_path / "tail.toml"
    scenario.write_text('name = "tail"\nseed = 1\nbase = 1\n' + "".join(
        f"[[module]]\nid = {i}\nposition = [{x}, {y}]\norientation = 0\n"
        for i, (x, y) in ((1, (0, 0)), (2, (-1, 1)), (3, (-2, 1)))))
    session = open_session(scenario)
    workflows.localize(session, 1)
    workflows.set_role(session, 2, workflows.Role.MOBILE)
    workflows.set_role(session, 1, workflows.Role.SUBSTRATE)
    session.request(select(1, 2))
    session.request(combined_rotation(direction_of("CW"), 4, 0, 0))
    session.sleep(3.0)  # the plant's verdict
    split = [w for w in session.host.warnings if w.startswith("the cluster split")]
    assert len(split) == 1, session.host.warnings  # once, not once per subscription


def test_a_port_configured_again_closes_the_old_one(responder):
    # the console's port dialog, pointed at another device: the old port
    # is let go (it is opened exclusively; another program may want it)
    from hexbot.host.link import LinkState, PortSettings

    host = Host()
    old = host.add_port(IR, PortSettings(responder.path))
    host.start(5.0)
    host.add_port(IR, PortSettings("loop://"))
    try:
        assert old.link.state is LinkState.CLOSED
    finally:
        host.close()
