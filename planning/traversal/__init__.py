"""Collision-free traversal of a hexagonal surface with bridges (Ivanov & Walter,
"Layering algorithm for collision-free traversal using hexagonal
self-reconfigurable metamorphic robots").

n modules start in a chain at the source end of a contiguous surface of
unmoving modules and roll across it, in synchronous rounds and without
messages, to the goal cells at the other end. A preprocessing phase run on
the map (:mod:`.bridges`, FINDBRIDGECELLS) finds the narrow pockets where
moving modules would touch, and the cells where the first modules to get
there stop to bridge them; the round engine (:mod:`.engine`) runs the same
per-module rule (MOVEMODULE) for every module and checks the invariants
each round.

Modules: :mod:`.surface` (text maps), :mod:`.motion` (what a rotation needs
under the paper's deformable model or HexBot's Table 4-3),
:mod:`.layers` (perimeter tracing and numbering), :mod:`.bridges`,
:mod:`.engine`, :mod:`.bank` (the map bank and random surfaces),
:mod:`.experiments` (the paper's figures), :mod:`.render`,
:mod:`.cli`.
See docs/traversal.md.
"""
