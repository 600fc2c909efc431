"""HexBot scripts (``*.hbs``): a user's hardware-in-the-loop regression.

One command per line, ``#`` starts a comment, words are separated by
spaces. The whole file is checked before anything is sent, so a typo on
line 40 does not leave the cluster half-configured. Execution stops at the
first failed step. Grammar (``[...]`` optional, ``ID...`` one or more)::

    timeout S                      wait S for the following steps' replies and
                                   expectations (default: replies as long as the
                                   protocol says each function takes, 5 s for
                                   expectations)
    select ID...                   Select(ids) (0 = all); expects their ACKs
    FUNCTION [ARG...]              send a function by name or code and expect
                                   its ACK from every selected module
                                   (e.g. ``Ref``, ``JxOpen 3``, ``65``)
    send FUNCTION [ARG...]         the same, spelled out
    post FUNCTION [ARG...]         send without waiting for anything
    status                         Status(); expects a STA from each selected module
    rotate cw|ccw JOINT mobile ID substrate ID [verify auto|plant|localize|status]
                                   67/68 about a lattice joint: sets the roles,
                                   body indices from each module's last status,
                                   thesis timings; verified (plant on the
                                   simulator, re-localization elsewhere)
    plan GOAL [reference ID] [verify auto|plant|localize|status]
                                   localize from the reference (default: the
                                   simulator's base module, else the lowest
                                   id), plan from the cluster to the goal
                                   configuration file GOAL (relative to the
                                   script; robust mode, the reference fixed),
                                   execute it move by move, each verified, and
                                   localize again: the step passes only when
                                   the cluster is the goal
    wait S                         let S seconds pass (replies keep arriving)
    expect ack CODE [from ID...] [within S]
    expect err CODE [REASON] [from ID...] [within S]
    expect text PHRASE [count N] [within S]      e.g. ``expect text LOCALIZED count 7``
    expect status ID [localized|unlocalized] [at X Y] [yref R] [role M|S|-]
    expect placements N [within S] at least N modules reported a position
    expect quiet S                 no ERR and no garbage for S seconds
    echo TEXT                      print TEXT

Expectations look at everything received since the last sent command, so
a reply that arrived during a ``wait`` still counts. Every ``S`` is a finite
number of seconds more than 0 and at most :data:`MAX_SECONDS`.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from hexbot.cli_args import seconds_up_to
from hexbot.errors import FrameError, HexBotError, LinkUnavailableError, ScenarioError
from hexbot.files import read_text
from hexbot.host import workflows
from hexbot.host.commands import parse_command
from hexbot.host.describe import describe_event
from hexbot.host.events import Observed
from hexbot.host.host import IR
from hexbot.host.session import OutcomeKind, Session, select
from hexbot.protocol.codes import ErrorCode, lookup
from hexbot.protocol.frames import Command
from hexbot.protocol.parser import Ack, ErrorReply, Garbage, StatusReport, Text

DEFAULT_TIMEOUT = 5.0
#: The longest time a script may name (``timeout``, ``wait``, ``within``,
#: ``expect quiet``): an hour. Longer is a typo or a hang (docs/console.md,
#: "Script language"); a command's own reply wait without ``timeout`` is the
#: protocol's bound for it, which this does not cap.
MAX_SECONDS = 3600.0
#: The argparse types of the host commands' own waits, capped as a script's
#: times are (the same clocks: 1e300 hung a session on the simulator at
#: speed 0): ``send``/``console --timeout``, and ``send --linger``, where 0
#: is the default and means no linger.
timeout_seconds = seconds_up_to(MAX_SECONDS)
linger_seconds = seconds_up_to(MAX_SECONDS, zero=True)


class ScriptFailed(HexBotError):
    """A step of a script did not get what it expected. ``exit_status``: 1,
    or its cause's (3 a command no module answered in time)."""

    def __init__(self, message: str, exit_status: int = 1) -> None:
        super().__init__(message)
        self.exit_status = exit_status


@dataclass(frozen=True)
class Step:
    line: int
    text: str
    verb: str
    words: tuple[str, ...]
    command: Command | None = None  # for steps that send


