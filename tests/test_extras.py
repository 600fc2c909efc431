"""Optional extras: without them, the commands that need them say what to install."""

import sys

import pytest

from hexbot.cli import main
from hexbot.errors import HexBotError, MissingExtraError
from hexbot.extras import require


def test_require_returns_the_module():
    assert require("json", "plot", "x").dumps([1]) == "[1]"


def test_missing_module_names_the_extra_and_keeps_the_cause(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(MissingExtraError, match=r"drawing needs matplotlib.*hexbot\[plot\]") as e:
        require("matplotlib", "plot", "drawing")
    assert isinstance(e.value, HexBotError) and isinstance(e.value.__cause__, ImportError)


def test_plan_plot_without_matplotlib(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.delitem(sys.modules, "hexbot.planning.plot", raising=False)
    with pytest.raises(MissingExtraError, match=r"pip install 'hexbot\[plot\]'"):
        import hexbot.planning.plot  # noqa: F401


def test_locomotion_render_without_pillow(monkeypatch, capsys, tmp_path):
    monkeypatch.setitem(sys.modules, "PIL.Image", None)
    code = main(["locomotion", "run", "salvador-free", "flat", "--n", "5", "--rounds", "3",
                 "--render", str(tmp_path / "run.gif")])
    err = capsys.readouterr().err
    assert code == 1
    assert "--render (PNG, GIF) needs PIL" in err and "pip install 'hexbot[plot]'" in err
