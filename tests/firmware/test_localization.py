"""Localization of a whole cluster from one Localize (66): the reference
teaches its neighbours with MSG1, they teach theirs, and every module reports
its cell and orientation (Yref) relative to the reference."""

from __future__ import annotations

from fwsim import Bench, scenario_file

from hexbot.hil_sim.geometry import neighbor
from hexbot.protocol import parser


def reports(events: list[parser.Event]) -> dict[int, dict]:
    """Per module id: the LOCALIZED report that precedes its ACK 66."""
    out: dict[int, dict] = {}
    current: dict = {}
    for e in events:
        if isinstance(e, parser.Text) and e.phrase == "LOCALIZED":
            current = {"localized": True}
        elif isinstance(e, parser.SideReport):
            current["side"] = e.side
        elif isinstance(e, parser.YrefReport):
            current["yref"] = e.yref
        elif isinstance(e, parser.PositionReport):
            current["pos"] = (e.x, e.y)
        elif isinstance(e, parser.Ack):
            assert e.code == 66, e
            out[e.module] = current
            current = {}
    return out


def check_cluster(bench: Bench, ref: int) -> None:
    sim = bench.sim
    rx, ry = sim.modules[ref].position
    replies = bench.command("Status")  # after Select(0): every module
    for sta in replies:
        module = sim.modules[sta.module_id]
        x, y = module.position
        assert sta.localized, sta
        assert (sta.x, sta.y) == (x - rx, y - ry), sta
        assert sta.yref == module.orientation, sta


def run_localization(bench: Bench, ref: int) -> dict[int, dict]:
    sim = bench.sim
    n = len(sim.modules)
    bench.command("Select", ref)
    bench.command("Ref")
    bench.command("Select", 0)
    bench.sim.events.clear()
    # Every module answers within the protocol's bound (rank id - 1), nothing after.
    assert len(bench.command("Localize", settle=1.0)) == n
    replies_heard = bench.events()  # what the PC heard since sending it
    assert not [e for e in replies_heard if isinstance(e, parser.Garbage)], replies_heard
    assert [e for e in sim.events if e["event"] == "ir-collision"] == []
    return reports(replies_heard)


def test_flower7_localizes_from_one_command(images):
    bench = Bench.boot("flower7")
    found = run_localization(bench, ref=1)
    assert sorted(found) == list(range(1, 8))
    assert found[1] == {}  # the reference only acknowledges
    for ident in range(2, 8):
        module = bench.sim.modules[ident]
        report = found[ident]
        assert report["pos"] == module.position
        assert report["yref"] == module.orientation
        # It heard a localized neighbour, through its own global side "side".
        teacher_cell = neighbor(module.position, report["side"])
        assert teacher_cell in bench.sim.positions().values()
    check_cluster(bench, ref=1)


def test_oriented_cluster_with_the_reference_on_the_rim(images, tmp_path):
    # A flower whose petals are turned every which way, plus a tail two hops out.
    cells = [(0, 0), (-1, 1), (0, 1), (1, 0), (1, -1), (0, -1), (-1, 0), (2, -1), (3, -1)]
    turns = [3, 0, 1, 5, 2, 4, 1, 3, 2]
    modules = [(i + 1, cell, o) for i, (cell, o) in enumerate(zip(cells, turns, strict=True))]
    bench = Bench.boot(scenario_file(tmp_path, modules, base=2))
    found = run_localization(bench, ref=2)  # (-1, 1), orientation 0: 3 hops to (3, -1)
    assert sorted(found) == list(range(1, 10))
    check_cluster(bench, ref=2)


def test_a_second_localize_keeps_positions(images):
    bench = Bench.boot("flower7")
    run_localization(bench, ref=1)
    again = bench.command("Localize")
    assert [(r.code, r.module) for r in again] == [(66, i) for i in range(1, 8)]
    check_cluster(bench, ref=1)
    # A mobile rotation moves the module: its position is no longer known.
    bench.command("Select", 3)
    bench.command("MCW", 2, 1, 1, 1)
    (sta,) = bench.command("Status")
    assert (sta.module_id, sta.localized) == (3, False)