def _int(word: str, what: str, where: str) -> int:
    try:
        return int(word, 0)
    except ValueError:
        raise ScenarioError(f"{where}: {what} must be a number, got {word!r}") from None


def _count(word: str, what: str, where: str) -> int:
    """A count an expectation waits for: at least 1 (0 would pass at once)."""
    value = _int(word, what, where)
    if value < 1:
        raise ScenarioError(f"{where}: {what} must be at least 1, got {word!r}")
    return value


def _seconds(word: str, what: str, where: str) -> float:
    """A time to wait (``timeout``, ``wait``, ``within``, ``expect quiet``): a
    finite number more than 0 and at most MAX_SECONDS. 0 would judge nothing;
    nan compared as no time at all and passed at once; inf and 1e300 waited
    for ever on the simulator's virtual clock."""
    try:
        value = float(word)
    except ValueError:
        raise ScenarioError(f"{where}: {what} must be a number, got {word!r}") from None
    if not math.isfinite(value):
        raise ScenarioError(f"{where}: {what} must be a finite number, got {word!r}")
    if value <= 0:
        raise ScenarioError(f"{where}: {what} must be more than 0, got {word!r}")
    if value > MAX_SECONDS:
        raise ScenarioError(f"{where}: {what} must be at most {MAX_SECONDS:g} (an hour), "
                            f"got {word!r}")
    return value


def _options(words: list[str], where: str, known: dict[str, int]) -> dict[str, list[str]]:
    """Split ``from 3 4 within 2`` style keyword options; known maps each
    keyword to its number of values (-1 = all numbers that follow)."""
    out: dict[str, list[str]] = {}
    i = 0
    while i < len(words):
        key = words[i]
        if key not in known:
            raise ScenarioError(f"{where}: unexpected {key!r} (expected one of "
                                f"{', '.join(known)})")
        n = known[key]
        if n == -1:
            j = i + 1
            while j < len(words) and words[j].lstrip("-").isdigit():
                j += 1
            vals = words[i + 1 : j]
        else:
            vals = words[i + 1 : i + 1 + n]
            j = i + 1 + n
        if (n == -1 and not vals) or len(vals) < max(n, 0):
            raise ScenarioError(f"{where}: {key!r} needs a value")
        if key == "within":
            _seconds(vals[0], "within", where)
        out[key] = vals
        i = j
    return out


def parse_script(text: str, name: str = "<script>") -> list[Step]:
    """Every line checked; a ScenarioError lists every bad line (one per
    line of its message, ``file:line: problem``), not only the first."""
    steps, problems = [], []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        try:
            steps.append(_parse_line(line, f"{name}:{number}", number))
        except ScenarioError as exc:
            problems.append(str(exc))
    if problems:
        raise ScenarioError("\n".join(problems))
    return steps


def load_script(path: Path) -> list[Step]:
    path = Path(path)
    return parse_script(read_text(path, "script"), str(path))


def _parse_line(line: str, where: str, number: int) -> Step:  # noqa: C901 - one branch a verb
    words = line.split()
    verb, rest = words[0].lower(), words[1:]
    cmd: Command | None = None
    try:
        if verb == "timeout" or verb == "wait":
            if len(rest) != 1:
                raise ScenarioError(f"{where}: {verb} takes one number of seconds")
            _seconds(rest[0], "seconds", where)
        elif verb == "select":
            if not rest:
                raise ScenarioError(f"{where}: select needs at least one module id (0 = all)")
            cmd = select(*[_int(w, "module id", where) for w in rest])
        elif verb in ("send", "post"):
            cmd = parse_command(rest)
        elif verb == "status":
            if rest:
                raise ScenarioError(f"{where}: status takes no arguments "
                                    "(use 'expect status ID ...' to check one)")
            cmd = parse_command(["Status"])
        elif verb == "rotate":
            _parse_rotate(rest, where)
        elif verb == "plan":
            _parse_plan(rest, where)
        elif verb == "expect":
            _parse_expect(rest, where)
        elif verb == "echo":
            pass
        else:
            cmd = parse_command(words)
            verb, rest = "send", words
    except FrameError as exc:
        raise ScenarioError(f"{where}: {exc}") from None
    return Step(number, line, verb, tuple(rest), cmd)


