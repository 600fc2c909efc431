"""Threads: the MCUs of a quantum run on several host threads (cluster_pool.c)
and give the same trace as on one: byte-identical VCD, event log and PC
transcript, and the same bytes and pin changes on the C core's wires.

The clusters here are small, so the tests set ``min_mcus_per_thread = 1``:
every thread asked for takes part in every quantum (by default a thread
needs 32 MCUs of its own)."""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
import threading
from dataclasses import replace
from pathlib import Path

import pytest

from hexbot.errors import HexBotError, ScenarioError
from hexbot.hil_sim._avr import Cluster
from hexbot.hil_sim.scenario import load_scenario, parse_scenario
from hexbot.hil_sim.scenario_gen import generate
from hexbot.hil_sim.simulator import Simulator
from hexbot.hil_sim.vcd import VcdWriter
from hexbot.protocol.frames import encode_pc, make, select
from hexbot.protocol.timing import boot_seconds

AVR_DIR = Path(__file__).parent / "avr"


def build(name: str) -> str:
    target = f"build/{name}.atmega162.elf"
    subprocess.run(["make", "-s", "-C", str(AVR_DIR), target], check=True)
    return str(AVR_DIR / target)


def recorded(scenario, threads: int, localize: bool = False, idle_s: float = 1.0,
             min_per_thread: int = 1):
    """(VCD text, event log as JSON lines, PC transcript) of booting the
    scenario, optionally localizing it from module 1, then idling."""
    sim = Simulator(scenario, threads=threads)
    assert sim.cluster.threads == threads
    sim.cluster.min_mcus_per_thread = min_per_thread
    log = io.StringIO()
    sim.event_sinks.append(lambda e: log.write(json.dumps(e) + "\n"))
    vcd_text = io.StringIO()
    vcd = VcdWriter(sim, vcd_text)
    ids = sorted(sim.modules)
    sim.run(boot_seconds(ids))
    pc = bytearray()
    if localize:
        sim.pc_write(encode_pc(select([1])))
        pc += sim.expect(b"M01: ACKE", timeout=10.0)
        sim.pc_write(encode_pc(make("Ref")))
        pc += sim.expect(b"S01: ACKA", timeout=10.0)
        sim.pc_write(encode_pc(select([0])))
        sim.run(1.0)
        sim.pc_write(encode_pc(make("Localize")))

        def all_reported(s: Simulator) -> bool:
            pc.extend(s.pc_read())
            return pc.count(b"ACKB") == len(ids)  # every module acknowledged Localize

        sim.run_until(all_reported, timeout=120.0)
    sim.run(idle_s)
    pc += sim.pc_read()
    vcd.close()
    return vcd_text.getvalue(), log.getvalue(), bytes(pc)


def test_flower7_boot_and_localization_are_byte_identical_on_1_2_and_3_threads():
    one = recorded(load_scenario("flower7"), threads=1, localize=True)
    vcd, events, pc = one
    # a trace worth comparing: selector and actuator changes, medium events,
    # every module's report
    assert vcd.count("\n#") > 100
    assert events.count("\n") > 10
    assert pc.count(b"LOCALIZED") == 6  # all but the reference
    for threads in (2, 3):
        assert recorded(load_scenario("flower7"), threads=threads, localize=True) == one


def test_generated_blob_on_spread_clocks_is_byte_identical_on_1_and_2_threads():
    blob = replace(generate("blob", 20, seed=5), clock_spread_ppm=20_000)
    one = recorded(blob, threads=1, idle_s=2.0)
    assert one[0].count("\n#") > 100
    assert recorded(blob, threads=2, idle_s=2.0) == one
    assert recorded(blob, threads=4, idle_s=2.0) == one
    # the default share: 40 MCUs give one thread 32, so 2 of the 4 run
    assert recorded(blob, threads=4, idle_s=2.0, min_per_thread=32) == one


