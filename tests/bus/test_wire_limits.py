"""Between processes: bounded names and message sizes, and a node whose transport fails exits.

Issue 17, item 3: ``workbench service call /spawn 1 1 0 <100,000 characters>`` made Zenoh panic
inside turtlesim (a key too long for one network batch) and every later call timed out.
"""

from __future__ import annotations

import subprocess
import textwrap

import pytest
from process_helpers import Processes, joined_bus, private_core

from workbench.bus.errors import ServiceError
from workbench.bus.names import MAX_NAME_LENGTH, InvalidNameError, check_name, resolve
from workbench.bus.wire import EXIT_TRANSPORT_FAILED, MAX_MESSAGE_BYTES
from workbench.errors import MessageError


def test_names_are_bounded():
    check_name("a" * MAX_NAME_LENGTH)
    with pytest.raises(InvalidNameError, match="is 513 characters long, more than the 512"):
        check_name("a" * (MAX_NAME_LENGTH + 1), "topic name")
    # each part may be short and the resolved name still too long
    namespace = "/" + "/".join(["ns"] * 200)
    with pytest.raises(InvalidNameError, match="more than the 512 a name may have"):
        resolve("x" * 200, namespace, namespace + "/node")


@pytest.mark.multiprocess
def test_a_huge_turtle_name_is_refused_and_turtlesim_keeps_working(tmp_path, run_cli):
    pytest.importorskip("zenoh")
    with private_core(tmp_path) as uri:
        processes = Processes(uri, tmp_path)
        try:
            sim = processes.start("-m", "workbench", "turtlesim", name="turtlesim")
            processes.wait_output(sim, "Spawning turtle [turtle1]")
            env = {"WORKBENCH_MASTER_URI": uri}
            huge = run_cli("service", "call", "/spawn", "1", "1", "0", "a" * 100_000, env=env)
            assert huge.returncode == 1
            lines = huge.stderr.strip().splitlines()
            assert len(lines) == 1 and "is 100,000 characters long" in lines[0], huge.stderr
            again = run_cli("service", "call", "/spawn", "2", "2", "0", "t3", env=env)
            assert again.returncode == 0, again.stderr
            assert 'name: "t3"' in again.stdout
            assert sim.poll() is None, processes.output(sim)
            assert "panicked" not in processes.output(sim)
        finally:
            processes.stop_all()


@pytest.mark.multiprocess
def test_messages_and_calls_past_the_size_bound_are_refused_where_they_are_sent(tmp_path):
    pytest.importorskip("zenoh")
    from workbench.bus import Node
    from workbench.msgs.std_msgs import String
    from workbench.msgs.turtlesim import Spawn

    with private_core(tmp_path) as uri:
        bus = joined_bus(uri)
        try:
            node = Node("sender", bus=bus)
            pub = node.create_publisher("/big", String, queue_size=1)
            too_big = "x" * (MAX_MESSAGE_BYTES + 1)
            with pytest.raises(MessageError, match="a message on /big is 64.0 MiB, more than"):
                pub.publish(String(data=too_big))
            node.create_service("/spawn", Spawn, lambda req: Spawn.Response(name=req.name))
            other = joined_bus(uri)
            try:
                client = Node("caller", bus=other).create_client("/spawn", Spawn)
                client.wait_for_service(timeout=10)
                with pytest.raises(ServiceError, match="a request to service /spawn is 64.0 MiB"):
                    client.call(Spawn.Request(name=too_big))
                assert client.call(Spawn.Request(name="fine")).name == "fine"
            finally:
                other.shutdown()
        finally:
            bus.shutdown()


PANIC_SCRIPT = textwrap.dedent(
    """
    import time
    from workbench.bus import Bus, Node
    from workbench.msgs.std_msgs import String

    bus = Bus.connect()
    pub = Node("victim", bus=bus).create_publisher("/chatter", String, queue_size=10)
    session = bus.transports[-1].session
    print("ready", flush=True)
    # a key longer than a network batch: what a 100,000-character name did before names
    # were bounded; Zenoh panics in its own threads and poisons the session
    session.declare_publisher("wb/x/" + "a" * 100_000)
    for _ in range(600):
        pub.publish(String(data="still here?"))
        time.sleep(0.05)
    print("lingered", flush=True)
    """
)


@pytest.mark.multiprocess
def test_a_node_whose_transport_fails_exits_instead_of_lingering(tmp_path):
    pytest.importorskip("zenoh")
    with private_core(tmp_path) as uri:
        processes = Processes(uri, tmp_path)
        script = tmp_path / "victim.py"
        script.write_text(PANIC_SCRIPT)
        child = processes.start(str(script), name="victim")
        try:
            status = child.wait(timeout=60)
        except subprocess.TimeoutExpired:
            processes.stop_all()
            raise AssertionError("the node lingered:\n" + processes.output(child)[-3000:]) from None
        out = processes.output(child)
        assert status == EXIT_TRANSPORT_FAILED, out[-3000:]
        assert "lingered" not in out and "Traceback" not in out, out[-3000:]
        # Zenoh's own panic report goes to the same stderr and may interleave with ours
        fatal = [line[line.index("[FATAL]") :] for line in out.splitlines() if "[FATAL]" in line]
        assert len(fatal) == 1 and "the Zenoh transport failed in" in fatal[0], out[-3000:]
