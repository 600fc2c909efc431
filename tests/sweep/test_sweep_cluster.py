"""A small sweep on the embedded cluster, on a scheduler and two workers started
as separate processes, and in this process: the same rows everywhere."""

from __future__ import annotations

import pytest

from hexbot.cli import main
from hexbot.sweep.engine import execute, run_sweep
from hexbot.sweep.results import ResultStore, read_table
from hexbot.sweep.spec import load_spec
from tests.sweep.conftest import kill_group

SWEEP = """\
kind = "locomotion"
[grid]
ruleset = ["salvador", "otero"]
n = [5, 8]
seed = { start = 0, stop = 2 }
round_limit = 600
"""
TIMING = ("seconds",)  # the one column that may differ between runs


def rows_of(folder) -> dict[str, dict]:
    table = read_table(folder)
    assert table is not None
    return {r["task"]: {k: v for k, v in r.items() if k not in TIMING}
            for r in table.to_pylist()}


def test_embedded_and_separate_processes_give_the_same_rows(write_spec, tmp_path,
                                                            dask_processes, capsys):
    spec_path = write_spec(SWEEP)
    address = dask_processes.address
    assert main(["sweep", str(spec_path), "--out", str(tmp_path / "local"),
                 "--workers", "2", "--no-progress"]) == 0
    assert main(["sweep", str(spec_path), "--out", str(tmp_path / "remote"),
                 "--scheduler", address, "--no-progress"]) == 0
    local, remote = rows_of(tmp_path / "local"), rows_of(tmp_path / "remote")
    assert len(local) == 8 and local == remote
    assert {r["result"] for r in local.values()} <= {"reached", "deadlock", "rounds-exhausted"}
    assert all(r["outcome"] == "ok" for r in local.values())
    # a task is pure: run here, in this process, it gives the same figures
    spec = load_spec(spec_path)
    for task in spec.tasks()[:2]:
        here = execute(spec.kind.target, task.call)
        del here["seconds"]
        there = local[task.id]
        assert {k: there[k] for k in here} == here


def test_a_lost_worker_keeps_every_row_and_the_sweep_completes(write_spec, tmp_path,
                                                               dask_processes):
    from distributed import Client

    address, workers, _ = dask_processes
    spec = load_spec(write_spec(SWEEP))
    seen = []

    def kill_one_worker_after_the_first_row(outcome: str) -> None:
        seen.append(outcome)
        if len(seen) == 1:
            kill_group(workers[0])  # nanny and worker: its tasks move to the other one

    with ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store, \
            Client(address, timeout="30s") as client:
        outcome = run_sweep(spec, client, store, on_result=kill_one_worker_after_the_first_row)
    assert workers[0].wait(10) is not None
    assert outcome.stored == 8 and outcome.lost == 0
    assert len(rows_of(tmp_path / "out")) == 8


def test_an_unreachable_scheduler_is_exit_4_and_says_why(write_spec, tmp_path, capsys,
                                                        monkeypatch):
    """A port nobody listens on was said to accept connections and stay silent:
    Dask's connect and the deadline around it ended at the same moment, and
    the deadline won."""
    import socket

    from hexbot.sweep import engine

    monkeypatch.setattr(engine, "CONNECT_SECONDS", 1.0)
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    code = main(["sweep", str(write_spec(SWEEP)), "--out", str(tmp_path / "o"),
                 "--scheduler", f"tcp://127.0.0.1:{port}", "--no-progress"])
    err = capsys.readouterr().err
    assert code == 4
    assert (f"cannot reach the Dask scheduler tcp://127.0.0.1:{port}: Timed out trying to "
            f"connect to tcp://127.0.0.1:{port} after 0.8 s") in err
    assert "accepts connections" not in err
    # why, unless Dask's last attempt was cut by its clock (a loaded machine)
    assert "(ConnectionRefusedError: [Errno 111] Connection refused)" in err or (
        err.endswith("after 0.8 s\n")), err


def test_a_port_that_speaks_another_protocol_is_named_so(write_spec, tmp_path, capsys):
    """An SSH server's greeting read as a Dask frame said only 'MemoryError:
    Unable to allocate 2.82 EiB ...'."""
    import socket
    import threading

    with socket.socket() as server:
        server.bind(("127.0.0.1", 0))
        server.listen()

        def greet() -> None:
            conn, _ = server.accept()
            with conn:
                conn.sendall(b"SSH-2.0-OpenSSH_9.2p1 Debian-2\r\n")
                conn.recv(1)  # until the client hangs up

        threading.Thread(target=greet, daemon=True).start()
        code = main(["sweep", str(write_spec(SWEEP)), "--out", str(tmp_path / "o"),
                     "--scheduler", f"tcp://127.0.0.1:{server.getsockname()[1]}",
                     "--no-progress"])
    assert code == 4
    err = capsys.readouterr().err
    assert "something answers there, but not as a Dask scheduler (" in err
    assert "Unable to allocate" not in err  # not this machine's memory


@pytest.mark.parametrize("resume", [False, True])
def test_an_existing_results_folder_needs_resume(write_spec, tmp_path, embedded_client, resume):
    spec = load_spec(write_spec(SWEEP))
    with ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store:
        run_sweep(spec, embedded_client, store)
    with ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store:
        if resume:
            again = run_sweep(spec, embedded_client, store, resume=True)
            assert (again.skipped, again.stored) == (8, 0)
        else:
            from hexbot.errors import HexBotError

            with pytest.raises(HexBotError, match="already holds 8 rows: --resume"):
                run_sweep(spec, embedded_client, store)


@pytest.mark.parametrize(("address", "words"), [
    ("foo://x", "unknown scheme 'foo'"), ("tcp://127.0.0.1", "missing port number")])
