"""`hexbot flash` reads the image's mark (protocol/image_mark.py) before it
touches the device: another board's firmware, or firmware built from another
protocol than this host's, is refused unless --force."""

from __future__ import annotations

from pathlib import Path

from intelhex import IntelHex

from hexbot.protocol.header import SCHEMA_HASH
from hexbot.protocol.wire import FW_VERSION

SCHEMA = f"{SCHEMA_HASH:08x}"



def _other_schema(source: Path, out: Path) -> Path:
    """``source`` as if built from another protocol: its mark's schema digits
    changed, everything else as built."""
    image = IntelHex(str(source))
    flash = image.tobinstr()
    at = flash.index(f"schema={SCHEMA}".encode()) + len("schema=")
    for i, byte in enumerate(b"0badf00d"):
        image[at + i] = byte
    image.write_hex_file(str(out))
    return out


def test_another_boards_image_is_refused_before_the_device_is_read(hexbot_flash,
                                                                   built_images):
    result = hexbot_flash("--board", "control", "--image", str(built_images / "comm.hex"),
                          "--port", "/dev/pts/0")
    assert result.code == 1
    lines = result.out.splitlines()  # the image's line, and no step on the device
    assert len(lines) == 1 and lines[0].startswith(
        f"image {built_images / 'comm.hex'}: comm board firmware {FW_VERSION}, protocol schema "
        f"{SCHEMA}, ")
    assert result.err.strip() == (
        f"hexbot flash: error: {built_images / 'comm.hex'}: it is the comm board's firmware, not "
        "the control board's; refusing to flash it, nothing was written (--force flashes "
        "it anyway)")


def test_an_image_of_another_protocol_is_refused_and_force_flashes_it(hexbot_flash,
                                                                      built_images,
                                                                      tmp_path):
    old = _other_schema(built_images / "control.hex", tmp_path / "old-control.hex")
    refused = hexbot_flash("--board", "control", "--image", str(old), "--port", "/dev/pts/0")
    assert refused.code == 1
    assert (f"it was built from protocol schema 0badf00d, this host speaks {SCHEMA}: "
            "rebuild it (make -C firmware); refusing to flash it") in refused.err
    forced = hexbot_flash("--board", "control", "--image", str(old), "--port", "/dev/pts/0",
                          "--force", "--dry-run")
    assert forced.code == 0
    assert ("warning: old-control.hex: it was built from protocol schema 0badf00d, this host "
            f"speaks {SCHEMA}: rebuild it (make -C firmware) (--force: flashing it anyway)"
            in forced.out)
    assert "avrdude" in forced.out.splitlines()[-1] and str(old) in forced.out.splitlines()[-1]


def test_an_image_given_alone_names_its_board(hexbot_flash, built_images):
    result = hexbot_flash("--image", str(built_images / "control.hex"), "--port", "/dev/pts/0",
                          "--dry-run")
    assert result.code == 0
    assert result.out.startswith(f"image {built_images / 'control.hex'}: control board firmware "
                                 f"{FW_VERSION}, protocol schema {SCHEMA}, ")
