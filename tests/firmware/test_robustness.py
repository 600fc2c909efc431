"""Bad input on the IR link: truncated and malformed frames, noise, and a
thousand random byte strings. None of it may stop the module from
acknowledging the next valid command."""

from __future__ import annotations

import random

import pytest
from fwsim import Bench, pc_frame, single_ack

from hexbot.protocol import codes, frames, parser
from hexbot.protocol.codes import ErrorCode

LON = frames.encode_pc(frames.make("LOn"))


@pytest.mark.parametrize(
    "junk",
    [
        pytest.param(b"*\x01\x02", id="truncated"),
        pytest.param(b"*" + bytes(9) + b"X", id="end-byte-not-hash"),
        pytest.param(b"*\x01\x01NNNNNNN", id="hash-missing"),
        pytest.param(b"#####", id="hashes"),
        pytest.param(b"**********", id="stars"),
        pytest.param(b"*\x2a\x2a\x2a", id="stars-as-arguments"),
        pytest.param(b"\x00\xff\x0a\x0d" * 4, id="binary"),
    ],
)
def test_malformed_frame_then_valid_frame_back_to_back(single: Bench, junk: bytes):
    replies = single.frame(junk + LON)
    assert [r.code for r in replies if isinstance(r, parser.Ack)][-1:] == [44]


def test_truncated_frame_is_dropped_after_the_inter_byte_timeout(single: Bench):
    single.send(b"*\x01\x03NN")
    single.run(0.6)  # > 10 byte times of silence: the half frame is abandoned
    assert single.replies() == []
    single_ack(single.frame(LON), 44)
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.BAD_FRAME


def test_argument_bytes_may_be_star_and_hash(single: Bench):
    # JTest(42, 35): '*' and '#' as arguments; the frame is taken by length.
    ack = single_ack(single.frame(pc_frame(5, 1, 35)), 5)
    assert ack.code == 5
    single_ack(single.frame(pc_frame(36, 42, 0)), 36)


def test_a_new_command_stops_a_long_led_sequence(single: Bench):
    single.send(pc_frame(46, 255, 255))  # LCircle: hours at the thesis' pace
    single.run(3.0)
    replies = single.frame(LON)
    assert [r.code for r in replies] == [46, 44]


def test_a_new_command_stops_a_long_actuator_sequence(single: Bench):
    single.send(pc_frame(5, 255, 255))  # JTest(255, 255) on the control board
    single.run(3.0)
    single.drain()
    replies = single.frame(frames.encode_pc(frames.make("TurnOffAll")))
    # JTest stops on both boards: it is reported stopped, TurnOffAll done.
    assert [type(r).__name__ for r in replies] == ["ErrorReply", "Ack"]
    assert [r.code for r in replies] == [5, 20] and replies[0].reason == ErrorCode.STOPPED
    ports = {p: single.sim.modules[1].control.port(p)[1] for p in "ABD"}
    assert ports["A"] & 0x3F == 0
    # the comm board's own TurnOffAll carries the 'N' filler: the control
    # board runs it (ACK 20 on its debug port), it does not refuse it (ACK N)
    debug = single.debug_read(1)
    assert b"ACK\x14" in debug and b"ACKN" not in debug, debug


def random_strings(seed: int, count: int) -> list[bytes]:
    rng = random.Random(seed)
    return [bytes(rng.randrange(256) for _ in range(rng.randint(1, 12))) for _ in range(count)]


VALID = [
    (frames.encode_pc(frames.make("LOn")), 44),
    (frames.encode_pc(frames.make("JxClose", 3)), 2),
    # Not SideOffAllN: its code is '#' (35), and a random '*' eight bytes
    # earlier makes "*........*#" a complete (unused-code) frame; the fixed
    # frame length cannot tell them apart.
    (frames.encode_pc(frames.make("SideOffAllP")), 31),
    (frames.encode_pc(frames.make("ClearError")), 72),
]


def test_a_thousand_random_strings_never_stop_the_next_valid_command(single: Bench):
    strings = random_strings(seed=2026, count=1000)
    # The seed was chosen without help: none of the strings holds a complete
    # frame that would send the module away (IrSel to a side, Select).
    for s in strings:
        for at in range(len(s) - 10):
            if s[at] == 42 and s[at + 10] == 35:
                assert s[at + 1] not in (25, 69)
    for n, junk in enumerate(strings):
        frame, code = VALID[n % len(VALID)]
        mark = single.send(junk + frame)
        acked = single.session.wait_for(
            lambda o, c=code: isinstance(o.event, parser.Ack) and o.event.code == c, mark, 8.0)
        assert acked is not None, (n, junk, code)
    assert single.sim.modules[1].comm.state in ("running", "sleeping")
    single.sim.run(1.0)
    assert single.sim.modules[1].control.state in ("running", "sleeping")


