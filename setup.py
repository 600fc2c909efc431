"""Build script: maps the top-level folders onto the ``hexbot`` package.

The folders (protocol/, host/, hil_sim/, planning/) show the architecture;
they import as ``hexbot.<folder>``. Package metadata lives in pyproject.toml.
"""

from pathlib import Path

from setuptools import setup

ROOTS = {
    "hexbot": "hexbot",
    "hexbot.protocol": "protocol",
    "hexbot.host": "host",
    "hexbot.hil_sim": "hil_sim",
    "hexbot.planning": "planning",
}


def find_packages_mapped() -> tuple[list[str], dict[str, str]]:
    """Every folder with an __init__.py below a root becomes a subpackage."""
    packages: list[str] = []
    package_dir: dict[str, str] = {}
    for name, folder in ROOTS.items():
        root = Path(folder)
        for init in sorted(root.rglob("__init__.py")):
            rel = init.parent.relative_to(root)
            if any(part.startswith(".") or part == "__pycache__" for part in rel.parts):
                continue
            pkg = ".".join([name, *rel.parts])
            packages.append(pkg)
            package_dir[pkg] = init.parent.as_posix()
    return packages, package_dir


packages, package_dir = find_packages_mapped()

setup(
    packages=packages,
    package_dir=package_dir,
    include_package_data=True,
    package_data={"": ["*.toml", "*.tcss", "*.txt", "*.rules", "*.map", "*.json"]},
)
