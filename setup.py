"""Build script: maps the top-level folders onto the ``hexbot`` package.

The folders (protocol/, host/, hil_sim/, planning/, bench/, sweep/) show the architecture;
they import as ``hexbot.<folder>``. Package metadata lives in pyproject.toml.
"""

import shlex
import subprocess
from pathlib import Path

from setuptools import Extension, setup

ROOTS = {
    "hexbot": "hexbot",
    "hexbot.protocol": "protocol",
    "hexbot.host": "host",
    "hexbot.hil_sim": "hil_sim",
    "hexbot.planning": "planning",
    "hexbot.bench": "bench",
    "hexbot.sweep": "sweep",
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


AVR_LIBC_IOM162 = Path("/usr/lib/avr/include/avr/iom162.h")


def pkg_config(*args: str) -> list[str]:
    """Flags from pkg-config, or [] when it or the package is missing."""
    try:
        out = subprocess.run(
            ["pkg-config", *args], check=True, capture_output=True, text=True
        ).stdout
    except (OSError, subprocess.CalledProcessError):
        return []
    return shlex.split(out)


def simavr_extension() -> Extension:
    """hexbot.hil_sim._avr: our ATmega162 core + lock-step scheduler on libsimavr."""
    if not AVR_LIBC_IOM162.exists():
        raise SystemExit(
            f"{AVR_LIBC_IOM162} is missing: install the Debian package avr-libc "
            "(the ATmega162 core takes its register map from it)"
        )
    cflags = pkg_config("--cflags", "simavr") or ["-I/usr/include/simavr"]
    libs = pkg_config("--libs", "simavr") or ["-lsimavr"]
    include_dirs = [f[2:] for f in cflags if f.startswith("-I")]
    library_dirs = [f[2:] for f in libs if f.startswith("-L")]
    libraries = [f[2:] for f in libs if f.startswith("-l")]
    for lib in ("simavr", "elf"):
        if lib not in libraries:
            libraries.append(lib)
    sources = sorted(p.as_posix() for p in Path("hil_sim/core").glob("*.c"))
    return Extension(
        "hexbot.hil_sim._avr",
        sources=sources,
        # firmware/include: the generated protocol header (fuses of Table 3-6)
        include_dirs=(include_dirs or ["/usr/include/simavr"]) + ["firmware/include"],
        library_dirs=library_dirs,
        libraries=libraries,
        extra_compile_args=["-std=gnu11", "-O2", "-Wall", "-Wno-unused-function",
                            "-Werror=implicit-function-declaration", "-pthread"],
        extra_link_args=["-pthread"],  # cluster_pool.c: the quantum's worker threads
        depends=sorted(p.as_posix() for p in Path("hil_sim/core").glob("*.h"))
        + ["firmware/include/hexbot_codes.h"],
    )


def planning_extension(name: str) -> Extension:
    """hexbot.planning.<name> from planning/<name>.c: the planners' hot searches
    (_crossing: a journey's crossing, planning/journey.py; _strip: the strip
    route's mover pick and paths, planning/canonical.py; _schedule: the list
    schedule, planning/schedule.py; _tidy: the detour-cutting pass,
    planning/tidy.py; _regroup: runs of moves re-planned together,
    planning/regroup.py)."""
    return Extension(
        f"hexbot.planning.{name}",
        sources=[f"planning/{name}.c"],
        depends=["planning/_rules.h"],
        extra_compile_args=["-std=gnu11", "-O2", "-Wall",
                            "-Werror=implicit-function-declaration"],
    )


packages, package_dir = find_packages_mapped()

setup(
    packages=packages,
    package_dir=package_dir,
    include_package_data=True,
    package_data={"": ["*.toml", "*.tcss", "*.txt", "*.rules", "*.map", "*.json"]},
    ext_modules=[simavr_extension(), planning_extension("_crossing"),
                 planning_extension("_strip"), planning_extension("_schedule"),
                 planning_extension("_tidy"), planning_extension("_regroup")],
)
