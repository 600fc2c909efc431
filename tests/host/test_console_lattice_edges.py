"""The lattice and the Boards tab at their edges (session 35's audit): the
plant's modules are drawn dim before any reply placed them, and the side
LEDs' polarity reads as the firmware drives it."""

from __future__ import annotations

from hexbot.host.cluster import ClusterModel
from hexbot.host.console.boards_view import side_leds
from hexbot.host.console.lattice import draw_lattice, lattice_legend
from hexbot.protocol.simulation import Placement


def test_before_localizing_the_plants_modules_are_drawn_dim():
    truth = {1: Placement((0, 0), 0), 2: Placement((-1, 1), 0)}
    drawing = draw_lattice(ClusterModel(), truth)
    assert "no positions yet" not in drawing.plain
    assert "/01\\" in drawing.plain and "/02\\" in drawing.plain
    at = drawing.plain.index("/01\\")
    assert {str(span.style) for span in drawing.spans if span.start <= at < span.end} == {"dim"}
    assert "dim: where the simulator has a module" in lattice_legend(ClusterModel(), truth)


def test_without_replies_or_a_plant_the_lattice_says_how_to_fill_it():
    assert draw_lattice(ClusterModel()).plain == "no positions yet: localize the cluster (key l)"


def test_side_leds_show_positive_negative_and_both():
    assert side_leds([1, 0, 1, 0, 0, 0], [0, 1, 1, 0, 0, 0]) == "+-±···"
