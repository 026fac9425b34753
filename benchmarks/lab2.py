"""Lab 2 benchmark: topic echo/hz at 1 kHz, bag record throughput, turtlesim with 10 turtles.

Run ``python benchmarks/lab2.py [--quick]``. It starts a ``workbench core`` on
a free port, publishers in other processes, and measures:

* ``topic hz`` and ``topic echo`` against a 1 kHz publisher (baseline: the 1000 Hz sent);
* ``bag record`` of small messages sent as fast as possible from another process:
  messages in the bag vs. messages sent, and msgs/s, next to rosbags' own writer
  writing the same messages in this process (the ceiling);
* turtlesim's update with 10 turtles: time per 16 ms step, and the pose rate of a
  running node (baseline: the nominal 62.5 Hz).

Prints a table with the machine and writes ``benchmarks/results/lab2.json``.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from machine import describe

SEED = 0
HERE = Path(__file__).resolve().parent

PUBLISHER = r"""
import sys, time
from workbench.bus import Node
from workbench.msgs.std_msgs import Int64
rate, count, topic = float(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
node = Node("bench_pub", anonymous=True, disable_rosout=True)
pub = node.create_publisher(topic, Int64, queue_size=0)
time.sleep(float(sys.argv[4]))  # let subscribers discover us
start = time.perf_counter()
for i in range(count):
    pub.publish(Int64(data=i))
    if rate > 0:
        delay = start + (i + 1) / rate - time.perf_counter()
        if delay > 0:
            time.sleep(delay)
elapsed = time.perf_counter() - start
print(f"SENT {count} {elapsed:.6f}", flush=True)
time.sleep(float(sys.argv[5]) if len(sys.argv) > 5 else 1.0)
# exits now: what is still on its way to a slower subscriber is flushed on the way out
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start(args: list[str], env: dict[str, str]) -> subprocess.Popen:
    return subprocess.Popen(
        args, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )


def stop(proc: subprocess.Popen) -> str:
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
    return proc.stdout.read() if proc.stdout else ""


def wb(*args: str) -> list[str]:
    return [sys.executable, "-m", "workbench", *args]


def bench_hz_echo(env: dict[str, str], seconds: float) -> dict[str, float]:
    count = int(1000 * (seconds + 4))
    pub = start([sys.executable, "-c", PUBLISHER, "1000", str(count), "/bench_hz", "1.0"], env)
    try:
        hz = subprocess.run(
            wb("topic", "hz", "/bench_hz", "--duration", str(seconds + 1)),
            env=env, capture_output=True, text=True, timeout=120,
        ).stdout  # fmt: skip
        rates = [float(x) for x in re.findall(r"average rate: ([0-9.]+)", hz)]
        n = int(500 * seconds)
        t0 = time.perf_counter()
        echo = subprocess.run(
            wb("topic", "echo", "/bench_hz", "-n", str(n), "--timeout", "60"),
            env=env, capture_output=True, text=True, timeout=120,
        )  # fmt: skip
        elapsed = time.perf_counter() - t0
        got = echo.stdout.count("---")
    finally:
        stop(pub)
    return {
        "hz_measured": rates[-1] if rates else 0.0,
        "hz_sent": 1000.0,
        "echo_messages": got,
        "echo_wanted": n,
        "echo_seconds_incl_startup": elapsed,
    }


def bench_record(env: dict[str, str], count: int, tmp: Path) -> dict[str, float]:
    bag = tmp / "bench.bag"
    # -l COUNT: the recorder stops by itself once it has written every message sent
    recorder = start(wb("bag", "record", "-O", str(bag), "-l", str(count), "/bench_rec"), env)
    time.sleep(3.0)
    # the publisher exits right after its burst (the bus flushes to the recorder on exit)
    pub = start([sys.executable, "-c", PUBLISHER, "0", str(count), "/bench_rec", "2.0", "0"], env)
    out = ""
    while "SENT" not in out and pub.poll() is None:
        out = pub.stdout.readline() if pub.stdout else ""
    match = re.search(r"SENT (\d+) ([0-9.]+)", out)
    sent, seconds = (int(match.group(1)), float(match.group(2))) if match else (count, float("nan"))
    # if it did not get everything in time, stop it and count what it wrote
    with contextlib.suppress(subprocess.TimeoutExpired):
        recorder.wait(timeout=max(60.0, count / 2000.0))
    stop(recorder)
    stop(pub)
    from workbench.bag import read_messages, summarize

    summary = summarize(bag)
    in_bag = summary.message_count
    span = (summary.end_ns - summary.start_ns) / 1e9 if in_bag > 1 else float("nan")
    in_order = [m.msg.data for m in read_messages(bag)] == list(range(in_bag))
    # rosbags' own writer on the same serialized messages: the ceiling
    from rosbags.rosbag1 import Writer

    from workbench.msgs import definition, md5sum, serialize
    from workbench.msgs.std_msgs import Int64

    ceiling = tmp / "ceiling.bag"
    t0 = time.perf_counter()
    with Writer(ceiling) as writer:
        conn = writer.add_connection(
            "/bench_rec", "std_msgs/msg/Int64", msgdef=definition("std_msgs/Int64"),
            md5sum=md5sum("std_msgs/Int64"),
        )  # fmt: skip
        for i in range(count):
            writer.write(conn, time.time_ns(), serialize(Int64(data=i)))
    ceiling_rate = count / (time.perf_counter() - t0)
    return {
        "sent": sent,
        "in_bag": in_bag,
        "lost": sent - in_bag,
        "in_order": in_order,
        "send_rate": sent / seconds if seconds else float("nan"),
        "record_rate": in_bag / span if span else float("nan"),
        "rosbags_writer_rate": ceiling_rate,
    }


def bench_turtlesim(env: dict[str, str], seconds: float) -> dict[str, float]:
    from workbench.bus import Bus, Node
    from workbench.turtlesim.node import TurtlesimNode

    bus = Bus(threaded=False)
    sim = TurtlesimNode(Node("turtlesim", bus=bus, disable_rosout=True), start_timer=False)
    for i in range(9):
        sim.spawn("", 1.0 + i, 2.0, 0.1 * i)
    steps = 300
    t0 = time.perf_counter()
    for _ in range(steps):
        sim.step()
    step_ms = (time.perf_counter() - t0) / steps * 1000
    bus.shutdown()
    # a running node in its own process, 10 turtles, pose rate seen by `topic hz`
    node_proc = start(wb("turtlesim"), env)
    try:
        time.sleep(3.0)
        for i in range(9):
            subprocess.run(
                wb("service", "call", "/spawn", str(1 + i), "2", "0", ""), env=env,
                capture_output=True, timeout=60,
            )  # fmt: skip
        hz = subprocess.run(
            wb("topic", "hz", "/turtle9/pose", "--duration", str(seconds)),
            env=env, capture_output=True, text=True, timeout=120,
        ).stdout  # fmt: skip
    finally:
        stop(node_proc)
    rates = [float(x) for x in re.findall(r"average rate: ([0-9.]+)", hz)]
    return {
        "step_ms_10_turtles": step_ms,
        "budget_ms": 16.0,
        "pose_rate_hz": rates[-1] if rates else 0.0,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="shorter runs")
    parser.add_argument(
        "--only", choices=("hz", "record", "turtlesim"), help="run one part (no JSON written)"
    )
    args = parser.parse_args()
    seconds = 2.0 if args.quick else 5.0
    count = 20_000 if args.quick else 100_000
    env = dict(os.environ, WORKBENCH_MASTER_URI=f"tcp/127.0.0.1:{free_port()}")
    os.environ["WORKBENCH_MASTER_URI"] = env["WORKBENCH_MASTER_URI"]
    core = start(wb("core"), env)
    time.sleep(1.5)
    try:
        with tempfile.TemporaryDirectory() as tmp:
            parts = ("hz", "record", "turtlesim") if args.only is None else (args.only,)
            hz = bench_hz_echo(env, seconds) if "hz" in parts else None
            rec = bench_record(env, count, Path(tmp)) if "record" in parts else None
            ts = bench_turtlesim(env, seconds) if "turtlesim" in parts else None
    finally:
        stop(core)
    info = describe(("rosbags", "eclipse-zenoh"), seed=SEED)
    if args.only is not None:
        print(f"machine: {info['cpu']}, {info['cores']} cores, python {info['python']}, "
              f"rosbags {info['rosbags']}, zenoh {info['eclipse-zenoh']}, seed {info['seed']}")  # fmt: skip
        print(json.dumps({"hz_echo": hz, "record": rec, "turtlesim": ts}, indent=2))
        return 0
    assert hz is not None and rec is not None and ts is not None
    rows = [
        ("topic hz on a 1 kHz publisher (Hz)", hz["hz_measured"], hz["hz_sent"]),
        ("topic echo -n N: messages printed", hz["echo_messages"], hz["echo_wanted"]),
        ("bag record: messages in bag", rec["in_bag"], rec["sent"]),
        (
            "bag record: recorded msg/s vs rosbags writer",
            rec["record_rate"],
            rec["rosbags_writer_rate"],
        ),
        ("bag record: publisher send rate (msg/s)", rec["send_rate"], 20000.0),
        ("turtlesim step, 10 turtles (ms)", ts["step_ms_10_turtles"], ts["budget_ms"]),
        ("turtlesim pose rate, 10 turtles (Hz)", ts["pose_rate_hz"], 62.5),
    ]
    print(f"machine: {info['cpu']}, {info['cores']} cores, python {info['python']}, "
          f"rosbags {info['rosbags']}, zenoh {info['eclipse-zenoh']}, seed {info['seed']}")  # fmt: skip
    print(f"{'measure':<50} {'workbench':>12} {'baseline':>12} {'ratio':>7}")
    for name, ours, base in rows:
        ratio = ours / base if base else float("nan")
        print(f"{name:<50} {ours:>12.1f} {base:>12.1f} {ratio:>7.2f}")
    print(f"bag record lost {rec['lost']} messages; in order: {rec['in_order']}")
    out = HERE / "results" / "lab2.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps({"machine": info, "quick": args.quick, "hz_echo": hz, "record": rec,
                               "turtlesim": ts}, indent=2))  # fmt: skip
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