def _parse_rotate(rest: list[str], where: str) -> tuple[str, int, int, int, workflows.Verify]:
    verify = workflows.Verify.AUTO
    if len(rest) == 8 and rest[6] == "verify":
        try:
            verify = workflows.Verify.named(rest[7])
        except ScenarioError as exc:
            raise ScenarioError(f"{where}: {exc}") from None
        rest = rest[:6]
    if len(rest) != 6 or rest[2] != "mobile" or rest[4] != "substrate":
        raise ScenarioError(f"{where}: expected 'rotate cw|ccw JOINT mobile ID substrate ID "
                            "[verify auto|plant|localize|status]'")
    direction = rest[0].lower()
    if direction not in ("cw", "ccw"):
        raise ScenarioError(f"{where}: direction must be cw or ccw, got {rest[0]!r}")
    joint = _int(rest[1], "joint", where)
    if not 1 <= joint <= 6:
        raise ScenarioError(f"{where}: joint must be 1..6, got {joint}")
    return (direction, joint, _int(rest[3], "mobile id", where),
            _int(rest[5], "substrate id", where), verify)


def _parse_plan(rest: list[str], where: str):
    """The step's :class:`~hexbot.planning.execute.PlanRequest` (its goal file
    relative to the script)."""
    from hexbot.planning.execute import plan_request

    script = Path(where.rsplit(":", 1)[0])
    try:
        return plan_request(rest, script.parent if script.parent.is_dir() else None)
    except HexBotError as exc:
        raise ScenarioError(f"{where}: {exc}") from None


_EXPECT_OPTIONS = {
    "ack": {"from": -1, "within": 1},
    "err": {"from": -1, "within": 1},
    "placements": {"within": 1},
}


def _parse_expect(rest: list[str], where: str) -> None:  # noqa: C901
    if not rest:
        raise ScenarioError(f"{where}: expect what? (ack, err, text, status, placements, quiet)")
    kind, args = rest[0].lower(), rest[1:]
    if kind == "ack":
        if not args:
            raise ScenarioError(f"{where}: expect ack needs a function code or name")
        _code(args[0], where)
        _options(args[1:], where, _EXPECT_OPTIONS["ack"])
    elif kind == "err":
        if not args:
            raise ScenarioError(f"{where}: expect err needs a function code or name")
        _code(args[0], where)
        tail = args[1:]
        if tail and tail[0] not in ("from", "within"):
            _reason(tail[0], where)
            tail = tail[1:]
        _options(tail, where, _EXPECT_OPTIONS["err"])
    elif kind == "text":
        _split_text(args, where)
    elif kind == "status":
        _parse_status_expect(args, where)
    elif kind == "placements":
        if not args:
            raise ScenarioError(f"{where}: expect placements needs a count")
        _count(args[0], "count", where)
        _options(args[1:], where, _EXPECT_OPTIONS["placements"])
    elif kind == "quiet":
        if len(args) != 1:
            raise ScenarioError(f"{where}: expect quiet takes one number of seconds")
        _seconds(args[0], "seconds", where)
    else:
        raise ScenarioError(f"{where}: unknown expectation {kind!r} "
                            "(ack, err, text, status, placements, quiet)")


def _code(word: str, where: str) -> int:
    try:
        return lookup(word).code
    except KeyError:
        raise ScenarioError(f"{where}: unknown function {word!r}") from None


def _reason(word: str, where: str) -> int:
    if word.isdigit():
        return int(word)
    try:
        return ErrorCode[word.upper()].value
    except KeyError:
        raise ScenarioError(f"{where}: unknown error reason {word!r} (one of "
                            f"{', '.join(e.name for e in ErrorCode)})") from None


def _split_text(args: list[str], where: str) -> tuple[str, int, float | None]:
    count, within = 1, None
    words = list(args)
    while len(words) >= 2 and words[-2] in ("count", "within"):
        if words[-2] == "count":
            count = _count(words[-1], "count", where)
        else:
            within = _seconds(words[-1], "within", where)
        words = words[:-2]
    if not words:
        raise ScenarioError(f"{where}: expect text needs a phrase")
    return " ".join(words), count, within


