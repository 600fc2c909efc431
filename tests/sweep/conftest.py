"""Fixtures of the sweep tests: Dask clusters (embedded, and as separate processes)
and small sweep files written into the test's own folder."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import NamedTuple

import pytest

DASK = Path(sys.executable).with_name("dask")


@pytest.fixture(scope="session")
def embedded_client():
    """A client on an embedded LocalCluster of two worker processes (what
    ``hexbot sweep`` starts by default), shared by the tests of one process."""
    from hexbot.sweep.engine import connect

    with connect(workers=2) as client:
        yield client


ROOT = Path(__file__).resolve().parents[2]


def _start(argv: list[str], log: Path) -> subprocess.Popen:
    # the repository on the path, so workers import the tests' own task functions
    path = os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")]))
    return subprocess.Popen(argv, stdout=log.open("w"), stderr=subprocess.STDOUT,
                            start_new_session=True, env={**os.environ, "PYTHONPATH": path})


def kill_group(proc: subprocess.Popen, sig: int = signal.SIGKILL) -> None:
    """Signal the process and its children (a dask worker's nanny starts one)."""
    try:
        os.killpg(proc.pid, sig)
    except ProcessLookupError:
        pass  # the whole group is gone already


def _stop(proc: subprocess.Popen) -> None:
    kill_group(proc, signal.SIGTERM)
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        kill_group(proc)
        proc.wait()
    kill_group(proc)  # a child the leader left behind


class DaskProcesses(NamedTuple):
    address: str
    workers: list[subprocess.Popen]
    scheduler: subprocess.Popen


def _dask_processes(tmp_path: Path, n_workers: int,
                    scheduler_args: tuple[str, ...] = ("--host", "127.0.0.1"),
                    ) -> Iterator[DaskProcesses]:
    info = tmp_path / "scheduler.json"
    procs = [_start([str(DASK), "scheduler", *scheduler_args, "--port", "0",
                     "--no-dashboard", "--scheduler-file", str(info)],
                    tmp_path / "scheduler.log")]
    try:
        deadline = time.monotonic() + 60
        while not info.exists() or not info.read_text().strip():
            assert procs[0].poll() is None, (tmp_path / "scheduler.log").read_text()
            assert time.monotonic() < deadline, "the scheduler wrote no address"
            time.sleep(0.1)
        address = json.loads(info.read_text())["address"]
        workers = [_start([str(DASK), "worker", address, "--nthreads", "1", "--no-dashboard",
                           "--host", "127.0.0.1", "--local-directory", str(tmp_path / f"w{i}"),
                           "--name", f"w{i}"], tmp_path / f"worker{i}.log")
                   for i in range(n_workers)]
        procs += workers
        if workers:
            from distributed import Client

            with Client(address, timeout="30s") as client:
                client.wait_for_workers(n_workers, timeout=60)
        yield DaskProcesses(address, workers, procs[0])
    finally:
        for proc in reversed(procs):
            _stop(proc)


@pytest.fixture
def dask_processes(tmp_path):
    """``dask scheduler`` and two ``dask worker`` processes on 127.0.0.1 (ports
    chosen by the OS); yields (scheduler address, worker processes, scheduler
    process); all killed after."""
    yield from _dask_processes(tmp_path, 2)


@pytest.fixture
def dask_scheduler_alone(tmp_path):
    """A ``dask scheduler`` process that no worker joins."""
    yield from _dask_processes(tmp_path, 0)


@pytest.fixture
def write_spec(tmp_path):
    """``write_spec(text, name="sweep.toml")``: a sweep file in the test's folder."""
    def write(text: str, name: str = "sweep.toml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path
    return write


@pytest.fixture
def tls_scheduler(tmp_path):
    """A ``dask scheduler`` that speaks TLS only (a self-signed certificate made
    with openssl); yields (address, certificate, key)."""
    cert, key = tmp_path / "cert.pem", tmp_path / "key.pem"
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1",
                    "-subj", "/CN=127.0.0.1", "-keyout", str(key), "-out", str(cert)],
                   check=True, capture_output=True)
    args = ("--host", "tls://127.0.0.1", "--tls-ca-file", str(cert), "--tls-cert", str(cert),
            "--tls-key", str(key))
    for processes in _dask_processes(tmp_path, 0, args):
        yield processes.address, cert, key