def ping_pong(threads: int, pairs: int = 3):
    """pinger/echo pairs on wires: every byte and pin change, per MCU."""
    c = Cluster(700, threads=threads)
    c.min_mcus_per_thread = 1
    mcus = []
    for i in range(pairs):
        p = c.add_mcu(build("pinger"), f"pinger{i}")
        e = c.add_mcu(build("echo"), f"echo{i}")
        c.connect_uart(p, 0, e, 0)
        c.watch_uart(p, 0)
        c.watch_uart(e, 0)
        mcus += [p, e]
    sent: dict[int, list] = {m: [] for m in mcus}
    while c.run(150_000) < 150_000:
        for m in mcus:
            sent[m] += c.uart_take(m, 0)
    return [(sent[m] + c.uart_take(m, 0), c.pin_log(m), c.mcu_cycle(m)) for m in mcus]


def test_wired_mcus_exchange_the_same_bytes_on_any_number_of_threads():
    one = ping_pong(threads=1)
    assert all(len(tx) >= 10 for tx, _, _ in one)  # every MCU talked
    assert ping_pong(threads=2) == one
    assert ping_pong(threads=5) == one


def test_more_threads_than_mcus_run_every_mcu():
    one = ping_pong(threads=1, pairs=1)
    assert ping_pong(threads=16, pairs=1) == one
    single = load_scenario("single")
    assert recorded(single, threads=8, idle_s=0.5) == recorded(single, threads=1, idle_s=0.5)


def test_thread_count_can_change_between_runs_without_changing_the_trace():
    def pair(cluster: Cluster) -> tuple[int, int]:
        p = cluster.add_mcu(build("pinger"), "pinger")
        e = cluster.add_mcu(build("echo"), "echo")
        cluster.connect_uart(p, 0, e, 0)
        cluster.watch_uart(p, 0)
        return p, e

    c = Cluster(1000, threads=1)
    c.min_mcus_per_thread = 1
    p, e = pair(c)
    for step, threads in enumerate((1, 3, 2, 1), start=1):
        c.threads = threads
        while c.run(step * 25_000) < step * 25_000:
            pass
    ref = Cluster(1000)
    p2, e2 = pair(ref)
    while ref.run(100_000) < 100_000:
        pass
    want = ref.uart_take(p2, 0), ref.pin_log(p2), ref.pin_log(e2)
    assert len(want[0]) >= 5
    assert (c.uart_take(p, 0), c.pin_log(p), c.pin_log(e)) == want


def test_run_releases_the_gil_and_the_cluster_refuses_other_threads_meanwhile():
    """Another Python thread runs during run() (the GIL is released) and finds
    the cluster busy instead of racing the C state."""
    c = Cluster(1000, threads=2)
    c.min_mcus_per_thread = 1
    for i in range(8):
        c.add_mcu(build("cpuloop"), f"busy{i}")
    seen: list[str] = []
    done = threading.Event()

    def poke() -> None:
        while not done.is_set() and not seen:
            try:
                c.pin_log(0)
            except RuntimeError as exc:
                seen.append(str(exc))

    other = threading.Thread(target=poke)
    other.start()
    until = 0
    try:
        while not seen and until < 40_000_000:  # 20 runs: far more than needed
            until += 2_000_000
            c.run(until)
    finally:
        done.set()
        other.join()
    assert seen and "running in another thread" in seen[0]
    assert c.cycle == until  # the cluster itself went on undisturbed


def test_thread_count_errors_are_clear(tmp_path):
    with pytest.raises(ValueError, match="threads must be 1..256"):
        Cluster(1000, threads=0)
    with pytest.raises(ValueError, match="min_mcus_per_thread must be >= 1"):
        Cluster(1000).min_mcus_per_thread = 0
    with pytest.raises(HexBotError, match="threads must be 1..256, not 0"):
        Simulator(load_scenario("single"), threads=0)
    text = 'name = "t"\nthreads = 0\n[[module]]\nid = 1\nposition = [0, 0]\n'
    with pytest.raises(ScenarioError, match=r"t.toml:2: threads must be a whole number 1..256"):
        parse_scenario(text, tmp_path / "t.toml")
    assert parse_scenario(text.replace("= 0", "= 3"), tmp_path / "t.toml").threads == 3


