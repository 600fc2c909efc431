"""Scenario files: the built-ins load, bad files fail with file, line and problem."""

from pathlib import Path

import pytest

from hexbot.errors import ScenarioError
from hexbot.hil_sim import load_scenario
from hexbot.hil_sim.scenario import builtin_names

GOOD = """\
name = "two"
seed = 7
base = 1

[faults]
byte_loss = 0.1

[[faults.link]]
from = "pc"
to = 2
bit_error_rate = 0.5

[[module]]
id = 1
position = [0, 0]

[[module]]
id = 2
position = [1, 0]
orientation = 3
firmware = { comm = "img/comm.elf" }
"""


def write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "s.toml"
    path.write_text(text)
    return path


def test_builtins_exist_and_load():
    assert {"single", "pair", "thesis-fig5-8", "flower7"} <= set(builtin_names())
    flower = load_scenario("flower7")
    assert len(flower.modules) == 7 and flower.base == 1
    cells = {m.position for m in flower.modules}
    assert cells == {(0, 0), (-1, 1), (0, 1), (1, 0), (1, -1), (0, -1), (-1, 0)}
    fig = load_scenario("thesis-fig5-8")
    assert {m.position for m in fig.modules} == {(0, 0), (1, 0), (2, 0), (3, 0), (4, 0), (0, 1)}


def test_full_file(tmp_path):
    s = load_scenario(write(tmp_path, GOOD))
    assert s.seed == 7 and s.base == 1
    assert s.modules[1].orientation == 3
    assert s.modules[1].firmware.comm == (tmp_path / "img/comm.elf").resolve()
    assert s.faults_for(1, 2).byte_loss == 0.1
    assert s.faults_for("pc", 2).bit_error_rate == 0.5


@pytest.mark.parametrize(
    "old,new,line,problem",
    [
        ("id = 2\n", "id = 1\n", 18, "module id 1 used twice"),
        ("orientation = 3", "orientation = 6", 20, "orientation must be an integer 0..5"),
        ("position = [1, 0]", "position = [0, 0]", 19, "already holds module 1"),
        ("position = [1, 0]", "position = [1]", 19, "position must be [x, y]"),
        ("to = 2", "to = 9", 10, "neither \"pc\" nor the id of a module"),
        ("byte_loss = 0.1", "byte_loss = 2", 6, "probability"),
        ("base = 1", "base = 5", 3, "base = 5 is not the id"),
        ("orientation = 3", "orientation = 3\ncolour = 1", 21, "unknown key 'colour'"),
        ("id = 2\n", "id = 256\n", 18, "outside 1..255"),
        ("id = 2\n", "id = 2\nclock_ppm = 60000\n", 19, "beyond +-50000 ppm"),
        ("seed = ", "clock_spread_ppm = -5\nseed = ", 2, "must not be negative"),
        ("seed = ", "pc_radio = [1]\nseed = ", 2, "pc_radio must be a cell [x, y]"),
        # session 33's audit: values at the edges, each refused, not run
        ("id = 2\n", "id = 0\n", 18, "module id 0 outside 1..255"),  # 0 addresses all
        ("id = 2\n", "id = 2\nclock_ppm = -60000\n", 19, "beyond +-50000 ppm"),
        ("byte_loss = 0.1", "byte_loss = -0.1", 6, "must be a probability 0..1"),
        ("bit_error_rate = 0.5", "bit_error_rate = -1", 11, "must be a probability 0..1"),
        # a misspelt fault would silently inject nothing
        ("byte_loss = 0.1", "byte_los = 0.1", 6, "unknown key 'byte_los' in [faults]"),
        ("bit_error_rate = 0.5", "bit_eror_rate = 0.5", 11,
         "unknown key 'bit_eror_rate' in [faults.link]"),
        ("seed = ", "radio_range = -1\nseed = ", 2, "radio_range must be a whole number"),
        ("seed = ", "threads = 0\nseed = ", 2, "threads must be a whole number 1..256"),
    ],
)
def test_semantic_errors_name_file_line_problem(tmp_path, old, new, line, problem):
    path = write(tmp_path, GOOD.replace(old, new, 1))
    with pytest.raises(ScenarioError) as err:
        load_scenario(path)
    assert f"{path}:{line}:" in str(err.value)
    assert problem in str(err.value)