def _parse_status_expect(args: list[str], where: str) -> dict:
    if not args:
        raise ScenarioError(f"{where}: expect status needs a module id")
    want: dict = {"id": _int(args[0], "module id", where)}
    i = 1
    while i < len(args):
        w = args[i].lower()
        if w in ("localized", "unlocalized"):
            want["localized"] = w == "localized"
            i += 1
        elif w == "at" and len(args) >= i + 3:
            want["at"] = (_int(args[i + 1], "x", where), _int(args[i + 2], "y", where))
            i += 3
        elif w == "yref" and len(args) >= i + 2:
            want["yref"] = _int(args[i + 1], "yref", where)
            i += 2
        elif w == "role" and len(args) >= i + 2:
            if args[i + 1] not in ("M", "S", "-"):
                raise ScenarioError(f"{where}: role must be M, S or -, got {args[i + 1]!r}")
            want["role"] = args[i + 1]
            i += 2
        else:
            raise ScenarioError(f"{where}: in expect status, unexpected {args[i]!r} "
                                "(localized, unlocalized, at X Y, yref R, role M|S|-)")
    return want


# --- execution --------------------------------------------------------------


class StepStatus(enum.Enum):
    PASSED = "passed"
    FAILED = "failed"    # the step did not get what it expected
    ERROR = "error"      # the port was lost (or Ctrl-C): the step could not be judged
    NOT_RUN = "not run"  # an earlier step failed


@dataclass(frozen=True)
class StepResult:
    step: Step
    status: StepStatus
    seconds: float = 0.0  # on the session's clock (simulated seconds on a simulator)
    message: str = ""  # the reply for a pass, the reason for a failure


#: the message of the step a Ctrl-C cut short (JUnit: an error of type Interrupted)
INTERRUPTED = "interrupted (Ctrl-C)"


def not_started(steps: list[Step], reason: str) -> list[StepResult]:
    """The results of a script whose session never ran a step (the port did
    not open, the modules did not boot, Ctrl-C during the boot): its first
    step an error with ``reason``, the others not run, so a JUnit report
    says why and counts every step."""
    return [StepResult(steps[0], StepStatus.ERROR, 0.0, reason),
            *(StepResult(s, StepStatus.NOT_RUN) for s in steps[1:])]


Printer = Callable[[str], None]