def test_cli_runs_a_scenario_on_two_threads_with_the_same_files(tmp_path):
    # 32 modules: 64 MCUs, two threads at the default 32 MCUs per thread
    outputs = []
    for threads in ("1", "2"):
        vcd, events = tmp_path / f"{threads}.vcd", tmp_path / f"{threads}.jsonl"
        subprocess.run([sys.executable, "-m", "hexbot.cli", "sim", "line:32:2", "--duration",
                        "12", "--speed", "0", "--threads", threads, "--vcd", str(vcd),
                        "--events", str(events)], check=True, capture_output=True)
        outputs.append((vcd.read_bytes(), events.read_bytes()))
    assert outputs[0] == outputs[1]
    assert outputs[0][0].count(b"\n#") > 50
    bad = subprocess.run([sys.executable, "-m", "hexbot.cli", "sim", "single", "--duration",
                          "1", "--threads", "0"], capture_output=True, text=True)
    assert bad.returncode != 0
    assert "threads must be 1..256" in bad.stderr


def test_runner_without_python_prints_the_same_trace_on_three_threads():
    tools = Path(__file__).resolve().parents[2] / "hil_sim" / "core" / "tools"
    subprocess.run(["make", "-s", "-C", str(tools), "m162run"], check=True)
    images = [build("echo"), build("pinger"), build("tick"), build("echo"), build("pinger")]

    def trace(threads: str) -> str:
        return subprocess.run([str(tools / "m162run"), "-c", "80000", "-j", threads, "-m", "1",
                               "-w", *images], check=True, capture_output=True,
                              text=True).stdout

    one = trace("1")
    assert one.count(" uart0 ") >= 20
    assert trace("3") == one


def test_a_forked_child_runs_its_copy_of_a_threaded_cluster():
    """After fork() the workers stay in the parent: the child's cluster starts
    threads of its own (the pool's lock may have been copied held) and frees
    its copy without touching the parent's."""

    def start() -> tuple[Cluster, int, int]:
        c = Cluster(700, threads=3)
        c.min_mcus_per_thread = 1
        p = c.add_mcu(build("pinger"), "pinger")
        e = c.add_mcu(build("echo"), "echo")
        c.connect_uart(p, 0, e, 0)
        c.watch_uart(p, 0)
        return c, p, e

    def finish(c: Cluster, p: int, e: int) -> str:
        sent = []
        while c.run(120_000) < 120_000:
            sent += c.uart_take(p, 0)
        return repr((sent + c.uart_take(p, 0), c.pin_log(p), c.pin_log(e)))

    c, p, e = start()
    while c.run(30_000) < 30_000:  # the workers have run before the fork
        pass
    read_end, write_end = os.pipe()
    child = os.fork()
    if child == 0:  # pragma: no cover - runs in the child
        try:
            os.write(write_end, finish(c, p, e).encode())
            tasks = len(os.listdir("/proc/self/task"))  # this thread + the new workers
            del c  # frees the cluster: must not wait for the parent's workers
            os.write(write_end, f"|{tasks}|freed".encode())
        finally:
            os._exit(0)
    os.close(write_end)
    with os.fdopen(read_end, "rb") as pipe:
        from_child = pipe.read().decode()  # until the child exits (or hangs)
    _, status = os.waitpid(child, 0)
    assert status == 0
    from_child, tasks, freed = from_child.split("|")
    assert (tasks, freed) == ("3", "freed")  # the child ran on 3 threads of its own
    here = finish(c, p, e)
    assert from_child == here
    assert here.count("'B'") >= 5  # the echo's pin changes are in it
