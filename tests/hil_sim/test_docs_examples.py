"""The Python examples of docs/simulator.md and of the plugin's docstring,
run as they are written: a user copies them first."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

pytest.importorskip("hexbot.hil_sim._avr")

DOC = Path(__file__).resolve().parents[2] / "docs" / "simulator.md"
FIRMWARE = Path(__file__).resolve().parents[2] / "firmware" / "build"
pytestmark = pytest.mark.skipif(not (FIRMWARE / "comm.elf").exists(),
                                reason="firmware not built (make -C firmware)")


def _blocks(text: str) -> list[str]:
    return re.findall(r"```python\n(.*?)```", text, re.S)


def test_the_quick_start_runs_as_written():
    (block,) = [b for b in _blocks(DOC.read_text()) if "Simulator.from_name" in b]
    namespace: dict = {}
    exec(compile(block, f"{DOC}:quick start", "exec"), namespace)
    sim = namespace["sim"]
    assert (sim.modules[2].position, sim.modules[2].orientation) == ((0, 1), 2)


def _doc_test(source: str, name: str):
    namespace: dict = {"pytest": pytest}
    exec(compile("from hexbot.protocol.frames import encode_pc, make\n" + source, name, "exec"),
         namespace)
    return next(v for k, v in namespace.items() if k.startswith("test_"))


@pytest.mark.hexbot_scenario("pair", seed=3)
def test_the_plugin_example_of_the_docs_runs_as_written(hexbot_sim):
    (block,) = [b for b in _blocks(DOC.read_text()) if "def test_status_replies" in b]
    _doc_test(block, f"{DOC}:pytest plugin")(hexbot_sim)


@pytest.mark.hexbot_scenario("pair", seed=3)
def test_the_plugin_docstring_example_runs_as_written(hexbot_sim):
    from hexbot.hil_sim import pytest_plugin

    doc = pytest_plugin.__doc__
    start = doc.index("    @pytest.mark.hexbot_scenario")
    block = doc[start:doc.index("\n\n", start)]
    source = "\n".join(line[4:] for line in block.splitlines())
    _doc_test(source, "pytest_plugin docstring")(hexbot_sim)
