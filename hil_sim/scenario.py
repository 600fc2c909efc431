"""Scenario files: which modules sit where, which firmware they run, which faults.

A scenario is a TOML file (built-ins in ``hil_sim/scenarios/``)::

    name = "pair"
    seed = 1                      # fault injection and garbage bytes
    base = 1                      # id of the module fixed to the base (never moves)
    clock_spread_ppm = 20000      # optional: each MCU's RC clock drawn (seeded) within +-2 %
    threads = 2                   # optional: host threads per quantum (default 1; same trace)

    [firmware]                    # optional; default: firmware/build/*.elf
    comm = "firmware/build/comm.elf"       # relative to the scenario file
    control = "firmware/build/control.elf"
    rf12 = "firmware/build/rf12.elf"        # optional: a wireless board on every module

    radio_range = 100             # optional: RF12 range in lattice cells (see radio.py)
    pc_radio = [0, 0]             # optional: the cell of the PC's radio (a `radio=1` port)

    [faults]                      # optional; applies to every IR link
    bit_error_rate = 0.0          # probability that each data bit flips
    byte_loss = 0.0               # probability that a byte vanishes
    framing_error_rate = 0.0      # probability that a byte's stop bit is broken
    spurious_byte_rate = 0.0      # probability of an extra byte on the idle line after a byte
    burst_rate = 0.0              # probability that a noise burst starts at a byte

    [[faults.link]]               # optional; overrides for one directed link
    from = 1                      # module id or "pc"
    to = 2
    byte_loss = 0.5

    [[module]]
    id = 1                        # 1..255, also its 8 DIP switches
    position = [0, 0]             # Table 4-1 axial coordinates
    orientation = 0               # 0..5, see geometry.py
    clock_ppm = -12000            # optional: both boards' clocks off nominal (overrides the spread)

Every error names the file, the line and the problem. Besides files, the
generator of :mod:`hexbot.hil_sim.scenario_gen` makes clusters of any size by
name: ``blob:50``, ``line:12``, ``blob:255:7`` (shape, modules, seed).
"""

from __future__ import annotations

import math
import os
import random
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Any

from hexbot.errors import ScenarioError
from hexbot.files import load_toml, read_text
from hexbot.protocol.timing import CLOCK_TOLERANCE
from hexbot.protocol.wire import LOC_COORD_LIMIT, MAX_MODULE_ID
from hexbot.toml_lines import TomlLines as _Lines
from hexbot.toml_lines import unknown_key

from .geometry import Cell

MAX_CLOCK_PPM = round(CLOCK_TOLERANCE * 1e6)  # an RC clock further off cannot talk at all
PC = "pc"

_TOP_KEYS = {"name", "description", "seed", "base", "firmware", "faults", "module",
             "clock_spread_ppm", "radio_range", "pc_radio", "threads"}
_MODULE_KEYS = {"id", "position", "orientation", "firmware", "clock_ppm"}
_FIRMWARE_KEYS = {"comm", "control", "rf12"}
#: RF12 range in lattice cells unless the scenario says otherwise: ~10 m at a
#: ~10 cm module pitch, a low figure for the chip at full power indoors.
DEFAULT_RADIO_RANGE = 100
#: Host threads that run a quantum's MCUs: one unless asked (see
#: docs/simulator-core.md, "Threads": the trace is the same with any number).
DEFAULT_THREADS = 1
MAX_THREADS = 256  # the core's limit (pyavr.c)
_FAULT_KEYS = {"bit_error_rate", "byte_loss", "framing_error_rate", "spurious_byte_rate",
               "burst_rate"}
_LINK_KEYS = _FAULT_KEYS | {"from", "to"}


@dataclass(frozen=True)
class Faults:
    """Fault injection on one IR link (or the default for all)."""

    bit_error_rate: float = 0.0
    byte_loss: float = 0.0
    framing_error_rate: float = 0.0  # the receiver sees a broken stop bit (USART FE)
    spurious_byte_rate: float = 0.0  # a noise pulse after a byte reads as one more byte
    burst_rate: float = 0.0  # a burst of noise over the next bits (ir_bus.BURST_BITS)

    @property
    def active(self) -> bool:
        return self.bit_error_rate > 0 or self.byte_loss > 0 or self.extended

    @property
    def extended(self) -> bool:
        """Faults beyond flips and drops (drawn only when set, so that runs
        without them keep their random sequence)."""
        return self.framing_error_rate > 0 or self.spurious_byte_rate > 0 or self.burst_rate > 0


