"""Suite-wide settings.

Under CI (``CI`` set) hypothesis runs derandomized: the same examples every
run, so a red build is reproducible and never depends on luck. Locally it
explores new examples each run.
"""

import os

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


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
