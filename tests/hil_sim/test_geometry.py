"""Orientation of a module's body on the lattice, as the plant uses it."""

from hexbot.hil_sim.geometry import to_body, to_global


def test_orientation_maps_body_sides_onto_global_sides():
    # o = 2: body side 1 looks along global side 3; Yref = (S - j) mod 6.
    assert to_global(1, 2) == 3
    assert to_global(5, 2) == 1
    for o in range(6):
        for b in range(1, 7):
            assert to_body(to_global(b, o), o) == b
            assert (to_global(b, o) - b) % 6 == o
