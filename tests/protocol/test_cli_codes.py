"""`hexbot codes NAME`: one function in full, from the protocol table."""

from hexbot.cli import main
from hexbot.protocol import timing
from hexbot.protocol.codes import lookup


def test_a_function_in_full_shows_each_arguments_range_and_meaning(capsys):
    assert main(["codes", "JxOpen"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "1 JxOpen(i)"
    assert "    i    1..6  joint number" in out
    assert any(line.startswith("  reply      ACK 1 from each addressed module") for line in out)


def test_delays_say_their_unit_and_the_reply_bound_is_the_protocols(capsys):
    assert main(["codes", "cw"]) == 0  # names are case-insensitive
    text = capsys.readouterr().out
    for arg in lookup("CW").args:
        unit = " x 10 ms" if arg.unit == "tick" else ""
        assert f"{arg.name:<4} {arg.lo}..{arg.hi}{unit}" in text and arg.meaning in text
    assert "st1  0..255 x 10 ms  substrate: delay before the magnets start" in text
    assert f"within {timing.reply_timeout_s(67, 1):.1f} s at most" in text


def test_several_names_and_codes_and_unused_codes(capsys):
    assert main(["codes", "70", "Localize", "9"]) == 0
    blocks = capsys.readouterr().out.split("\n\n")
    assert [b.splitlines()[0] for b in blocks] == ["70 Status()", "66 Localize()",
                                                    f"9 {lookup(9).signature()}"]
    assert "  reply      STA from each addressed module" in blocks[0]
    assert "arguments  none" in blocks[1]


def test_an_unknown_name_fails_with_close_names_and_prints_nothing(capsys):
    assert main(["codes", "CW", "Jxopn"]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""
    assert "no function 'Jxopn' (did you mean JxOpen" in captured.err
