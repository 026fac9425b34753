"""Bus performance: in-process and cross-process, against plain baselines in the same run.

In-process: publish -> callback latency (p50/p99) and throughput on a threaded
``Bus``, beside a bare ``queue.SimpleQueue`` hand-off to a thread (the least
any threaded delivery can cost). Cross-process: the same through a core over
Zenoh (one-way latency = ping-pong round trip / 2), beside raw eclipse-zenoh
pub/sub with the same payload bytes, plus a loss check at a paced 10k msgs/s.

Payloads: ``geometry_msgs/Twist`` (48 bytes) and a 1 kB ``std_msgs/String``.

Run: ``python benchmarks/bus.py [--quick]``; prints a table and writes
``benchmarks/results/bus.json``.
"""

from __future__ import annotations

import argparse
import json
import queue
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

from machine import describe  # noqa: E402

SEED = 0
HERE = Path(__file__).resolve().parent


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


def payloads() -> dict:
    import random

    from workbench.msgs.geometry_msgs import Twist, Vector3
    from workbench.msgs.std_msgs import String

    rng = random.Random(SEED)
    text = "".join(rng.choice("abcdefghijklmnopqrstuvwxyz") for _ in range(1020))
    return {
        "Twist": Twist(linear=Vector3(x=0.5), angular=Vector3(z=1.8)),
        "String 1kB": String(data=text),
    }


# --- in-process ------------------------------------------------------------------------


def inproc_workbench(msg, n: int, inline: bool = False) -> dict:
    from workbench.bus import Bus, Node

    with Bus() as bus:
        a, b = Node("a", bus=bus), Node("b", bus=bus)
        cls = type(msg)
        got = threading.Event()
        stamp = [0]
        lat: list[float] = []

        def on_ping(_m):
            lat.append((time.perf_counter_ns() - stamp[0]) / 1e3)
            got.set()

        b.create_subscription("ping", cls, on_ping, queue_size=1, inline=inline)
        ping = a.create_publisher("ping", cls)
        for _ in range(n):
            got.clear()
            stamp[0] = time.perf_counter_ns()
            ping.publish(msg)
            got.wait(1.0)
        count = [0]
        done = threading.Event()
        total = n * 20

        def on_flood(_m):
            count[0] += 1
            if count[0] == total:
                done.set()

        b.create_subscription("flood", cls, on_flood, queue_size=0, inline=inline)
        flood = a.create_publisher("flood", cls)
        start = time.perf_counter()
        for _ in range(total):
            flood.publish(msg)
        done.wait(60)
        elapsed = time.perf_counter() - start
    return _row(lat, count[0] / elapsed, 0)


def inproc_queue(msg, n: int) -> dict:
    q_ping: queue.SimpleQueue = queue.SimpleQueue()
    got = threading.Event()
    stamp = [0]
    lat: list[float] = []
    count = [0]
    done = threading.Event()
    total = n * 20

    def worker():
        while True:
            item = q_ping.get()
            if item is None:
                return
            if item == "ping":
                lat.append((time.perf_counter_ns() - stamp[0]) / 1e3)
                got.set()
            else:
                count[0] += 1
                if count[0] == total:
                    done.set()

    thread = threading.Thread(target=worker, daemon=True)
    thread.start()
    for _ in range(n):
        got.clear()
        stamp[0] = time.perf_counter_ns()
        q_ping.put("ping")
        got.wait(1.0)
    start = time.perf_counter()
    for _ in range(total):
        q_ping.put(msg)
    done.wait(60)
    elapsed = time.perf_counter() - start
    q_ping.put(None)
    return _row(lat, count[0] / elapsed, 0)


def _row(lat: list[float], rate: float, lost: int | None) -> dict:
    return {
        "p50_us": round(percentile(lat, 0.5), 1) if lat else None,
        "p99_us": round(percentile(lat, 0.99), 1) if lat else None,
        "msgs_per_s": round(rate),
        "lost_at_10k": lost,
    }


# --- cross-process: the other side ----------------------------------------------------------


