"""The thesis' planner (Chapter 4, Appendix C), layer by layer, kept faithful.

Each module mirrors one MATLAB function; where the listing is damaged or
buggy the docstring says what was done (see also docs/planning.md).
"""
