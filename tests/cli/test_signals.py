"""Long-running commands stop cleanly on SIGINT and SIGTERM, also as background shell jobs.

A non-interactive shell starts a background job with SIGINT ignored; these tests run
the commands exactly so (``bash -c 'workbench ... & ... kill -INT %1; wait %1'``) and
check that each one finalises what it writes and exits with 130 (SIGINT) or 143
(SIGTERM). Every process group a test starts is killed in ``finally``.
"""

from __future__ import annotations

import contextlib
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from workbench.cli.signals import Terminated, stop_event_on_signals, stop_on_signals
from workbench.msgs.std_msgs import String

STATUS = {"INT": 130, "TERM": 143}

#: Start COMMAND in the background, wait (at most 120 s) until READY succeeds, send the
#: signal to the job, wait for it and print its exit status.
JOB = """
{setup}
"$PY" -m workbench {command} > job.log 2>&1 &
for _ in $(seq 1200); do {ready} && break; sleep 0.1; done
{ready} || {{ echo "not ready"; cat job.log; }}
sleep 0.5
kill -{signal} %1
wait %1
echo "status=$?"
"""


def _free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def run_job(
    tmp_path: Path, command: str, ready: str, sig: str, setup: str = "", uri: str = "inproc"
) -> tuple[int, str]:
    """Run the job script in ``bash -c``; returns the job's exit status and its output."""
    script = JOB.format(setup=setup, command=command, ready=ready, signal=sig)
    env = dict(os.environ, PY=sys.executable, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    env.pop("WORKBENCH_DEBUG", None)
    shell = subprocess.Popen(
        ["bash", "-c", script],
        cwd=tmp_path,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,  # its own process group: the finally below ends every child
    )
    try:
        out, _ = shell.communicate(timeout=240)
    finally:
        with contextlib.suppress(ProcessLookupError):  # the core and publisher of a setup
            os.killpg(shell.pid, signal.SIGKILL)
        shell.wait()
    log = (
        (tmp_path / "job.log").read_text(errors="replace")
        if (tmp_path / "job.log").exists()
        else ""
    )
    assert "status=" in out, out + log
    return int(out.rsplit("status=", 1)[1].split()[0]), log


def _start(tmp_path: Path, uri: str, name: str, *args: str) -> subprocess.Popen:
    env = dict(os.environ, WORKBENCH_MASTER_URI=uri, PYTHONUNBUFFERED="1")
    with open(tmp_path / f"{name}.log", "wb") as log:
        return subprocess.Popen(
            [sys.executable, "-m", "workbench", *args], env=env, stdout=log, stderr=log
        )


def _wait_for(path: Path, text: str, process: subprocess.Popen) -> None:
    for _ in range(1200):
        if text in path.read_text(errors="replace") or process.poll() is not None:
            break
        time.sleep(0.1)
    assert text in path.read_text(errors="replace"), path.read_text(errors="replace")


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_bag_record_in_the_background_closes_its_bag(tmp_path, sig):
    uri = f"tcp/127.0.0.1:{_free_port()}"
    started: list[subprocess.Popen] = []
    try:
        started.append(_start(tmp_path, uri, "core", "core"))
        _wait_for(tmp_path / "core.log", "started core", started[-1])
        started.append(
            _start(
                tmp_path,
                uri,
                "pub",
                "topic",
                "pub",
                "-r",
                "20",
                "/chatter",
                "std_msgs/String",
                "hi",
            )
        )
        # the script: record in the background, interrupt job %1 once it has started
        status, log = run_job(
            tmp_path,
            "bag record -a -O x.bag",
            "grep -q 'Subscribing to /chatter' job.log",
            sig,
            uri=uri,
        )
    finally:
        for process in reversed(started):
            process.send_signal(signal.SIGINT)
            try:
                process.wait(20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
    assert status == STATUS[sig], log
    assert "Closing" in log and "Traceback" not in log
    assert (tmp_path / "x.bag").is_file() and not (tmp_path / "x.bag.active").exists()
    info = subprocess.run(
        [sys.executable, "-m", "workbench", "bag", "info", "x.bag"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert info.returncode == 0, info.stderr
    assert "/chatter" in info.stdout and "std_msgs/String" in info.stdout


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_core_stops_from_a_background_job(tmp_path, sig):
    uri = f"tcp/127.0.0.1:{_free_port()}"
    status, log = run_job(tmp_path, "core", "grep -q 'started core' job.log", sig, uri=uri)
    assert status == STATUS[sig], log
    assert "shutting down core service" in log and "Traceback" not in log


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_turtlesim_stops_from_a_background_job_and_writes_its_canvas(tmp_path, sig):
    status, log = run_job(tmp_path, "turtlesim --png canvas.png", "test -s canvas.png", sig)
    assert status == STATUS[sig], log
    assert (tmp_path / "canvas.png").read_bytes()[:4] == b"\x89PNG"
    assert "Traceback" not in log


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_topic_echo_stops_from_a_background_job(tmp_path, sig):
    status, log = run_job(tmp_path, "topic echo /chatter", "grep -q chatter job.log", sig)
    assert status == STATUS[sig], log
    assert "Traceback" not in log


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_launch_stops_its_nodes_from_a_background_job(tmp_path, sig):
    (tmp_path / "talk.launch").write_text(
        '<launch><node pkg="beginner_tutorials" type="talker.py" name="talker"/></launch>'
    )
    uri = f"tcp/127.0.0.1:{_free_port()}"
    status, log = run_job(
        tmp_path, "launch talk.launch", "grep -q 'started with pid' job.log", sig, uri=uri
    )
    assert status == STATUS[sig], log
    pids = [int(line.split("[")[-1].split("]")[0]) for line in log.splitlines() if "pid [" in line]
    assert pids, log
    for pid in pids:  # the launcher stopped its node before it exited
        assert not Path(f"/proc/{pid}").exists() or "Z" in _proc_state(pid), log
    assert "Traceback" not in log


def _proc_state(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/stat").read_text().split(")")[-1].split()[0]
    except OSError:
        return "gone"


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_run_of_a_lab_script_stops_from_a_background_job(tmp_path, sig):
    status, log = run_job(
        tmp_path, "run beginner_tutorials talker.py", "grep -q 'hello world' job.log", sig
    )
    assert status == STATUS[sig], log
    assert "Traceback" not in log


@pytest.mark.multiprocess
@pytest.mark.slow
def test_tf_view_writes_its_html_snapshot_when_terminated(tmp_path):
    status, log = run_job(
        tmp_path, "tf view --html snap.html", "grep -q 'tf frames in' job.log", "TERM"
    )
    assert status == STATUS["TERM"], log
    assert "snapshot:" in log
    assert "<html" in (tmp_path / "snap.html").read_text(errors="replace").lower()


def test_stop_on_signals_raises_even_when_sigint_was_ignored():
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)  # as in a background job
    try:
        with stop_on_signals() as stop:
            with pytest.raises(KeyboardInterrupt) as raised:
                os.kill(os.getpid(), signal.SIGINT)
                signal.sigtimedwait([], 0)  # let the handler run
            assert not isinstance(raised.value, Terminated)
            assert stop.exit_status == 130
            os.kill(os.getpid(), signal.SIGINT)  # a second signal does not interrupt finalising
        assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN  # the caller's handler is back
    finally:
        signal.signal(signal.SIGINT, previous)


def test_sigterm_raises_terminated_and_reports_143():
    previous = signal.getsignal(signal.SIGTERM)
    with stop_on_signals() as stop:
        with pytest.raises(Terminated):
            os.kill(os.getpid(), signal.SIGTERM)
            signal.sigtimedwait([], 0)
        assert stop.exit_status == 143
    assert signal.getsignal(signal.SIGTERM) == previous


def test_stop_event_on_signals_sets_the_event_instead_of_raising():
    event = threading.Event()
    with stop_on_signals() as stop, stop_event_on_signals(event):
        os.kill(os.getpid(), signal.SIGTERM)
        assert event.wait(5)
    assert stop.exit_status == 143


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_bag_play_in_a_loop_stops_from_a_background_job(tmp_path, sig):
    from workbench.bag import BagWriter

    with BagWriter(tmp_path / "in.bag") as bag:
        for i in range(20):
            bag.write("/chatter", String(data=f"m{i}"), 100.0 + 0.1 * i)
    status, log = run_job(tmp_path, "bag play -l in.bag", "grep -q 'Opening' job.log", sig)
    assert status == STATUS[sig], log
    assert "Traceback" not in log


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_sim_stops_from_a_background_job_and_writes_its_recording(tmp_path, sig):
    uri = f"tcp/127.0.0.1:{_free_port()}"
    status, log = run_job(
        tmp_path,
        "sim model_push --html rec.html",
        "grep -q 'services ready' job.log",
        sig,
        uri=uri,
    )
    assert status == STATUS[sig], log
    assert "stopped at t =" in log and "wrote" in log and "Traceback" not in log
    from workbench.viz.snapshot import snapshot_paths

    assert any("box" in path for path in snapshot_paths(tmp_path / "rec.html"))


@pytest.mark.multiprocess
def test_topic_echo_into_head_ends_quietly(tmp_path, free_uri):
    """`workbench topic echo ... | head -3` prints three lines and exits, no tracebacks."""
    script = """
"$PY" -m workbench core > core.log 2>&1 &
for _ in $(seq 300); do grep -q 'started core' core.log && break; sleep 0.1; done
"$PY" -m workbench topic pub -r 50 /chatter std_msgs/String "data: hi" > pub.log 2>&1 &
timeout 60 "$PY" -m workbench topic echo /chatter 2> echo.err | head -3 > head.out
echo "status=${PIPESTATUS[0]}"
kill %1 %2
"""
    env = dict(os.environ, PY=sys.executable, WORKBENCH_MASTER_URI=free_uri, PYTHONUNBUFFERED="1")
    shell = subprocess.run(
        ["bash", "-c", script], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120
    )
    assert "status=0" in shell.stdout, shell.stdout + shell.stderr
    assert (tmp_path / "head.out").read_text().splitlines() == ['data: "hi"', "---", 'data: "hi"']
    assert "Traceback" not in (tmp_path / "echo.err").read_text()


@pytest.mark.multiprocess
def test_ctrl_c_to_a_launch_ends_its_nodes_quietly(tmp_path):
    """Ctrl-C reaches every process of the terminal's group, and the launcher forwards it
    once more, as roslaunch does: the nodes stop without an error line, a traceback or a
    note about the second signal (issue 14, item 18)."""
    (tmp_path / "demo.launch").write_text(
        "<launch>"
        '<node pkg="turtlesim" type="turtlesim_node" name="sim"/>'
        '<node name="turtle1_tf_broadcaster" pkg="learning_tf" type="turtle_tf_broadcaster.py"'
        ' output="screen"><param name="turtle" type="string" value="turtle1"/></node>'
        '<node pkg="learning_tf" type="turtle_tf_listener.py" name="listener" output="screen"/>'
        "</launch>"
    )
    env = dict(
        os.environ, WORKBENCH_MASTER_URI=f"tcp/127.0.0.1:{_free_port()}", PYTHONUNBUFFERED="1"
    )
    env.pop("WORKBENCH_DEBUG", None)
    log_path = tmp_path / "launch.log"
    with open(log_path, "wb") as log:
        launch = subprocess.Popen(
            [sys.executable, "-m", "workbench", "launch", "demo.launch"],
            cwd=tmp_path,
            env=env,
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,  # a group of its own, like a terminal's foreground job
        )
    try:
        _wait_for(log_path, "process[listener-3]: started", launch)
        time.sleep(4)  # the listener spawns turtle2 and loops on its Rate
        os.killpg(launch.pid, signal.SIGINT)  # what Ctrl-C does
        assert launch.wait(60) == 130
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(launch.pid, signal.SIGKILL)
    text = log_path.read_text(errors="replace")
    for noise in ("error:", "Traceback", "already stopping", "Exception ignored"):
        assert noise not in text, text