def test_a_position_on_the_coordinate_limit_is_accepted(tmp_path):
    # MSG1 carries two decimal digits per coordinate: +-99 still fits
    scenario = load_scenario(write(tmp_path, GOOD.replace("[1, 0]", "[99, -99]")))
    assert scenario.modules[1].position == (99, -99)


def test_toml_syntax_error_names_the_line(tmp_path):
    path = write(tmp_path, GOOD.replace("seed = 7", "seed = = 7"))
    with pytest.raises(ScenarioError, match=r"s\.toml:2: "):
        load_scenario(path)


def test_unknown_builtin_lists_the_choices():
    with pytest.raises(ScenarioError, match="flower7"):
        load_scenario("no-such-scenario")


def test_bad_values_name_the_line_instead_of_a_traceback(tmp_path):
    from hexbot.errors import ScenarioError

    cases = {
        "module = [1, 2]\n": "array of tables",
        "[[module]]\nid = 1\nposition = [0, 0]\norientation = true\n": "orientation",
        "clock_ppm = nan\n[[module]]\nid = 1\nposition = [0, 0]\n": "ppm",
    }
    for n, (text, word) in enumerate(cases.items()):
        path = tmp_path / f"bad{n}.toml"
        path.write_text('name = "bad"\n' + text)
        with pytest.raises(ScenarioError, match=word) as info:
            load_scenario(path)
        assert str(info.value).startswith(f"{path}:"), info.value


def test_an_image_built_for_another_avr_is_refused_with_its_line(tmp_path):
    import subprocess

    from hexbot.errors import ScenarioError
    from hexbot.hil_sim import Simulator

    src = tmp_path / "m328.c"
    src.write_text("#include <avr/io.h>\nint main(void){DDRB=0xFF;for(;;)PORTB++;}\n")
    elf = tmp_path / "control328.elf"
    subprocess.run(["avr-gcc", "-mmcu=atmega328p", "-Os", "-o", str(elf), str(src)], check=True)
    path = tmp_path / "wrong.toml"
    path.write_text('name = "wrong"\n[[module]]\nid = 1\nposition = [0, 0]\n'
                    f'firmware = {{ control = "{elf}" }}\n')
    with pytest.raises(ScenarioError, match="built for the atmega328p, not the ATmega162"):
        Simulator(load_scenario(path), seed=1)


def test_a_wild_write_above_ramend_crashes_the_mcu_not_the_simulator(tmp_path):
    import subprocess

    from hexbot.hil_sim._avr import Cluster

    src = tmp_path / "wild.c"
    # 0xFF00: 63 KB past simavr's 1.25 KB of data memory, in the host's heap
    src.write_text("int main(void){*(volatile unsigned char*)0xFF00=0xAA;for(;;);}\n")
    elf = tmp_path / "wild.elf"
    subprocess.run(["avr-gcc", "-mmcu=atmega162", "-Os", "-o", str(elf), str(src)], check=True)
    cluster = Cluster()
    mcu = cluster.add_mcu(str(elf), "wild")
    cluster.run(2_000_000)
    assert cluster.state(mcu) == "crashed" and "out of ram" in cluster.last_error(mcu)


def test_a_name_without_toml_or_a_folder_is_never_a_file_of_the_current_one(
        tmp_path, monkeypatch):
    """(fuzz, session 37) `pair` was read from a file `pair` in the current
    folder first; `./pair` names it."""
    (tmp_path / "pair").write_text("not a scenario\n")
    (tmp_path / "nosuch").write_text("not a scenario either\n")
    monkeypatch.chdir(tmp_path)
    assert sorted(m.id for m in load_scenario("pair").modules) == [1, 2]
    with pytest.raises(ScenarioError, match=r"^unknown scenario 'nosuch': built-in ones are .* "
                                            r"\(a file: a name ending in \.toml, or \./NAME\)$"):
        load_scenario("nosuch")
    with pytest.raises(ScenarioError, match=r"^pair:1: "):
        load_scenario("./pair")
