"""What ``workbench launch`` does with roslaunch's run-time settings, with real processes:
``<env>``, ``launch-prefix``, ``cwd``, ``clear_params``, ``<rosparam command="delete|dump">``
(run before the parameters are set, as roslaunch runs them) and ``required``."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
import yaml

from workbench.bus import Bus

pytestmark = pytest.mark.multiprocess

REPORTER = """import json, os, sys
from pathlib import Path
Path(sys.argv[1]).write_text(json.dumps({
    "env": os.environ.get("WB_NODE_ENV"), "group_env": os.environ.get("WB_GROUP_ENV"),
    "prefixed": os.environ.get("WB_PREFIXED"), "cwd": os.getcwd(),
}))
"""


def test_env_prefix_cwd_and_parameter_commands_reach_the_processes(tmp_path, core_uri):
    scripts = tmp_path / "scripts"
    scripts.mkdir()
    (scripts / "reporter.py").write_text(REPORTER)
    report = tmp_path / "report.json"
    launch = tmp_path / "run.launch"
    launch.write_text(
        f"""<launch>
  <rosparam command="dump" file="$(dirname)/dump.yaml" param="/keep"/>
  <rosparam command="delete" param="/gone"/>
  <group ns="old" clear_params="true"><param name="z" value="3"/></group>
  <group><env name="WB_GROUP_ENV" value="group"/>
    <node pkg="tests" type="reporter.py" name="reporter" required="true" cwd="node"
          args="{report}" launch-prefix="env WB_PREFIXED=yes">
      <env name="WB_NODE_ENV" value="node"/>
    </node>
  </group>
</launch>
"""
    )
    with Bus.connect(core_uri) as bus:
        bus.params.set("/keep/y", 2)
        bus.params.set("/gone", 1)
        bus.params.set("/old/x", 1)
    env = dict(os.environ, WORKBENCH_MASTER_URI=core_uri, PYTHONUNBUFFERED="1")
    env.pop("WB_GROUP_ENV", None)
    done = subprocess.run(
        [sys.executable, "-m", "workbench", "launch", str(launch)],
        env=env,
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "required node ended" in done.stdout
    seen = json.loads(report.read_text())
    assert seen == {
        "env": "node",
        "group_env": "group",
        "prefixed": "yes",
        "cwd": str(scripts),
    }
    assert yaml.safe_load((tmp_path / "dump.yaml").read_text()) == {"y": 2}
    with Bus.connect(core_uri) as bus:
        assert not bus.params.has("/gone")
        assert bus.params.get("/old") == {"z": 3}  # x cleared before z was set
        assert bus.params.get("/keep/y") == 2


def test_a_missing_launch_prefix_program_is_one_line(tmp_path, core_uri):
    launch = tmp_path / "run.launch"
    launch.write_text(
        '<launch><node pkg="tests" type="reporter.py" name="r" '
        'launch-prefix="no-such-debugger --args"/></launch>'
    )
    env = dict(os.environ, WORKBENCH_MASTER_URI=core_uri)
    done = subprocess.run(
        [sys.executable, "-m", "workbench", "launch", str(launch)],
        env=env,
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 1
    assert "launch-prefix program 'no-such-debugger' is not installed" in done.stderr
    assert "Traceback" not in done.stderr and len(done.stderr.strip().splitlines()) == 1