@dataclass(frozen=True)
class Firmware:
    comm: Path
    control: Path
    rf12: Path | None = None  # the wireless board, if the module has one


@dataclass(frozen=True)
class ModuleSpec:
    id: int
    position: Cell
    orientation: int
    firmware: Firmware
    line: int  # where the module's table starts, for later error messages
    clock_ppm: float | None = None  # both boards; None: drawn from the scenario's spread


@dataclass
class Scenario:
    name: str
    modules: list[ModuleSpec]
    base: int | None = None
    seed: int = 0
    faults: Faults = field(default_factory=Faults)
    link_faults: dict[tuple[int | str, int | str], Faults] = field(default_factory=dict)
    path: Path | None = None
    description: str = ""
    clock_spread_ppm: float = 0.0
    radio_range: int = DEFAULT_RADIO_RANGE
    pc_radio: Cell = (0, 0)  # where the PC's radio stands (hil_sim/radio.py PcRadio)
    threads: int = DEFAULT_THREADS

    def clocks(self, seed: int) -> dict[tuple[int, str], float]:
        """Clock error in ppm of every MCU, by (module id, "comm"/"control"):
        the module's ``clock_ppm``, else drawn uniformly within the spread by
        a generator of its own (seeded), in module order."""
        rng = random.Random(seed ^ 0xC10C)
        spread = self.clock_spread_ppm
        clocks: dict[tuple[int, str], float] = {}
        for spec in sorted(self.modules, key=lambda m: m.id):
            for board in ("comm", "control"):
                drawn = rng.uniform(-spread, spread) if spread else 0.0
                clocks[(spec.id, board)] = drawn if spec.clock_ppm is None else spec.clock_ppm
        return clocks

    def faults_for(self, sender: int | str, receiver: int | str) -> Faults:
        return self.link_faults.get((sender, receiver), self.faults)

    def where(self, line: int) -> str:
        return f"{self.path or self.name}:{line}"

    def with_firmware(self, folder: Path) -> Scenario:
        """The same cluster with every module on ``folder``'s comm.elf and
        control.elf: one firmware build against another on the same scenario."""
        return replace(self, modules=[
            replace(m, firmware=replace(m.firmware, comm=Path(folder) / "comm.elf",
                                        control=Path(folder) / "control.elf"))
            for m in self.modules])


def default_firmware_dir() -> Path:
    """firmware/build of the source tree this package runs from."""
    return Path(__file__).resolve().parent.parent / "firmware" / "build"


def builtin_names() -> list[str]:
    folder = resources.files("hexbot.hil_sim") / "scenarios"
    return sorted(p.name[: -len(".toml")] for p in folder.iterdir() if p.name.endswith(".toml"))


def is_scenario_file(source: str | Path) -> bool:
    """Whether a scenario value names a file: a Path, or a name ending in
    ``.toml`` or holding a path separator (``rig.toml``, ``./pair``,
    ``../rigs/pair``); any other value is a built-in (``pair``) or generated
    (``blob:50``) name, whatever files the current folder holds. The one
    rule of ``--scenario``, ``# scenario:`` lines, ``hexbot sim``, the
    ``hexbot-sim://`` URL and the sweep's hil-script kind (docs/simulator.md,
    "Scenario names and files"): a file ``pair`` in the current folder ran
    instead of the built-in pair before session 37."""
    if isinstance(source, Path):
        return True
    return source.endswith(".toml") or "/" in source or os.sep in source


def load_scenario(source: str | Path) -> Scenario:
    """A scenario by built-in name (``"pair"``), generator name (``"blob:50"``)
    or TOML file (see :func:`is_scenario_file`)."""
    text_source = str(source)
    if is_scenario_file(source):
        path = Path(text_source)
        if not path.is_file():
            raise ScenarioError(f"{path}: no such scenario file")
        return parse_scenario(read_text(path), path)
    if text_source.split(":", 1)[0] in ("blob", "line") and ":" in text_source:
        from .scenario_gen import from_name

        return from_name(text_source)
    folder = resources.files("hexbot.hil_sim") / "scenarios"
    candidate = folder / f"{text_source}.toml"
    if not candidate.is_file():
        names = ", ".join(builtin_names())
        raise ScenarioError(f"unknown scenario {text_source!r}: built-in ones are {names} "
                            "(a file: a name ending in .toml, or ./NAME)")
    return parse_scenario(candidate.read_text(encoding="utf-8"), Path(str(candidate)))