class ScriptRunner:
    """Runs parsed steps over a :class:`~hexbot.host.session.Session`. Waits
    for replies last as long as the protocol says each function takes,
    unless the script set ``timeout S``; expectations wait ``within`` or
    that time-out (5 s by default)."""

    def __init__(self, session: Session, name: str = "<script>", out: Printer = print) -> None:
        self.session = session
        self.host = session.host
        self.name = name
        self.out = out
        self.timeout = DEFAULT_TIMEOUT
        self.reply_timeout: float | None = None  # None: the protocol's bound per function
        self.mark = self.host.mark()
        self.results: list[StepResult] = []

    @property
    def steps_done(self) -> int:
        return sum(r.status is StepStatus.PASSED for r in self.results)

    def run(self, steps: list[Step]) -> None:
        """Run every step; ScriptFailed at the first failure. Each step's
        result (with its session-clock duration) goes to ``results``; the
        steps after a failure are recorded as not run."""
        for index, step in enumerate(steps):
            try:
                self.run_step(step)
            except HexBotError:
                self.results.extend(StepResult(s, StepStatus.NOT_RUN) for s in steps[index + 1:])
                raise
            except KeyboardInterrupt:  # the report must not read as a pass
                self.results.append(StepResult(step, StepStatus.ERROR, 0.0, INTERRUPTED))
                self.results.extend(StepResult(s, StepStatus.NOT_RUN) for s in steps[index + 1:])
                raise

    def run_step(self, step: Step) -> StepResult:
        """One step; its result is appended to ``results`` and returned,
        or ScriptFailed / LinkUnavailableError raised (and recorded)."""
        started = self.session.now()

        def record(status: StepStatus, message: str = "") -> StepResult:
            result = StepResult(step, status, self.session.now() - started, message)
            self.results.append(result)
            return result

        if self.session.cancel.is_set():
            record(StepStatus.FAILED, "cancelled")
            raise ScriptFailed(f"{self.name}:{step.line}: cancelled")
        try:
            text = self._step(step)
        except ScriptFailed as exc:
            record(StepStatus.FAILED, str(exc))
            raise
        except LinkUnavailableError as exc:  # a lost port is no failed step: the caller says so
            record(StepStatus.ERROR, str(exc))
            raise
        except HexBotError as exc:
            failure = ScriptFailed(f"{self.name}:{step.line}: {step.text}: {exc}",
                                   exc.exit_status)
            record(StepStatus.FAILED, str(failure))
            raise failure from exc
        self.out(f"{step.line:4d} ok    {step.text}" + (f"  -> {text}" if text else ""))
        return record(StepStatus.PASSED, text)

    def _fail(self, step: Step, why: str) -> ScriptFailed:
        return ScriptFailed(f"{self.name}:{step.line}: {step.text}: {why}")

    def _step(self, step: Step) -> str:
        w = list(step.words)
        where = f"{self.name}:{step.line}"
        if step.verb == "timeout":
            self.timeout = self.reply_timeout = float(w[0])
            return ""
        if step.verb == "wait":
            self._sleep(float(w[0]))
            return ""
        if step.verb == "echo":
            return " ".join(w)
        if step.verb == "post":
            assert step.command is not None
            self.mark = self.session.send(step.command)
            return f"sent {step.command}"
        if step.verb in ("select", "send", "status"):
            return self._exchange(step, step.command)
        if step.verb == "rotate":
            direction, joint, mobile, substrate, verify = _parse_rotate(w, where)
            self.mark = self.host.mark()
            return workflows.rotate(self.session, direction, joint, mobile, substrate,
                                    verify=verify).describe()
        if step.verb == "plan":
            return self._plan(step, w, where)
        if step.verb == "expect":
            return self._expect(step, w, where)
        raise self._fail(step, f"unknown verb {step.verb}")  # parse_script prevents this

    def _plan(self, step: Step, w: list[str], where: str) -> str:
        """Localize, plan, execute, localize again (:mod:`hexbot.planning.execute`,
        the same as ``hexbot plan --execute`` and the console's plan)."""
        from hexbot.planning.cli_plan import plan_summary
        from hexbot.planning.execute import execute, plan_from_cluster

        request = _parse_plan(w, where)
        reference = request.reference_in(self.session)
        self.mark = self.host.mark()
        plan, poses = plan_from_cluster(self.session, request.goal, reference)
        self.out(f"{step.line:4d} ..    {plan_summary(plan)}")
        report = execute(plan, self.session, reference, verify=request.verify, poses=poses,
                         log=lambda line: self.out(f"{step.line:4d} ..    {line.strip()}"))
        return report.outcome(plan.move_count)

    def _exchange(self, step: Step, cmd: Command | None) -> str:
        assert cmd is not None
        before = self.host.mark()
        # (in legacy mode the session itself judges every module's answer)
        outcome = self.session.exchange(cmd, timeout=self.reply_timeout)
        self.mark = before
        if outcome.kind is OutcomeKind.PORT_LOST:
            outcome.raise_for_status()
        if not outcome.ok:
            failure = self._fail(step, outcome.reason)
            if outcome.kind is OutcomeKind.TIMED_OUT:
                failure.exit_status = 3
            raise failure
        return ", ".join(outcome.lines())

    def _sleep(self, seconds: float) -> None:
        """Wait ``seconds`` of session time; a port lost before or during it
        ends the wait (a dead port is not a quiet one)."""
        self.session.host.clock.wait(lambda: self.session.port_lost() is not None
                                     or self.session.cancel.is_set(), seconds)
        lost = self.session.port_lost()
        if lost is not None:
            raise LinkUnavailableError(f"{self.name}: port lost ({lost})")

    def _wait(self, pred: Callable[[Observed], bool], within: float | None) -> Observed | None:
        found = self.session.wait_for(pred, self.mark,
                                      self.timeout if within is None else within)
        lost = self.session.port_lost()
        if found is None and lost is not None:
            raise LinkUnavailableError(f"{self.name}: port lost ({lost})")
        return found

    def _expect(self, step: Step, w: list[str], where: str) -> str:  # noqa: C901
        kind, args = w[0].lower(), w[1:]
        if kind in ("ack", "err"):
            code = _code(args[0], where)
            tail = args[1:]
            reason = None
            if kind == "err" and tail and tail[0] not in ("from", "within"):
                reason, tail = _reason(tail[0], where), tail[1:]
            opts = _options(tail, where, _EXPECT_OPTIONS[kind])
            ids = {int(x, 0) for x in opts.get("from", [])}
            within = float(opts["within"][0]) if "within" in opts else None
            cls = Ack if kind == "ack" else ErrorReply
            got: dict[int | None, Observed] = {}
            need = ids or {None}

            def match(o: Observed) -> bool:
                ev = o.event
                if o.port != IR or not isinstance(ev, cls) or ev.code != code:
                    return False
                if reason is not None and ev.reason != reason:
                    return False
                key = ev.module if ids else None
                if key in need and key not in got:
                    got[key] = o
                return set(got) >= need

            if self._wait(match, within) is None:
                missing = sorted(k for k in need - set(got) if k is not None)
                who = f" from {', '.join(map(str, missing))}" if missing else ""
                raise self._fail(step, f"no {kind.upper()} {code}{who} "
                                       f"within {within or self.timeout:g} s"
                                 + self._recent())
            return ", ".join(describe_event(o.event) for o in got.values())
        if kind == "text":
            phrase, count, within = _split_text(args, where)
            seen: list[Observed] = []

            def text_match(o: Observed) -> bool:
                ev = o.event
                if isinstance(ev, Text) and (ev.phrase + (" " + ev.tail if ev.tail else "")
                                             ).startswith(phrase):
                    if o not in seen:
                        seen.append(o)
                return len(seen) >= count

            if self._wait(text_match, within) is None:
                raise self._fail(step, f"saw {len(seen)} of {count} {phrase!r}"
                                 + self._recent())
            return f"{len(seen)} x {phrase}"
        if kind == "status":
            want = _parse_status_expect(args, where)
            obs = self._wait(lambda o: o.port == IR and isinstance(o.event, StatusReport)
                             and o.event.module_id == want["id"], None)
            if obs is None:
                raise self._fail(step, f"no status from module {want['id']}" + self._recent())
            ev = obs.event
            assert isinstance(ev, StatusReport)
            problems = []
            if "localized" in want and ev.localized != want["localized"]:
                problems.append("localized" if ev.localized else "not localized")
            if "at" in want and (ev.x, ev.y) != want["at"]:
                problems.append(f"at ({ev.x},{ev.y})")
            if "yref" in want and ev.yref != want["yref"]:
                problems.append(f"yref {ev.yref}")
            if "role" in want and ev.role != want["role"]:
                problems.append(f"role {ev.role}")
            if problems:
                raise self._fail(step, "module is " + ", ".join(problems)
                                 + f" ({describe_event(ev)})")
            return describe_event(ev)
        if kind == "placements":
            n = int(args[0], 0)
            opts = _options(args[1:], where, _EXPECT_OPTIONS["placements"])
            within = float(opts["within"][0]) if "within" in opts else self.timeout
            self.session.clock.wait(lambda: len(self.host.model.placements) >= n
                                    or self.session.cancel.is_set(), within)
            have = len(self.host.model.placements)
            if have < n:
                raise self._fail(step, f"{have} of {n} modules reported a position "
                                       f"within {within:g} s")
            return f"{have} placed"
        if kind == "quiet":
            start = self.host.mark()
            self._sleep(float(args[0]))
            bad = [o for o in self.host.since(start)
                   if isinstance(o.event, (ErrorReply, Garbage))]
            if bad:
                raise self._fail(step, "; ".join(describe_event(o.event) for o in bad))
            return "quiet"
        raise self._fail(step, f"unknown expectation {kind}")

    def _recent(self) -> str:
        evs = self.host.since(self.mark)[-4:]
        if not evs:
            return " (nothing received)"
        return " (last received: " + "; ".join(describe_event(o.event) for o in evs) + ")"
