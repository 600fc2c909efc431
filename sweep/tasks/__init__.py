"""The built-in task kinds, one module each: ``PARAMS``, ``run(**params) -> dict``
and, optionally, ``summarize(rows) -> str`` for ``hexbot sweep report``."""