def parse_scenario(text: str, path: Path) -> Scenario:
    data = load_toml(text, path)
    lines = _Lines(text)

    def fail(line: int, problem: str) -> ScenarioError:
        return ScenarioError(f"{path}:{line}: {problem}")

    def unknown(keys: set[str], allowed: set[str], table: str, index: int = -1) -> None:
        for key in sorted(keys - allowed):
            raise fail(lines.find(table, index, key),
                       unknown_key(key, allowed, f"[{table or 'top'}]"))

    unknown(set(data), _TOP_KEYS, "")
    name = data.get("name", path.stem)
    if not isinstance(name, str):
        raise fail(lines.find("", -1, "name"), "name must be a string")
    seed = data.get("seed", 0)
    if not isinstance(seed, int) or isinstance(seed, bool):
        raise fail(lines.find("", -1, "seed"), f"seed must be an integer, not {seed!r}")

    default_fw = _firmware(data.get("firmware", {}), None, path, lines, "firmware", -1, fail)

    faults = _faults(data.get("faults", {}), lines, "faults", -1, fail, set(_FAULT_KEYS | {"link"}))
    link_faults: dict[tuple[int | str, int | str], Faults] = {}
    raw_links = data.get("faults", {}).get("link", [])
    if not isinstance(raw_links, list):
        raise fail(lines.find("faults", -1, "link"), "faults.link must be an array of tables")

    modules_raw = data.get("module")
    if not isinstance(modules_raw, list) or not modules_raw:
        raise fail(1, "a scenario needs at least one [[module]] table")
    modules: list[ModuleSpec] = []
    ids: dict[int, int] = {}
    cells: dict[Cell, int] = {}
    for index, raw in enumerate(modules_raw):
        at = lines.find("module", index)
        if not isinstance(raw, dict):
            raise fail(at, "module must be an array of tables ([[module]]), not a list of values")
        unknown(set(raw), _MODULE_KEYS, "module", index)
        module_id = raw.get("id")
        if not isinstance(module_id, int) or isinstance(module_id, bool):
            raise fail(lines.find("module", index, "id"), "module id must be an integer")
        if not 1 <= module_id <= MAX_MODULE_ID:
            raise fail(
                lines.find("module", index, "id"),
                f"module id {module_id} outside 1..{MAX_MODULE_ID} (DIP switches PC0..PC7)",
            )
        if module_id in ids:
            raise fail(
                lines.find("module", index, "id"),
                f"module id {module_id} used twice (first at line {ids[module_id]})",
            )
        ids[module_id] = at
        pos = raw.get("position")
        pos_line = lines.find("module", index, "position")
        if (
            not isinstance(pos, list)
            or len(pos) != 2
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in pos)
        ):
            raise fail(pos_line, f"position must be [x, y] with two integers, not {pos!r}")
        cell = (pos[0], pos[1])
        if max(abs(cell[0]), abs(cell[1])) > LOC_COORD_LIMIT:
            raise fail(pos_line, f"position {list(cell)} outside +-{LOC_COORD_LIMIT}")
        if cell in cells:
            raise fail(pos_line, f"cell {list(cell)} already holds module {cells[cell]}")
        cells[cell] = module_id
        orientation = raw.get("orientation", 0)
        if (not isinstance(orientation, int) or isinstance(orientation, bool)
                or not 0 <= orientation <= 5):
            raise fail(
                lines.find("module", index, "orientation"),
                f"orientation must be an integer 0..5, not {orientation!r}",
            )
        fw = _firmware(raw.get("firmware", {}), default_fw, path, lines, "module", index, fail)
        clock = raw.get("clock_ppm")
        if clock is not None:
            clock = _ppm(clock, lines.find("module", index, "clock_ppm"), "clock_ppm", fail)
        modules.append(ModuleSpec(module_id, cell, orientation, fw, at, clock))

    for index, raw in enumerate(raw_links):
        if not isinstance(raw, dict):
            raise fail(lines.find("faults.link", index), "each faults.link must be a table")
        unknown(set(raw), _LINK_KEYS, "faults.link", index)
        ends: list[int | str] = []
        for key in ("from", "to"):
            value = raw.get(key)
            if value != PC and value not in ids:
                raise fail(
                    lines.find("faults.link", index, key),
                    f"{key} = {value!r} is neither \"pc\" nor the id of a module",
                )
            ends.append(value)
        link = _faults(raw, lines, "faults.link", index, fail, _LINK_KEYS)
        link_faults[(ends[0], ends[1])] = link

    base = data.get("base")
    if base is not None and base not in ids:
        raise fail(lines.find("", -1, "base"), f"base = {base!r} is not the id of a module")
    spread = _ppm(data.get("clock_spread_ppm", 0), lines.find("", -1, "clock_spread_ppm"),
                  "clock_spread_ppm", fail)
    if spread < 0:
        raise fail(lines.find("", -1, "clock_spread_ppm"),
                   f"clock_spread_ppm must not be negative, not {spread:g}")

    radio_range = data.get("radio_range", DEFAULT_RADIO_RANGE)
    if not isinstance(radio_range, int) or isinstance(radio_range, bool) or radio_range < 0:
        raise fail(lines.find("", -1, "radio_range"),
                   f"radio_range must be a whole number of cells >= 0, not {radio_range!r}")

    pc_radio = data.get("pc_radio", [0, 0])
    if (not isinstance(pc_radio, list) or len(pc_radio) != 2
            or not all(isinstance(v, int) and not isinstance(v, bool) for v in pc_radio)):
        raise fail(lines.find("", -1, "pc_radio"),
                   f"pc_radio must be a cell [x, y] of whole numbers, not {pc_radio!r}")

    threads = data.get("threads", DEFAULT_THREADS)
    if (not isinstance(threads, int) or isinstance(threads, bool)
            or not 1 <= threads <= MAX_THREADS):
        raise fail(lines.find("", -1, "threads"),
                   f"threads must be a whole number 1..{MAX_THREADS}, not {threads!r}")

    return Scenario(
        name=name,
        modules=modules,
        base=base,
        seed=seed,
        faults=faults,
        link_faults=link_faults,
        path=path,
        description=str(data.get("description", "")),
        clock_spread_ppm=spread,
        radio_range=radio_range,
        pc_radio=(pc_radio[0], pc_radio[1]),
        threads=threads,
    )


