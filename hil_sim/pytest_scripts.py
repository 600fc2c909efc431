"""pytest collection of HexBot scripts (``test_*.hbs``): one item per step.

The steps of a script depend on each other (Select before Ref), so they
share one booted session opened when the first step runs and closed after
the last; a failed step skips the rest, as ``hexbot run`` stops there.
"""

from __future__ import annotations

from contextlib import ExitStack
from typing import Any

import pytest

from hexbot.errors import HexBotError
from hexbot.hil_sim.pytest_plugin import booted_session
from hexbot.host.cli_run import declared_scenario
from hexbot.host.junit import SKIPPED_REASON, testcase_name
from hexbot.host.script import ScriptRunner, Step, StepResult, StepStatus, load_script


class ScriptFile(pytest.File):
    runner: ScriptRunner | None = None
    failed = False

    def collect(self):
        steps = load_script(self.path)  # a bad line: a collection error with file:line
        declared_scenario(self.path)  # and a scenario line that names nothing loadable
        for step in steps:
            yield ScriptStep.from_parent(
                self, name=testcase_name(StepResult(step, StepStatus.NOT_RUN)), step=step)

    def setup(self) -> None:
        self._stack = ExitStack()
        scenario = (declared_scenario(self.path)
                    or self.config.getoption("--hexbot-scenario"))
        session = self._stack.enter_context(booted_session(scenario, None))
        self.runner = ScriptRunner(session, str(self.path), out=lambda line: None)

    def teardown(self) -> None:
        self._stack.close()


class ScriptStep(pytest.Item):
    def __init__(self, *, step: Step, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.step = step

    @property
    def script(self) -> ScriptFile:
        assert isinstance(self.parent, ScriptFile)
        return self.parent

    def runtest(self) -> None:
        if self.script.failed:
            pytest.skip(SKIPPED_REASON)
        assert self.script.runner is not None
        try:
            result = self.script.runner.run_step(self.step)
        except HexBotError:
            self.script.failed = True
            raise
        if result.message:
            self.user_properties.append(("reply", result.message))

    def repr_failure(self, excinfo: pytest.ExceptionInfo[BaseException], style=None) -> str:
        if isinstance(excinfo.value, HexBotError):
            return str(excinfo.value)  # file:line: command: reason, no traceback
        return str(super().repr_failure(excinfo, style))

    def reportinfo(self):
        return self.path, self.step.line - 1, self.name
