"""Small modal screens: the help screen, a value prompt, the rotation form,
a plan to confirm."""

from __future__ import annotations

from rich.markup import escape
from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Button, Input, Label, Markdown, Select

from hexbot.protocol.codes import lookup

HELP = """\
# HexBot console

The thesis' VB GUI in the terminal: two ports (IR transceiver and a
control board's UART1), a composer for every function code, terminals
with decoded replies, a modules table and the lattice.

## Keys
{keys}

## Workflows
- **Select** (`s`): code 69 with the ids you type (0 = all); later
  commands go to those modules, which answer in list order.
- **Ref** (`r`): code 65 to the selection: it becomes the reference at
  (0,0), Yref 0, role S.
- **Localize** (`l`): Select(ref), Ref, Select(0), Localize (66), then
  Status (70) from everyone: positions and orientations fill the modules
  table and the lattice.
- **Status** (`t`): code 70 to the selection.
- **Rotate** (`w`): 67/68 about a joint in lattice directions; each
  module's body joint is computed from its orientation; Table 3-1 timings.
- **All off** (`o`): code 20 (TurnOffAll) to every module.
- **Plan** (`g`): asks for a goal configuration file, localizes, plans
  from the cluster as it stands (robust mode, the reference module stays
  put) and shows the plan next to its lower bounds; **Execute** runs it
  move by move, each move verified, and claims the goal only after a last
  localization. The first refused or unverified move stops it.

Long operations show progress in the status line (replies so far,
seconds waited and the time-out); `escape` cancels.
Every byte in and out is captured in the session folder shown in the
Ports tab (`5`); `hexbot replay FOLDER` plays it back.
"""


class HelpScreen(ModalScreen[None]):
    BINDINGS = [Binding("escape,q,f1,question_mark", "dismiss", "Close help")]

    def __init__(self, keys: list[tuple[str, str]]) -> None:
        super().__init__()
        self.keys = keys

    def compose(self) -> ComposeResult:
        table = "\n".join(f"- `{k}` {d}" for k, d in self.keys)
        with VerticalScroll(id="help-box"):
            yield Markdown(HELP.format(keys=table))
            yield Label("escape closes", classes="hint")


class PromptScreen(ModalScreen[str | None]):
    """Ask for one line of text (module ids, a reference id)."""

    BINDINGS = [Binding("escape", "cancel", "Cancel")]

    def __init__(self, question: str, default: str = "") -> None:
        super().__init__()
        self.question = question
        self.default = default

    def compose(self) -> ComposeResult:
        with Vertical(classes="dialog"):
            yield Label(escape(self.question))
            yield Input(self.default, id="prompt-input")
            yield Label("enter confirms, escape cancels", classes="hint")

    @on(Input.Submitted)
    def _done(self, event: Input.Submitted) -> None:
        self.dismiss(event.value.strip())

    def action_cancel(self) -> None:
        self.dismiss(None)


class RotateScreen(ModalScreen[tuple[str, int, int, int] | None]):
    """Direction, lattice joint, mobile id, substrate id."""

    BINDINGS = [Binding("escape", "cancel", "Cancel")]

    def __init__(self, ids: list[int]) -> None:
        super().__init__()
        self.ids = ids

    def compose(self) -> ComposeResult:
        choices = [(f"{i:02d}", i) for i in self.ids]
        with Vertical(classes="dialog"):
            yield Label("Rotate the mobile module about a lattice joint (Table 3-1 timings)")
            with Horizontal(classes="form-row"):
                yield Label("direction", classes="form-label")
                yield Select([(f"CW ({lookup('CW').code})", "cw"),
                              (f"CCW ({lookup('CCW').code})", "ccw")], value="cw",
                             allow_blank=False, id="rot-dir")
            with Horizontal(classes="form-row"):
                yield Label("joint 1..6", classes="form-label")
                yield Input("1", id="rot-joint", type="integer")
            with Horizontal(classes="form-row"):
                yield Label("mobile", classes="form-label")
                yield Select(choices, id="rot-mobile")
            with Horizontal(classes="form-row"):
                yield Label("substrate", classes="form-label")
                yield Select(choices, id="rot-substrate")
            yield Label("", id="rot-error", classes="error")
            yield Button("Rotate", id="rot-go", variant="primary")

    @on(Input.Changed, "#rot-joint")
    @on(Select.Changed)
    def _clear_error(self) -> None:
        """A value changed: the last complaint may no longer hold."""
        self.query_one("#rot-error", Label).update("")

    @on(Button.Pressed, "#rot-go")
    def _go(self) -> None:
        joint = self.query_one("#rot-joint", Input).value.strip()
        mobile = self.query_one("#rot-mobile", Select).value
        substrate = self.query_one("#rot-substrate", Select).value
        error = self.query_one("#rot-error", Label)
        if not joint.isdigit() or not 1 <= int(joint) <= 6:
            error.update("joint must be 1..6")
            return
        if not isinstance(mobile, int) or not isinstance(substrate, int) or mobile == substrate:
            error.update("pick two different modules")
            return
        self.dismiss((str(self.query_one("#rot-dir", Select).value), int(joint), mobile,
                      substrate))

    def action_cancel(self) -> None:
        self.dismiss(None)


#: Moves listed in the plan dialog (a plan of 63 modules can have hundreds).
PLAN_PREVIEW = 12


class PlanScreen(ModalScreen[bool]):
    """A plan to execute or discard: its summary line (size, lower bounds),
    why a fallback method planned, and its first moves."""

    BINDINGS = [Binding("e", "execute", "Execute"), Binding("escape", "discard", "Discard")]

    def __init__(self, plan) -> None:  # a hexbot.planning.plan.Plan
        super().__init__()
        self.plan = plan

    def compose(self) -> ComposeResult:
        from hexbot.planning.cli_plan import plan_summary

        plan = self.plan
        moves = [(t, m) for t, step in enumerate(plan.steps, start=1) for m in step.moves]
        lines = [f"step {t}: module {m.module} {m.src} -> {m.dst}, joint {m.joint} "
                 f"{m.direction} on module {m.substrate_module}"
                 for t, m in moves[:PLAN_PREVIEW]]
        if len(moves) > PLAN_PREVIEW:
            lines.append(f"... and {len(moves) - PLAN_PREVIEW} more moves")
        with Vertical(classes="dialog", id="plan-box"):
            yield Label(plan_summary(plan), id="plan-summary")
            for reason in plan.tried:
                yield Label(f"tried first, no plan: {reason}", classes="hint")
            yield Label("\n".join(lines), id="plan-moves")
            with Horizontal(classes="form-row"):
                yield Button("Execute", id="plan-go", variant="primary")
                yield Button("Discard", id="plan-discard")
            yield Label("e executes (each move verified; escape then cancels), "
                        "escape discards", classes="hint")

    @on(Button.Pressed, "#plan-go")
    def action_execute(self) -> None:
        self.dismiss(True)

    @on(Button.Pressed, "#plan-discard")
    def action_discard(self) -> None:
        self.dismiss(False)
