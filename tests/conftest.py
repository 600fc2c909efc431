"""Suite-wide settings.

Under CI (``CI`` set) hypothesis runs derandomized: the same examples every
run, so a red build is reproducible and never depends on luck. Locally it
explores new examples each run.
"""

import importlib
import os
from pathlib import Path

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")

#: The subpackages the editable install maps from the repository's folders
#: (setup.py's ROOTS).
MAPPED = ("hexbot", "hexbot.protocol", "hexbot.host", "hexbot.hil_sim",
          "hexbot.planning", "hexbot.bench", "hexbot.sweep")


def pytest_configure(config):
    """Refuse to test another tree's code. The editable install maps each
    subpackage to a folder of the checkout it was installed from; a second
    checkout (a git worktree, a clone) run with the same virtualenv would
    import the first one's code and its C extensions, and pass or fail for
    it, silently."""
    root = Path(config.rootpath).resolve()
    for name in MAPPED:
        where = Path(importlib.import_module(name).__file__).resolve().parent
        if not where.is_relative_to(root):
            raise pytest.UsageError(
                f"{name} is imported from {where}, not from the checkout under test "
                f"({root}): this virtualenv's editable install belongs to another tree; "
                f"run `pip install -e .` here, or use this checkout's own virtualenv")


@pytest.fixture
def open_session():
    """``open_session(scenario, seed=1, speed=0, boot=True)``: a Session on the
    embedded simulator's pyserial URL (stepped: virtual time), closed after
    the test. ``scenario`` is a built-in name or a TOML path, or a pty
    (``/dev/pts/N``) to open as hardware."""
    from hexbot.host.endpoints import sim_url
    from hexbot.host.host import IR, Host
    from hexbot.host.link import PortSettings
    from hexbot.host.session import Session

    hosts = []

    def factory(scenario, seed=1, speed=0.0, boot=True):
        host = Host()
        hosts.append(host)
        url = str(scenario) if str(scenario).startswith("/dev/") else sim_url(
            str(scenario), seed, speed)
        host.add_port(IR, PortSettings(url))
        host.start(5.0)
        session = Session(host)
        if boot:
            session.wait_booted(host.simulator.module_ids())
        return session

    yield factory
    for host in hosts:
        host.close()


@pytest.fixture
def cli_status(capsys):
    """``cli_status(*argv)``: hexbot's exit status and stderr for ``argv``,
    argparse's usage errors (SystemExit) included."""
    from hexbot.cli import main

    def run(*argv) -> tuple[int, str]:
        try:
            code = main([str(a) for a in argv])
        except SystemExit as exc:
            code = exc.code
        return code, capsys.readouterr().err
    return run


#: The firmware images `make -C firmware` builds (`make test` builds them first).
FIRMWARE_BUILD = Path(__file__).resolve().parents[1] / "firmware" / "build"


@pytest.fixture
def built_images() -> Path:
    """firmware/build, with the images in it (the test skips without them)."""
    if not (FIRMWARE_BUILD / "comm.hex").exists():
        pytest.skip("firmware not built (make -C firmware)")
    return FIRMWARE_BUILD


@pytest.fixture
def old_schema_images(built_images, tmp_path) -> Path:
    """comm.elf and control.elf as if built from another protocol: their
    image marks' schema digits are 0badf00d (the comm board's Status reads
    them from there too), everything else as built."""
    from hexbot.protocol.header import SCHEMA_HASH

    ours = f"schema={SCHEMA_HASH:08x}".encode()
    out = tmp_path / "old-schema"
    out.mkdir()
    for name in ("comm.elf", "control.elf"):
        data = (built_images / name).read_bytes()
        assert data.count(ours) == 1
        (out / name).write_bytes(data.replace(ours, b"schema=0badf00d"))
    return out
