"""Skip marks of the flash tests. A module of its own: with several test
folders in one run, ``from conftest import ...`` resolves to whichever
folder's conftest.py was loaded last (``pytest tests/flash tests/planning``
failed to import six files)."""

import shutil

import pytest

needs_avrdude = pytest.mark.skipif(shutil.which("avrdude") is None, reason="avrdude missing")
needs_avr_gcc = pytest.mark.skipif(shutil.which("avr-gcc") is None, reason="avr-gcc missing")
