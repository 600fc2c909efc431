"""Shared fixtures: the thesis' example configurations shipped as data files."""

from pathlib import Path

import pytest

from hexbot.planning.config_io import load_configuration

EXAMPLES = Path(__file__).resolve().parents[2] / "planning" / "examples"


@pytest.fixture
def example():
    """Load an example configuration by file name."""
    return lambda name: load_configuration(EXAMPLES / name)


@pytest.fixture
def examples_dir():
    return EXAMPLES


@pytest.fixture
def p01(example):
    """Test_All_P01 / S01: (initial configuration, goal cells)."""
    return example("test_all_p01_initial.txt"), example("test_all_p01_goal.txt").cells


@pytest.fixture
def p02_swapped(example):
    """Test_All_P02: P01 with initial and goal swapped."""
    return example("test_all_p01_goal.txt"), example("test_all_p01_initial.txt").cells


@pytest.fixture
def s02(example):
    return example("test_all_s02_initial.txt"), example("test_all_s02_goal.txt").cells
