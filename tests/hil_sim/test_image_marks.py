"""The simulator reads every image's mark (protocol/image_mark.py) before it
runs it: another board's firmware, or firmware built from another protocol,
runs with a warning that reaches the user (`hexbot sim`, and every session
on the embedded simulator)."""

from __future__ import annotations

from pathlib import Path

from hexbot.cli import main
from hexbot.hil_sim import Simulator, load_scenario
from hexbot.protocol.header import SCHEMA_HASH

SCHEMA = f"{SCHEMA_HASH:08x}"



def _scenario(tmp: Path, comm: Path, control: Path) -> Path:
    path = tmp / "two.toml"
    path.write_text("\n".join([
        'name = "two"', "seed = 1", "base = 1",
        "[firmware]", f'comm = "{comm}"', f'control = "{control}"',
        "[[module]]", "id = 1", "position = [0, 0]",
        "[[module]]", "id = 2", "position = [1, 0]", ""]))
    return path


def test_a_boards_image_in_the_other_boards_place_is_said(built_images, tmp_path):
    """Not refused: tests put a program that does nothing, or the RF12
    board's firmware, in a control board's place on purpose; but said."""
    path = _scenario(tmp_path, built_images / "comm.elf", built_images / "comm.elf")
    sim = Simulator(load_scenario(path))
    assert sim.image_notes == [
        f"{built_images / 'comm.elf'}: it is the comm board's firmware, not the control board's"]
    assert Simulator(load_scenario(_scenario(tmp_path, built_images / "comm.elf",
                                             built_images / "control.elf"))).image_notes == []


def test_hexbot_sim_warns_of_firmware_from_another_protocol(old_schema_images, tmp_path, capsys):
    path = _scenario(tmp_path, old_schema_images / "comm.elf", old_schema_images / "control.elf")
    assert main(["sim", str(path), "--duration", "0.01", "--speed", "0"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert [line for line in err if line.startswith("warning:")] == [
        f"warning: {old_schema_images / name}: it was built from protocol schema 0badf00d, this "
        f"host speaks {SCHEMA}: rebuild it (make -C firmware)"
        for name in ("comm.elf", "control.elf")]


def test_a_session_on_old_firmware_is_warned_before_any_status(old_schema_images, capsys, tmp_path,
                                                               monkeypatch):
    """The images' warning comes as the port opens; the comm board's Status,
    built from the same mark, then says the same of the running module."""
    monkeypatch.setenv("HEXBOT_LOG_DIR", str(tmp_path / "logs"))
    url = f"hexbot-sim://pair?speed=0&firmware={old_schema_images}"
    assert main(["send", "Status", "--module", "2", "--port", url]) == 0
    err = capsys.readouterr().err.splitlines()
    warnings = [line for line in err if line.startswith("warning:")]
    assert warnings[:2] == [
        f"warning: {old_schema_images / name}: it was built from protocol schema 0badf00d, this "
        f"host speaks {SCHEMA}: rebuild it (make -C firmware)"
        for name in ("comm.elf", "control.elf")]
    assert any("module 2: module firmware speaks protocol schema 0badf00d" in w
               for w in warnings[2:])
