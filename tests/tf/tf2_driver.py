"""Runs tf2 cases through ROS 1's own tf2 (``tf2_py.BufferCore``) and prints the results.

Run with the system Python that has Debian's python3-tf2 (not workbench's venv);
``test_tf2_differential.py`` feeds it JSON on stdin and compares its answers with
workbench's. It needs no ROS master: ``BufferCore`` is the bare C++ buffer.

Input: a JSON list of scenarios, each ``{"cache_ns": int, "steps": [...]}``. A step is
an operation -- ``["set", parent, child, stamp_ns, [x, y, z], [qx, qy, qz, qw], static]``
or ``["clear"]`` -- or a query:

* ``["lookup", target, source, t_ns]``
* ``["full", target, target_t_ns, source, source_t_ns, fixed]``
* ``["can", target, source, t_ns]``
* ``["can_full", target, target_t_ns, source, source_t_ns, fixed]``
* ``["lct", target, source]``

Output: one JSON list per scenario with one entry per query: ``["ok", value]`` or
``["err", exception class name, message]``. A lookup's value is
``[stamp_ns, frame_id, child_frame_id, x, y, z, qx, qy, qz, qw]``, a ``can`` query's
``[possible, error string]`` and ``lct``'s the time in nanoseconds.
"""

from __future__ import annotations

import json
import sys

import rospy
import tf2_py
from geometry_msgs.msg import TransformStamped


def _time(ns: int) -> rospy.Time:
    return rospy.Time(ns // 1_000_000_000, ns % 1_000_000_000)


def _message(parent: str, child: str, stamp_ns: int, xyz: list, quat: list) -> TransformStamped:
    msg = TransformStamped()
    msg.header.frame_id = parent
    msg.child_frame_id = child
    msg.header.stamp = _time(stamp_ns)
    t = msg.transform.translation
    t.x, t.y, t.z = xyz
    q = msg.transform.rotation
    q.x, q.y, q.z, q.w = quat
    return msg


def _transform(msg: TransformStamped) -> list:
    t = msg.transform.translation
    q = msg.transform.rotation
    return [
        msg.header.stamp.to_nsec(),
        msg.header.frame_id,
        msg.child_frame_id,
        t.x,
        t.y,
        t.z,
        q.x,
        q.y,
        q.z,
        q.w,
    ]


def _query(core: tf2_py.BufferCore, step: list) -> list:
    kind = step[0]
    try:
        if kind == "lookup":
            value = _transform(core.lookup_transform_core(step[1], step[2], _time(step[3])))
        elif kind == "full":
            value = _transform(
                core.lookup_transform_full_core(
                    step[1], _time(step[2]), step[3], _time(step[4]), step[5]
                )
            )
        elif kind == "can":
            ok, why = core.can_transform_core(step[1], step[2], _time(step[3]))
            value = [bool(ok), why]
        elif kind == "can_full":
            ok, why = core.can_transform_full_core(
                step[1], _time(step[2]), step[3], _time(step[4]), step[5]
            )
            value = [bool(ok), why]
        elif kind == "lct":
            value = core.get_latest_common_time(step[1], step[2]).to_nsec()
        else:
            raise ValueError(f"unknown query {kind!r}")
    except tf2_py.TransformException as exc:
        return ["err", type(exc).__name__, str(exc)]
    return ["ok", value]


def run(scenarios: list) -> list:
    results = []
    for scenario in scenarios:
        cache_ns = scenario["cache_ns"]
        core = tf2_py.BufferCore(
            rospy.Duration(cache_ns // 1_000_000_000, cache_ns % 1_000_000_000)
        )
        answers = []
        for step in scenario["steps"]:
            if step[0] == "set":
                _, parent, child, stamp_ns, xyz, quat, static = step
                msg = _message(parent, child, stamp_ns, xyz, quat)
                if static:
                    core.set_transform_static(msg, "differential")
                else:
                    core.set_transform(msg, "differential")
            elif step[0] == "clear":
                core.clear()
            else:
                answers.append(_query(core, step))
        results.append(answers)
    return results


if __name__ == "__main__":
    json.dump(run(json.load(sys.stdin)), sys.stdout)