def test_a_malformed_scheduler_address_is_a_usage_error(write_spec, tmp_path, capsys,
                                                        address, words):
    with pytest.raises(SystemExit) as exit_:
        main(["sweep", str(write_spec(SWEEP)), "--out", str(tmp_path / "o"),
              "--scheduler", address])
    assert exit_.value.code == 2
    assert words in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_a_scheduler_lost_mid_sweep_is_exit_4_and_keeps_the_rows_taken_back(
        write_spec, tmp_path, dask_processes):
    """Dask cancels every future when its scheduler goes; the sweep used to wait
    for them for ever."""
    from distributed import Client

    from hexbot.errors import LinkUnavailableError

    spec = load_spec(write_spec('kind = "tests.sweep.sample_tasks:slow_echo"\n'
                                '[grid]\nseed = { start = 0, stop = 12 }\n'))
    seen = []

    def kill_the_scheduler_after_the_first_row(outcome: str) -> None:
        seen.append(outcome)
        if len(seen) == 1:
            kill_group(dask_processes.scheduler)

    with ResultStore(tmp_path / "out", spec.kind.name, spec.param_names) as store, \
            Client(dask_processes.address, timeout="5s") as client, \
            pytest.raises(LinkUnavailableError, match="lost the Dask scheduler .* mid-sweep"):
        run_sweep(spec, client, store, on_result=kill_the_scheduler_after_the_first_row)
    assert 1 <= len(rows_of(tmp_path / "out")) < 12
    assert seen[0] == "ok" and "lost" not in seen  # no task counted lost or retried


def test_a_port_that_never_answers_is_exit_4_not_a_hang(write_spec, tmp_path, capsys,
                                                        monkeypatch):
    import socket

    from hexbot.sweep import engine

    monkeypatch.setattr(engine, "CONNECT_SECONDS", 1.0)
    with socket.socket() as silent:  # accepts (the kernel's backlog) and never writes
        silent.bind(("127.0.0.1", 0))
        silent.listen()
        code = main(["sweep", str(write_spec(SWEEP)), "--out", str(tmp_path / "o"),
                     "--scheduler", f"tcp://127.0.0.1:{silent.getsockname()[1]}",
                     "--no-progress"])
    assert code == 4
    assert "did not answer as a scheduler in 1 s" in capsys.readouterr().err


def test_a_scheduler_without_workers_says_so_and_gives_up(write_spec, tmp_path, capsys,
                                                          monkeypatch, dask_scheduler_alone):
    from hexbot.sweep import engine

    monkeypatch.setattr(engine, "WORKER_WAIT_SECONDS", 1.0)
    address = dask_scheduler_alone.address
    code = main(["sweep", str(write_spec(SWEEP)), "--out", str(tmp_path / "o"),
                 "--scheduler", address, "--no-progress"])
    err = capsys.readouterr().err
    assert code == 4
    assert f"{address} has no worker yet: waiting up to 1 s" in err
    assert f"no worker joined the Dask scheduler {address} in 1 s" in err


def test_a_tls_scheduler_is_reached_with_the_clients_own_certificates(tls_scheduler):
    """The handshake probe opened its comm without Dask's TLS settings, so a
    tls:// scheduler could never be reached (TypeError: no ssl_context)."""
    import dask

    from hexbot.sweep import engine

    address, cert, key = tls_scheduler
    assert address.startswith("tls://")
    tls = {"distributed.comm.tls.ca-file": str(cert),
           "distributed.comm.tls.client.cert": str(cert),
           "distributed.comm.tls.client.key": str(key)}
    with dask.config.set(tls):
        engine._hear_handshake(address)  # raises LinkUnavailableError when it cannot


def test_the_handshake_probe_works_inside_a_running_event_loop(dask_scheduler_alone,
                                                               monkeypatch):
    """asyncio.run refuses to start inside a running loop (a notebook, an async
    caller): the probe said it could not reach a scheduler that was there."""
    import asyncio
    import socket

    from hexbot.errors import LinkUnavailableError
    from hexbot.sweep import engine

    monkeypatch.setattr(engine, "CONNECT_SECONDS", 1.0)

    async def probe_from_a_coroutine() -> None:
        engine._hear_handshake(dask_scheduler_alone.address)  # raises when it cannot
        with socket.socket() as silent:  # its failure still reaches the caller
            silent.bind(("127.0.0.1", 0))
            silent.listen()
            address = f"tcp://127.0.0.1:{silent.getsockname()[1]}"
            with pytest.raises(LinkUnavailableError, match="did not answer as a scheduler"):
                engine._hear_handshake(address)

    asyncio.run(probe_from_a_coroutine())


@pytest.mark.parametrize("fails_in", ["LocalCluster", "Client"])
def test_ctrl_c_is_restored_whenever_the_embedded_cluster_fails_to_start(monkeypatch,
                                                                         fails_in):
    """SIGINT is ignored while the workers start; a cluster that failed on
    entering left it ignored for the rest of the process."""
    import signal

    import distributed

    from hexbot.sweep import engine

    closed = []

    class Cluster:  # a unit-test double of LocalCluster that fails where asked
        workers: dict = {}

        def __init__(self, **_options):
            if fails_in == "LocalCluster":
                raise RuntimeError("no cluster")

        def close(self, timeout=None):
            closed.append(timeout)

    def client(_cluster):
        raise RuntimeError("no cluster")

    monkeypatch.setattr(distributed, "LocalCluster", Cluster)
    monkeypatch.setattr(distributed, "Client", client)
    before = signal.getsignal(signal.SIGINT)
    with pytest.raises(RuntimeError, match="no cluster"), engine.connect(workers=1):
        pass
    assert closed == ([] if fails_in == "LocalCluster" else [engine.CLOSE_SECONDS])
    assert signal.getsignal(signal.SIGINT) is before