def serve_workbench(uri: str, type_name: str, inline: bool) -> None:
    """Echo /ping to /pong; count /flood and /paced and report on /report."""
    from workbench.bus import Bus, Node
    from workbench.msgs import get_type
    from workbench.msgs.std_msgs import Int64

    cls = get_type(type_name)
    with Bus.connect(uri) as bus:
        node = Node("echo", bus=bus)
        pong = node.create_publisher("pong", cls)
        report = node.create_publisher("report", Int64)
        count = [0]

        def bump(_m):
            count[0] += 1

        node.create_subscription("ping", cls, pong.publish, queue_size=0, inline=inline)
        node.create_subscription("flood", cls, bump, queue_size=0, inline=inline)
        stop = threading.Event()
        signal.signal(signal.SIGTERM, lambda *_: stop.set())
        print("ready", flush=True)
        while not stop.wait(0.05):
            report.publish(Int64(data=count[0]))


def serve_raw(uri: str) -> None:
    import zenoh

    from workbench.bus.zconfig import client_config

    session = zenoh.open(client_config(uri))
    pong = session.declare_publisher("raw/pong", congestion_control=zenoh.CongestionControl.BLOCK)
    report = session.declare_publisher("raw/report")
    count = [0]

    def bump(_s):
        count[0] += 1

    callback = zenoh.handlers.Callback
    session.declare_subscriber("raw/ping", callback(lambda s: pong.put(s.payload), indirect=False))
    session.declare_subscriber("raw/flood", callback(bump, indirect=False))
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    print("ready", flush=True)
    while not stop.wait(0.05):
        report.put(str(count[0]))
    session.close()


# --- cross-process: this side ------------------------------------------------------------------


class _Counter:
    def __init__(self) -> None:
        self.value = 0
        self.changed = threading.Condition()

    def set(self, value: int) -> None:
        with self.changed:
            self.value = value
            self.changed.notify_all()

    def wait_for(self, target: int, timeout: float) -> int:
        deadline = time.monotonic() + timeout
        with self.changed:
            while self.value < target and time.monotonic() < deadline:
                self.changed.wait(0.1)
            return self.value


def _cross(n: int, send, pong_event: threading.Event, counter: _Counter, flood) -> dict:
    lat: list[float] = []
    for _ in range(n):
        pong_event.clear()
        start = time.perf_counter_ns()
        send()
        if pong_event.wait(2.0):
            lat.append((time.perf_counter_ns() - start) / 2e3)
    base = counter.wait_for(0, 1.0)
    total = n * 10
    start = time.perf_counter()
    for _ in range(total):
        flood()
    received = counter.wait_for(base + total, 30.0) - base
    rate = received / (time.perf_counter() - start)
    # paced 10k msgs/s for a moment: nothing may be lost
    base = counter.wait_for(0, 0.1)
    base = counter.value
    paced = max(2000, n * 4)
    t0 = time.perf_counter()
    for i in range(paced):
        while time.perf_counter() < t0 + i / 10_000:
            pass
        flood()
    lost = paced - (counter.wait_for(base + paced, 30.0) - base)
    return _row(lat, rate, lost)


def cross_workbench(uri: str, msg, n: int, inline: bool) -> dict:
    from workbench.bus import Bus, Node
    from workbench.msgs.std_msgs import Int64

    cls = type(msg)
    with Bus.connect(uri) as bus:
        node = Node("bench", bus=bus)
        pong_event = threading.Event()
        counter = _Counter()
        node.create_subscription(
            "pong", cls, lambda m: pong_event.set(), queue_size=0, inline=inline
        )
        node.create_subscription("report", Int64, lambda m: counter.set(m.data), queue_size=1)
        ping = node.create_publisher("ping", cls)
        flood = node.create_publisher("flood", cls)
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline and (
            ping.get_num_connections() < 1 or flood.get_num_connections() < 1
        ):
            time.sleep(0.05)
        time.sleep(0.3)
        return _cross(n, lambda: ping.publish(msg), pong_event, counter, lambda: flood.publish(msg))


