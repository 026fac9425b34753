"""``workbench.compat.rospy``: the lab's scripts in one process, and the rospy API.

Each scenario runs in a fresh interpreter (rospy state is per process) with
``WORKBENCH_MASTER_URI=inproc`` so no core is involved.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


def run_python(code: str, *args: str, timeout: float = 120) -> subprocess.CompletedProcess:
    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc", PYTHONUNBUFFERED="1")
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code), *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        env=env,
        cwd=REPO,
    )


def test_lab_scripts_in_one_process_without_a_core():
    result = run_python(
        """
        import runpy, threading, time
        from workbench.compat import rospy
        server = runpy.run_path("examples/add_two_ints_server.py", run_name="lab")
        client = runpy.run_path("examples/add_two_ints_client.py", run_name="lab")
        talker = runpy.run_path("examples/talker.py", run_name="lab")
        listener = runpy.run_path("examples/listener.py", run_name="lab")

        def talk():
            try:
                talker["talker"]()
            except rospy.ROSInterruptException:  # as the script's __main__ does
                pass

        for target in (server["add_two_ints_server"], listener["listener"], talk):
            threading.Thread(target=target, daemon=True).start()
        print("%s + %s = %s" % (1, 3, client["add_two_ints_client"](1, 3)))
        time.sleep(0.6)
        rospy.signal_shutdown("done")
        """
    )
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "Ready to add two ints." in out
    assert "Returning [1 + 3 = 4]" in out and "1 + 3 = 4" in out
    assert "]: hello world" in out
    assert "/listener_" in out and "I heard hello world" in out
    assert "Traceback" not in result.stderr


def test_rospy_api():
    result = run_python(
        """
        import sys
        from workbench.compat import rospy
        from workbench.msgs.std_msgs import String
        from workbench.msgs.std_srvs import Trigger, TriggerResponse

        pub = rospy.Publisher("chatter", String, queue_size=1, latch=True)  # before init_node
        rospy.init_node("probe", anonymous=False)
        print("name", rospy.get_name(), rospy.get_caller_id())
        print("argv", rospy.myargv())
        print("private", rospy.get_param("~rate"), rospy.get_param("~missing", "dflt"))
        rospy.set_param("gain", {"p": 1.5})
        print("search", rospy.search_param("gain"), rospy.has_param("/gain/p"))
        rospy.delete_param("gain")
        try:
            rospy.get_param("/gain")
        except KeyError:
            print("missing raises KeyError")
        pub.publish("latched")
        msg = rospy.wait_for_message("chatter", String, timeout=2.0)
        print("latched message", msg.data, pub.get_num_connections() >= 0)
        print("published", rospy.get_published_topics())

        def fail(req):
            raise RuntimeError("sensor offline")

        rospy.Service("check", Trigger, lambda req: TriggerResponse(True, "ok"))
        rospy.Service("broken", Trigger, fail)
        rospy.wait_for_service("check", timeout=1.0)
        print("trigger", rospy.ServiceProxy("check", Trigger)().message)
        try:
            rospy.ServiceProxy("broken", Trigger)()
        except rospy.ServiceException as error:
            print("service exception:", error)
        try:
            rospy.wait_for_service("nobody", timeout=0.1)
        except rospy.ROSException as error:
            print("wait:", error)
        t = rospy.Time.now()
        print("time", t.to_sec() > 1e9, (t - rospy.Time(0)).to_sec() > 0, rospy.Time(1.5).nsecs)
        print("duration", rospy.Duration(2, 5).to_sec())
        rospy.sleep(0.01)
        rate = rospy.Rate(100)
        rate.sleep()
        rospy.on_shutdown(lambda: print("hook ran"))
        rospy.signal_shutdown("finished")
        print("is_shutdown", rospy.is_shutdown())
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            print("interrupted")
        """,
        "_rate:=7",
        "extra",
    )
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "name /probe /probe" in lines
    assert any(line.startswith("argv") and "extra" in line and ":=" not in line for line in lines)
    assert "private 7 dflt" in lines
    assert "search /gain True" in lines
    assert "missing raises KeyError" in lines
    assert "latched message latched True" in lines
    assert "published [['/chatter', 'std_msgs/String'], ['/rosout', 'rosgraph_msgs/Log']]" in lines
    assert "trigger ok" in lines
    assert any("service exception:" in ln and "sensor offline" in ln for ln in lines)
    assert "wait: timeout exceeded while waiting for service /nobody" in lines
    assert "time True True 500000000" in lines
    assert "duration 2.000000005" in lines
    assert "hook ran" in lines and "is_shutdown True" in lines and "interrupted" in lines


def test_client_prints_usage_without_arguments():
    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc")
    result = subprocess.run(
        [sys.executable, str(REPO / "examples" / "add_two_ints_client.py")],
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
    )
    assert result.returncode == 1
    assert "add_two_ints_client.py [x y]" in result.stdout


def test_rospy_state_lives_in_one_context(monkeypatch):
    from workbench.bus import Bus, Node
    from workbench.compat import rospy
    from workbench.msgs.std_msgs import String

    ctx = rospy.RospyContext()
    monkeypatch.setattr(rospy, "_CONTEXT", ctx)  # this test's own state, restored after
    assert rospy.context() is ctx and ctx.node() is None and not rospy.is_shutdown()
    with pytest.raises(rospy.ROSInitException, match="not initialized"):
        rospy.get_param("/x")
    pub = rospy.Publisher("chatter", String, queue_size=1)  # before the node: deferred
    assert ctx.pending == [pub]
    bus = Bus(threaded=False)
    node = Node("ctx_test", bus=bus, disable_rosout=True)
    got = []
    node.create_subscription("/chatter", String, got.append)
    ctx.adopt(node)
    assert ctx.pending == [] and ctx.main_node is node and rospy.get_caller_id() == "/ctx_test"
    pub.publish("bound")
    assert bus.spin_until(lambda: got, 1.0) and got == [String(data="bound")]
    rospy.signal_shutdown("test over")
    assert ctx.shutdown.is_set() and rospy.is_shutdown() and bus.is_shutdown


def test_publish_during_shutdown_is_dropped_and_on_an_unregistered_topic_raises():
    # rospy/topics.py, _PublisherImpl.publish: a closed topic during shutdown returns quietly
    # (shutdown races the script's is_shutdown() test); otherwise "publish() to a closed topic".
    result = run_python(
        """
        from workbench.compat import rospy
        from workbench.msgs.std_msgs import String

        rospy.init_node("closer")
        gone = rospy.Publisher("gone", String, queue_size=1)
        gone.unregister()
        try:
            gone.publish("x")
        except rospy.ROSException as error:
            print("unregistered:", error)
        pub = rospy.Publisher("chatter", String, queue_size=1)
        rospy.signal_shutdown("test")
        pub.publish("after shutdown")
        print("dropped quietly")
        """
    )
    assert result.returncode == 0, result.stderr
    assert "unregistered: publish() to a closed topic (/gone)" in result.stdout
    assert "dropped quietly" in result.stdout


@pytest.mark.multiprocess
@pytest.mark.parametrize("sig", ["INT", "TERM"])
def test_a_stop_signal_runs_the_shutdown_hooks_of_a_script_under_workbench_run(tmp_path, sig):
    # rospy's own handler (rospy/core.py, _ros_signal) calls signal_shutdown -- which runs the
    # on_shutdown hooks and wakes rospy.sleep with ROSInterruptException -- then chains to the
    # handler installed before it; workbench run's handler then sets the exit status.
    script = tmp_path / "hooked.py"
    script.write_text(
        textwrap.dedent(
            """
            from workbench.compat import rospy
            rospy.init_node("hooked")
            rospy.on_shutdown(lambda: print("hook ran", flush=True))
            print("ready", flush=True)
            try:
                while not rospy.is_shutdown():
                    rospy.sleep(0.05)
            except rospy.ROSInterruptException:
                print("interrupted", flush=True)
            print("loop over", flush=True)
            """
        )
    )
    workbench = Path(sys.executable).with_name("workbench")
    env = dict(os.environ, WORKBENCH_MASTER_URI="inproc", PYTHONUNBUFFERED="1")
    # a background job of a non-interactive shell: SIGINT starts out ignored
    result = subprocess.run(
        [
            "bash",
            "-c",
            f'"{workbench}" run pkg "{script}" > "{tmp_path}/out" 2>&1 &\n'
            f'for i in $(seq 600); do grep -q ready "{tmp_path}/out" 2>/dev/null && break; '
            "sleep 0.1; done\n"
            f"kill -{sig} %1; wait %1",
        ],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
    )
    out = (tmp_path / "out").read_text()
    assert result.returncode == (130 if sig == "INT" else 143), out
    assert "hook ran" in out and "loop over" in out, out
    assert "Traceback" not in out, out
