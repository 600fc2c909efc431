"""Optional dependencies, imported where they are used.

What most users never run (plots, rendered pictures) sits in an extra of
pyproject.toml; ``require`` turns its absence into a MissingExtraError that
says which extra to install, keeping the ImportError as the cause.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from hexbot.errors import MissingExtraError


def require(module: str, extra: str, purpose: str) -> ModuleType:
    """Import ``module`` (from the ``extra`` of hexbot) that ``purpose`` needs."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise MissingExtraError(
            f"{purpose} needs {module.split('.')[0]}, which is not installed: "
            f"pip install 'hexbot[{extra}]' ({exc})"
        ) from exc
