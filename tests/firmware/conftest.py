"""Firmware tests: the real images in the simulator, driven over the PC's
IR link. The images are built once per session by firmware/Makefile."""

from __future__ import annotations

import pytest
from fwsim import BUILD, Bench, build_firmware, close_all


@pytest.fixture(scope="session")
def images():
    return build_firmware(BUILD)


@pytest.fixture
def single(images) -> Bench:
    """One module (id 1) booted and listening."""
    bench = Bench.boot("single")
    bench.drain()
    bench.debug_read(1)
    return bench


@pytest.fixture(autouse=True)
def _close_benches():
    yield
    close_all()