def cross_raw(uri: str, msg, n: int) -> dict:
    import zenoh

    from workbench.bus.zconfig import client_config
    from workbench.msgs import serialize

    data = serialize(msg)
    session = zenoh.open(client_config(uri))
    pong_event = threading.Event()
    counter = _Counter()
    callback = zenoh.handlers.Callback
    subs = [
        session.declare_subscriber(
            "raw/pong", callback(lambda s: pong_event.set(), indirect=False)
        ),
        session.declare_subscriber(
            "raw/report",
            callback(lambda s: counter.set(int(s.payload.to_string())), indirect=False),
        ),
    ]
    block = zenoh.CongestionControl.BLOCK
    ping = session.declare_publisher("raw/ping", congestion_control=block)
    flood = session.declare_publisher("raw/flood", congestion_control=block)
    time.sleep(0.5)
    try:
        return _cross(n, lambda: ping.put(data), pong_event, counter, lambda: flood.put(data))
    finally:
        del subs
        session.close()


def _spawn(args: list[str]) -> subprocess.Popen:
    child = subprocess.Popen([sys.executable, __file__, *args], stdout=subprocess.PIPE, text=True)
    assert child.stdout is not None
    line = child.stdout.readline()
    if "ready" not in line:
        child.kill()
        raise RuntimeError(f"benchmark helper did not start: {line!r}")
    return child


def _stop(child: subprocess.Popen) -> None:
    child.terminate()
    try:
        child.wait(10)
    except subprocess.TimeoutExpired:
        child.kill()
        child.wait()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer messages")
    parser.add_argument("--role", choices=["echo", "raw"], help=argparse.SUPPRESS)
    parser.add_argument("--uri", help=argparse.SUPPRESS)
    parser.add_argument("--type", help=argparse.SUPPRESS)
    parser.add_argument("--inline", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.role == "echo":
        serve_workbench(args.uri, args.type, args.inline)
        return 0
    if args.role == "raw":
        serve_raw(args.uri)
        return 0

    n = 300 if args.quick else 2000
    info = describe(("workbench", "eclipse-zenoh", "rosbags"), seed=SEED)
    rows = []
    from workbench.bus.core import Core

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    uri = f"tcp/127.0.0.1:{port}"
    core = Core(uri)
    try:
        for name, msg in payloads().items():
            base = inproc_queue(msg, n)
            rows.append(("in-process", name, inproc_workbench(msg, n), "queue+thread", base))
            inline = inproc_workbench(msg, n, inline=True)
            rows.append(("in-proc inline", name, inline, "queue+thread", base))
            raw_child = _spawn(["--role", "raw", "--uri", uri])
            try:
                raw = cross_raw(uri, msg, n)
            finally:
                _stop(raw_child)
            for where, flag in (("2 processes", []), ("2 proc inline", ["--inline"])):
                echo = _spawn(["--role", "echo", "--uri", uri, "--type", msg._type, *flag])
                try:
                    wb = cross_workbench(uri, msg, n, inline=bool(flag))
                finally:
                    _stop(echo)
                rows.append((where, name, wb, "raw zenoh", raw))
    finally:
        core.close()

    print(
        f"machine: {info['cpu']}, {info['cores']} cores, Python {info['python']}, "
        f"eclipse-zenoh {info['eclipse-zenoh']}, rosbags {info['rosbags']}, seed {SEED}"
    )
    print(f"messages per latency run: {n}")
    header = (
        f"{'where':14} {'payload':11} | {'workbench p50/p99 us':>21} {'msgs/s':>8} "
        f"{'lost':>5} | {'baseline':12} {'p50/p99 us':>15} {'msgs/s':>8} {'lost':>5} "
        f"| p50 ratio"
    )
    print(header)
    print("-" * len(header))
    results = []
    for where, name, wb, base_name, base in rows:
        ratio = wb["p50_us"] / base["p50_us"] if wb["p50_us"] and base["p50_us"] else None
        print(
            f"{where:14} {name:11} | {wb['p50_us']:>9}/{wb['p99_us']:<11} {wb['msgs_per_s']:>8} "
            f"{str(wb['lost_at_10k']):>5} | {base_name:12} {base['p50_us']:>7}/{base['p99_us']:<7} "
            f"{base['msgs_per_s']:>8} {str(base['lost_at_10k']):>5} | "
            f"{ratio:.2f}x"
            if ratio
            else "-"
        )
        results.append(
            {
                "where": where,
                "payload": name,
                "workbench": wb,
                "baseline_name": base_name,
                "baseline": base,
                "p50_ratio": ratio,
            }
        )
    out = HERE / "results" / "bus.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps({"machine": info, "n": n, "rows": results}, indent=2) + "\n")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
