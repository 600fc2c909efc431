"""The hexbot_sim plugin as a user meets it: a test file in another directory."""

import subprocess
import sys

USER_TEST = '''
import pytest

@pytest.mark.hexbot_scenario("pair", seed=5)
def test_marked(hexbot_sim):
    assert hexbot_sim.seed == 5 and sorted(hexbot_sim.modules) == [1, 2]
    hexbot_sim.expect(b"COMM. LISTENING", timeout=10)

def test_default_scenario(hexbot_sim):
    assert sorted(hexbot_sim.modules) == [1]

def test_factory(hexbot_sim_factory):
    a, b = hexbot_sim_factory("single"), hexbot_sim_factory("single", seed=9)
    a.run(1.0)
    assert a.time == 1.0 and b.time == 0.0 and b.seed == 9

@pytest.mark.hexbot_scenario("pair", seed=5)
def test_session(hexbot_session):
    from hexbot.host.session import select
    from hexbot.protocol.frames import make
    from hexbot.protocol.parser import StatusReport

    assert hexbot_session.cluster == {1, 2}  # both booted
    hexbot_session.request(select(2))
    outcome = hexbot_session.request(make("Status"))
    (reply,) = outcome.replies
    assert isinstance(reply.event, StatusReport)
    assert (reply.event.module_id, reply.event.localized) == (2, False)
    assert hexbot_session.host.simulator.simulator.time < 30  # virtual time

@pytest.mark.hexbot_scenario("blob:10", seed=1)
def test_session_of_ten(hexbot_session):
    # ids 1 and 9, 2 and 10 share a boot slot: their texts collide, and the
    # fixture refused the cluster ("modules [1, 2, 9, 10] did not boot")
    assert hexbot_session.cluster == set(range(1, 11))
'''


def test_plugin_fixtures_marker_and_events_dir(tmp_path):
    (tmp_path / "test_user.py").write_text(USER_TEST)
    events = tmp_path / "events"
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(tmp_path),
         "--hexbot-events-dir", str(events)],
        capture_output=True, text=True, cwd=tmp_path, timeout=120,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    assert "5 passed" in result.stdout
    saved = sorted(p.name for p in events.iterdir())
    assert saved == [
        "test_user.py_test_default_scenario.jsonl",
        "test_user.py_test_factory-1.jsonl",
        "test_user.py_test_factory.jsonl",
        "test_user.py_test_marked.jsonl",
        "test_user.py_test_session.jsonl",
        "test_user.py_test_session_of_ten.jsonl",
    ]
    assert "ir-collision" in (events / "test_user.py_test_marked.jsonl").read_text()
    assert (events / "test_user.py_test_session.jsonl").read_text()
