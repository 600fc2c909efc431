"""Benchmarks, one module each, run by ``hexbot bench NAME`` (see bench/cli.py).

Results and the commands that made them: docs/performance.md.
"""