def _ppm(value: Any, line: int, key: str, fail: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise fail(line, f"{key} must be a number of ppm, not {value!r}")
    if abs(value) > MAX_CLOCK_PPM:
        raise fail(line, f"{key} = {value:g} beyond +-{MAX_CLOCK_PPM} ppm "
                         "(protocol/timing.py CLOCK_TOLERANCE)")
    return float(value)


def fault_rate_problem(key: str, value: Any) -> str | None:
    """What is wrong with ``value`` as the fault rate ``key`` (a probability
    0..1), or None: the rule of a scenario's [faults] and of the rates
    ``hexbot bench ir-noise --rates`` writes into its scenario."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not 0 <= value <= 1:
        return f"{key} must be a probability 0..1, not {value!r}"
    return None


def _faults(
    raw: Any, lines: _Lines, table: str, index: int, fail: Any, allowed: set[str]
) -> Faults:
    if not isinstance(raw, dict):
        raise fail(lines.find(table, index), f"[{table}] must be a table")
    for key in sorted(set(raw) - allowed):
        raise fail(lines.find(table, index, key), unknown_key(key, allowed, f"[{table}]"))
    values = {}
    for key in _FAULT_KEYS:
        value = raw.get(key, 0.0)
        problem = fault_rate_problem(key, value)
        if problem:
            raise fail(lines.find(table, index, key), problem)
        values[key] = float(value)
    return Faults(**values)


def _firmware(
    raw: Any,
    default: Firmware | None,
    path: Path,
    lines: _Lines,
    table: str,
    index: int,
    fail: Any,
) -> Firmware:
    if not isinstance(raw, dict):
        raise fail(lines.find(table, index, "firmware"), "firmware must be a table")
    fw_table = "firmware" if table == "firmware" else table
    for key in sorted(set(raw) - _FIRMWARE_KEYS):
        raise fail(lines.find(fw_table, index, key), f"unknown firmware image {key!r}")
    if default is None:
        base_dir = default_firmware_dir()
        default = Firmware(base_dir / "comm.elf", base_dir / "control.elf")
    images = {}
    for key in _FIRMWARE_KEYS:
        value = raw.get(key)
        if value is None:
            images[key] = getattr(default, key)
        elif not isinstance(value, str):
            raise fail(lines.find(fw_table, index, key), f"firmware {key} must be a path string")
        else:
            image = Path(value)
            images[key] = image if image.is_absolute() else (path.parent / image).resolve()
    return Firmware(**images)