def test_noisy_ir_link_loses_frames_but_never_the_module(images, tmp_path):
    from fwsim import scenario_file

    # 0.3 % of the bits flip on every IR link: about one frame in four of
    # the 11-byte PC frames or 13-byte replies is hit.
    bench = Bench.boot(scenario_file(tmp_path, [(1, (0, 0), 0)], bit_error_rate=0.003))
    answered = 0
    for n in range(60):
        frame, code = VALID[n % len(VALID)]
        mark = bench.send(frame)
        bench.run(1.2)
        answered += any(isinstance(o.event, parser.Ack) and o.event.code == code
                        for o in bench.session.host.since(mark))
    assert 30 <= answered < 60, answered  # noise did bite, yet most got through
    for _attempt in range(5):  # what a host does: retry until acknowledged
        if bench.session.exchange(frames.make("LOn"), timeout=1.2).ok:
            break
    else:
        raise AssertionError("no acknowledgement in five attempts")


SIDE_OFF_ALL_N = frames.encode_pc(frames.make("SideOffAllN"))  # code '#' (35)


@pytest.mark.parametrize("junk", [b"N" * 8, b"\x00ABCDEFG", b"\x011\x00\x00\x00\x00\x00\x00"],
                         ids=["unused-code-N", "unknown-code", "argument-out-of-range"])
def test_stray_star_before_a_hash_coded_frame_does_not_swallow_it(single: Bench, junk: bytes):
    # '*' + 8 bytes + "*#" looks like a complete frame; it is one this module
    # would refuse, so the "*#" is taken as the start of the real frame.
    replies = single.frame(b"*" + junk + SIDE_OFF_ALL_N)
    assert [(type(r).__name__, r.code) for r in replies] == [("Ack", 35)]
    (sta,) = single.command("Status")
    assert sta.error == ErrorCode.BAD_FRAME


def test_a_valid_frame_ending_in_star_is_still_executed(single: Bench):
    # Select(1, 2, ..., 7, 42): id 42 is valid, B8 = '*'; the frame is real.
    frame = pc_frame(69, 1, 2, 3, 4, 5, 6, 7, 42)
    assert frame[-2:] == b"*#"
    (ack,) = single.frame(frame)
    assert (ack.code, ack.module) == (69, 1)


def test_a_stray_star_before_a_frame_with_its_filler_is_told_apart(single: Bench):
    # "*" + LOn's code and 7 bytes + "*#" has LOn's length, but its last
    # unused byte is '*', not the 'N' filler: not a frame, so the '#'-coded
    # frame after it runs and LOn does not.
    replies = single.frame(b"*,NNNNNNN" + SIDE_OFF_ALL_N)
    assert [r.code for r in replies] == [35]


@pytest.mark.parametrize("frame, code", [
    pytest.param(b"*\x01\x03XXXXXXX#", 1, id="JxOpen-control-board"),
    pytest.param(b"*,NNNN\x00NNN#", 44, id="LOn-comm-board"),
])
def test_a_frame_whose_unused_bytes_are_not_the_filler_is_refused(single: Bench, frame, code):
    # A byte the function does not use is 'N' in every frame a host sends: any
    # other value is corruption, and the command must not run (the host's
    # decoder refuses the same frame).
    with pytest.raises(frames.FrameError, match="must be 'N'"):
        frames.decode_pc(frame)
    replies = single.frame(frame)
    assert [(type(r).__name__, r.code, r.reason) for r in replies] == [
        ("ErrorReply", code, ErrorCode.ARG_RANGE)]
    single_ack(single.frame(LON), 44)  # and the next good frame runs


@pytest.mark.parametrize("name,slot", [
    (name, slot) for name in ("JxOpen", "LOn", "JTest", "Status")
    for slot in range(len(codes.lookup(name).args), 8)])
def test_any_one_filler_byte_that_is_not_n_refuses_the_frame(single: Bench, name, slot):
    # host and module agree on every filler, the first one after the
    # arguments too: the frame is refused, the next one is executed
    fn = codes.lookup(name)
    arity = len(fn.args)
    args = [a.lo for a in fn.args] + [ord("N")] * (8 - arity)
    args[slot] = 0
    frame = pc_frame(fn.code, *args)
    with pytest.raises(frames.FrameError, match="must be 'N'"):
        frames.decode_pc(frame)
    replies = single.frame(frame)
    assert [(type(r).__name__, r.code, r.reason) for r in replies] == [
        ("ErrorReply", fn.code, ErrorCode.ARG_RANGE)], replies
    single_ack(single.frame(LON), 44)
