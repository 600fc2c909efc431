"""Scenarios (text maps of obstacles and modules) and the rule sets shipped as data.

Map format (``.map``): optional header lines ``key: value`` and ``;`` comments,
then the grid, top row first. ``#`` obstacle, ``o`` module, ``.`` (or a
space) empty; a row shorter than the widest is empty to its end.
Rows made only of ``#`` are floor: they continue without end to both sides
(a short floor row too).
Header keys: ``title``, ``figure`` (the thesis figure it reconstructs),
``directions`` (which of E N W S to offer; default all four).

A scenario named ``NAME-north`` (``-west``, ``-south``) is the map rotated so
the robot, following the right-hand rule, advances that way; ``NAME`` alone
advances east. ``--n`` rebuilds the strip with N modules ending at the map's
front module.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

from hexbot.errors import ScenarioError
from hexbot.files import read_text
from hexbot.planning.locomotion import rulefile
from hexbot.planning.locomotion.engine import Engine, Goal, RunResult, World
from hexbot.planning.locomotion.rules import RuleSet, rotate

Cell = tuple[int, int]
DIRECTION_TURNS = {"east": 0, "north": 1, "west": 2, "south": 3}
DIRECTION_LETTERS = {"E": "east", "N": "north", "W": "west", "S": "south"}


@dataclass
class Scenario:
    name: str
    obstacles: list[Cell]
    modules: list[Cell]
    direction: Cell = (1, 0)  # where the robot advances
    threshold: int | None = None  # goal: every module rests beyond this (along direction)
    title: str = ""
    figure: str = ""
    directions: list[str] = field(default_factory=lambda: list(DIRECTION_TURNS))

    def rotated(self, quarter_turns: int, suffix: str) -> Scenario:
        def rot(cells: list[Cell]) -> list[Cell]:
            return [rotate(c, quarter_turns) for c in cells]

        return Scenario(
            name=f"{self.name}-{suffix}" if quarter_turns else self.name,
            obstacles=rot(self.obstacles),
            modules=rot(self.modules),
            direction=rotate(self.direction, quarter_turns),
            threshold=self.threshold,
            title=self.title,
            figure=self.figure,
            directions=self.directions,
        )


#: The longest strip a run takes: the engine keeps a grid round the strip,
#: so a strip of 10^8 modules would need tens of GB before the first round.
MAX_MODULES = 100_000


def _check_n(n: int) -> None:
    if not 1 <= n <= MAX_MODULES:
        raise ScenarioError(f"--n must be 1..{MAX_MODULES:,}, got {n}")


def flat_scenario(n: int) -> Scenario:
    """A horizontal strip of n modules on a floor, advancing east (Table 1 of 001)."""
    _check_n(n)
    floor = [(x, -1) for x in range(-2, n + 3)]
    return Scenario("flat", floor, [(x, 0) for x in range(n)], title="no obstacles")


def parse_map(text: str, name: str, source: str, n: int | None = None) -> Scenario:
    header: dict[str, str] = {}
    rows: list[tuple[int, str]] = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.rstrip()
        if not line or line.startswith(";"):
            continue
        if not rows and ":" in line and not set(line.split(":")[0]) & set("#o."):
            key, _, value = line.partition(":")
            header[key.strip()] = value.strip()
            continue
        bad = set(line) - set("#o. ")
        if bad:
            raise ScenarioError(
                f"{source}:{lineno}: unknown map character {sorted(bad)[0]!r} "
                "(use # obstacle, o module, . empty)"
            )
        rows.append((lineno, line))
    if not rows:
        raise ScenarioError(f"{source}: the map has no rows")
    height = len(rows)
    # trailing spaces are empty cells, gone with rstrip: rows end where they end
    width = max(len(line) for _, line in rows)
    obstacles: list[Cell] = []
    modules: list[Cell] = []
    floor_rows: set[int] = set()
    for i, (_, line) in enumerate(rows):
        y = height - 1 - i
        if set(line) == {"#"}:
            floor_rows.add(y)
            line = line.ljust(width, "#")  # a floor runs on, also past a short row
        for x, ch in enumerate(line):
            if ch == "#":
                obstacles.append((x, y))
            elif ch == "o":
                modules.append((x, y))
    if not modules:
        raise ScenarioError(f"{source}: the map has no modules ('o')")
    if not floor_rows:
        raise ScenarioError(f"{source}: the map needs a floor: a row made only of '#'")
    module_rows = {y for _, y in modules}
    if len(module_rows) != 1:
        raise ScenarioError(f"{source}: the modules must form one horizontal strip")
    row = module_rows.pop()
    front = max(x for x, _ in modules)
    if n is not None:
        _check_n(n)
        modules = [(x, row) for x in range(front - n + 1, front + 1)]
    xs = sorted(x for x, _ in modules)
    if xs != list(range(xs[0], xs[-1] + 1)):
        raise ScenarioError(f"{source}: the strip of modules has a gap")
    lo = min(xs[0], 0) - 3
    for y in floor_rows:  # floors run on to the left, under a long strip
        obstacles.extend((x, y) for x in range(lo, 0))
    solid = set(obstacles)
    floating = [(x, y) for x, y in modules if (x, y - 1) not in solid]
    if floating:
        raise ScenarioError(f"{source}: the strip of modules must rest on the floor or on "
                            f"obstacles; nothing holds the cell below {floating[0]}")
    raised = [x for x, y in obstacles if y not in floor_rows]
    if not raised:
        raise ScenarioError(f"{source}: the map has no raised obstacle (a '#' off the floor "
                            "rows): the strip would have nothing to cross (the scenario "
                            "'flat' is a plain floor)")
    if max(raised) <= front:
        raise ScenarioError(f"{source}: every raised obstacle lies behind the strip's front "
                            f"(x = {front}): the strip would have nothing to cross")
    letters = header.get("directions", "E N W S").split()
    dirs = [DIRECTION_LETTERS.get(d.upper(), "?") for d in letters]
    if "?" in dirs:
        raise ScenarioError(f"{source}: directions must be letters among E N W S")
    return Scenario(
        name=name,
        obstacles=obstacles,
        modules=modules,
        threshold=max(raised),
        title=header.get("title", ""),
        figure=header.get("figure", ""),
        directions=dirs,
    )


def _data(package: str, suffix: str) -> dict[str, resources.abc.Traversable]:
    files = resources.files(f"hexbot.planning.locomotion.{package}")
    return {
        f.name[: -len(suffix)].replace("_", "-"): f
        for f in files.iterdir()
        if f.name.endswith(suffix)
    }


def ruleset_names() -> list[str]:
    return sorted(_data("rulesets", ".rules"))


def load_ruleset(name: str) -> RuleSet:
    """A shipped rule set by name (``salvador-free``), or a path to a .rules file."""
    shipped = _data("rulesets", ".rules")
    if name in shipped:
        return rulefile.loads(shipped[name].read_text(encoding="utf-8"), f"{name}.rules")
    if Path(name).is_file():
        return rulefile.load(name)
    raise ScenarioError(f"unknown rule set {name!r} (shipped: {', '.join(sorted(shipped))})")


def scenario_names(with_directions: bool = True) -> list[str]:
    names = ["flat"]
    for base, f in sorted(_data("maps", ".map").items()):
        names.append(base)
        if with_directions:
            sc = parse_map(f.read_text(encoding="utf-8"), base, f.name)
            names.extend(f"{base}-{d}" for d in sc.directions if d != "east")
    return names


def load_scenario(name: str, n: int | None = None) -> Scenario:
    """``flat``, a shipped map, ``random-SEED`` (optionally ``-north`` etc.), or a
    path to a .map file."""
    base, turns, suffix = name, 0, ""
    for d, q in DIRECTION_TURNS.items():
        if name.endswith(f"-{d}"):
            base, turns, suffix = name[: -len(d) - 1], q, d
    if base == "flat":
        sc = flat_scenario(20 if n is None else n)
    else:
        maps = _data("maps", ".map")
        if base in maps:
            sc = parse_map(maps[base].read_text(encoding="utf-8"), base, f"{base}.map", n)
        elif base.startswith("random-") and base[len("random-"):].isdigit():
            from hexbot.planning.locomotion.randommaps import random_map  # imports us

            seed = int(base[len("random-"):])
            sc = parse_map(random_map(seed), base, f"random seed {seed}", n)
        elif Path(name).is_file():
            return parse_map(read_text(name), Path(name).stem, name, n)
        elif name.endswith(".map") or "/" in name:
            raise ScenarioError(f"{name}: no such map file")
        else:
            raise ScenarioError(
                f"unknown scenario {name!r} (try: flat, {', '.join(sorted(maps))}; "
                "random-SEED for a random map; "
                "add -north, -west or -south for the rotated versions)"
            )
    if suffix and suffix not in sc.directions:
        raise ScenarioError(f"scenario {base!r} is not offered going {suffix}")
    return sc.rotated(turns, suffix)


def simulate(
    ruleset: RuleSet,
    scenario: Scenario,
    rounds: int = 10_000,
    until_advance: int | None = None,
    on_round: Callable[[Engine], None] | None = None,
    check_connectivity: bool = True,
) -> RunResult:
    """Run a rule set on a scenario. The run ends when ``until_advance`` modules
    have come to rest in new cells, when every module rests past the obstacle
    (maps only, without ``until_advance``), on a deadlock, a violation, or after
    ``rounds`` rounds."""
    axis = 0 if scenario.direction[0] else 1
    states = [ruleset.states[0]] * len(scenario.modules)
    if ruleset.front_state:
        dx, dy = scenario.direction
        front = max(range(len(states)), key=lambda i: scenario.modules[i][0] * dx
                    + scenario.modules[i][1] * dy)
        states[front] = ruleset.front_state
    world = World(scenario.obstacles, scenario.modules, ruleset.states,
                  module_states=states, extend_axis=axis)
    frame = [(1, 0), (0, 1), (-1, 0), (0, -1)].index(scenario.direction)
    engine = Engine(ruleset, world, check_connectivity=check_connectivity, frame=frame)
    if until_advance is not None:
        goal = Goal(advance=until_advance)
    elif scenario.threshold is not None:
        goal = Goal(direction=scenario.direction, threshold=scenario.threshold)
    else:
        goal = Goal()
    return engine.run(rounds, goal, on_round)
