"""``workbench topic echo`` against ROS 1's own ``rostopic echo`` (Debian's python3-rostopic 1.15).

Random messages (seeded) of many Noetic types go into a bag written by workbench's
``BagWriter``; ROS's ``rostopic echo -b BAG TOPIC`` (run in ``/usr/bin/python3``:
its command function in-process for speed, and once as the real ``rostopic`` program)
and ``workbench topic echo -b BAG TOPIC`` must print the same text, byte for byte, for:

* whole messages: strings (empty, unicode, quotes, YAML words such as ``yes``/``null``,
  ``: ``/``#``, leading spaces, numbers as text, several lines, longer than a line),
  ``string[]`` block lists, floats (float32 and float64: repr, ``nan``, ``inf``,
  ``-0.0``, huge and tiny), the full range of ints, bools, ``time``/``duration`` with
  padded ``nsecs``, ``uint8[]``, ``char[]`` (Python's ``b'...'``), fixed arrays, empty arrays, nested messages, arrays
  of messages (``TFMessage``, ``DiagnosticArray``, ``JointState``, ``LaserScan``,
  ``Image``, ``Odometry``, ``PoseStamped``, ``TransformStamped``, ``Twist``, ``Header``,
  and a test type with ``bool[]``, ``int8[]``, ``byte[]``, ``time``/``duration`` arrays and fixed
  arrays of messages);
* ``--noarr``, ``--nostr``, ``-w WIDTH``, ``-p`` (CSV), ``-n COUNT``, ``-a``, ``-c``,
  ``--filter EXPR``;
* field paths: ``/odom/pose/pose``, ``/header/stamp``, ``/tf/transforms``,
  ``/joint_states/name``, indexes and slices (``transforms[1]``, ``ranges[0:3]``,
  ``transforms[0:2]/child_frame_id``).

And the live-topic formatting (rostopic hands the field's declared type to
``--noarr``/``--nostr`` when echoing a field of a live topic) against rostopic's
``CallbackEcho`` given the same type information.

Skips (fails under WORKBENCH_REQUIRE_ALL=1) without ``/usr/bin/python3`` able to import
rostopic and the message packages; ``.ci/run`` installs them.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from skipping import ros_python as find_ros_python

from workbench.bag import BagWriter, read_messages
from workbench.cli import topic as topic_cli
from workbench.introspect.echo import field_type, format_echo, get_field
from workbench.msgs import Duration, Time, get_type
from workbench.msgs._store import store

ROS_MODULES = (
    "rostopic, rosbag, std_msgs.msg, geometry_msgs.msg, sensor_msgs.msg, nav_msgs.msg, "
    "tf2_msgs.msg, diagnostic_msgs.msg"
)

KINDS_TYPE = "echo_test/Kinds"
KINDS_TEXT = """\
bool flag
bool[] flags
int8 small
int8[] smalls
uint8 octet
uint8[4] quad
char letter
char[] letters
char[3] three
byte signed
byte[] signeds
int16 short
uint16 ushort
int32 word
uint32 uword
int64 big
uint64 ubig
float32 single
float32[3] singles
float64 double
float64[] doubles
string text
string[2] pair
time when
duration span
time[] whens
duration[] spans
geometry_msgs/Vector3[2] arrows
std_msgs/Header header
"""

STRINGS = [
    "",
    "hello",
    "h\u00e9llo",
    "\u4e2d\u6587",
    "\U0001f600 emoji",
    "a: b",
    "#comment",
    "- dash",
    " leading",
    "trailing ",
    "yes",
    "No",
    "null",
    "~",
    "true",
    "123",
    "1.5e3",
    "0x1F",
    "multi\nline",
    "tab\there",
    "it's",
    'say "hi"',
    "back\\slash",
    "[1, 2]",
    "{a: 1}",
    "*star",
    "&anchor",
    "!tag",
    "%percent",
    "@at",
    "`tick",
    "?",
    "a,b",
    "\x7f\x01",
    "\u2028sep",
    "\ufeffbom",
    "word " * 30,
    "x" * 90,
    "frame_" + "1" * 3,
]

SPECIAL_FLOATS = [
    0.0,
    -0.0,
    1.0,
    0.1,
    -2.5,
    1e20,
    1e-20,
    1e300,
    5e-324,
    123456789.123,
    1e16,
    float("nan"),
    float("inf"),
    float("-inf"),
]


@pytest.fixture(scope="module")
def ros_python() -> str:
    return find_ros_python(
        ROS_MODULES,
        "python3-rostopic python3-sensor-msgs python3-nav-msgs python3-diagnostic-msgs "
        "python3-tf2-msgs python3-geometry-msgs",
    )


class Random:
    """Seeded random field values, biased towards the awkward ones."""

    def __init__(self, seed: int) -> None:
        self.rng = np.random.default_rng(seed)

    def string(self) -> str:
        if self.rng.random() < 0.7:
            return STRINGS[int(self.rng.integers(len(STRINGS)))]
        alphabet = "abc XYZ:#-'\"\\\n\u00e9\u00fc\u03c0\u4e2d0123456789"
        size = int(self.rng.integers(0, 12))
        return "".join(alphabet[int(i)] for i in self.rng.integers(len(alphabet), size=size))

    def strings(self, most: int = 4) -> list[str]:
        return [self.string() for _ in range(int(self.rng.integers(0, most + 1)))]

    def real(self) -> float:
        if self.rng.random() < 0.3:
            return SPECIAL_FLOATS[int(self.rng.integers(len(SPECIAL_FLOATS)))]
        return float(self.rng.normal() * 10.0 ** int(self.rng.integers(-3, 4)))

    def reals(self, n: int) -> list[float]:
        return [self.real() for _ in range(n)]

    def single(self) -> float:
        """A value a float32 holds (the packer refuses bigger finite ones)."""
        value = self.real()
        return 3.0e38 if np.isfinite(value) and abs(value) > 3.4e38 else value

    def finite(self) -> float:
        value = self.real()
        return value if np.isfinite(value) and abs(value) < 1e30 else 1.25

    def integer(self, low: int, high: int) -> int:
        choice = self.rng.random()
        if choice < 0.2:
            return low
        if choice < 0.4:
            return high
        return low + int(self.rng.integers(0, 2**63)) % (high - low + 1)

    def stamp(self) -> tuple[int, int]:
        return self.integer(0, 2**31 - 1), self.integer(0, 999_999_999)


def _header(r: Random) -> Any:
    secs, nsecs = r.stamp()
    return get_type("std_msgs/Header")(
        seq=r.integer(0, 2**32 - 1), stamp=Time(secs, nsecs), frame_id=r.string()
    )


def _vector(r: Random) -> Any:
    return get_type("geometry_msgs/Vector3")(x=r.real(), y=r.real(), z=r.real())


def _quaternion(r: Random) -> Any:
    return get_type("geometry_msgs/Quaternion")(x=r.real(), y=r.real(), z=r.real(), w=r.real())


def _transform_stamped(r: Random) -> Any:
    transform = get_type("geometry_msgs/Transform")(translation=_vector(r), rotation=_quaternion(r))
    return get_type("geometry_msgs/TransformStamped")(
        header=_header(r), child_frame_id=r.string(), transform=transform
    )


def _pose(r: Random) -> Any:
    point = get_type("geometry_msgs/Point")(x=r.real(), y=r.real(), z=r.real())
    return get_type("geometry_msgs/Pose")(position=point, orientation=_quaternion(r))


def _twist(r: Random) -> Any:
    return get_type("geometry_msgs/Twist")(linear=_vector(r), angular=_vector(r))


def _diagnostics(r: Random) -> Any:
    status = get_type("diagnostic_msgs/DiagnosticStatus")
    value = get_type("diagnostic_msgs/KeyValue")
    items = [
        status(
            level=r.integer(0, 3),
            name=r.string(),
            message=r.string(),
            hardware_id=r.string(),
            values=[value(key=r.string(), value=r.string()) for _ in range(r.integer(0, 3))],
        )
        for _ in range(r.integer(0, 3))
    ]
    return get_type("diagnostic_msgs/DiagnosticArray")(header=_header(r), status=items)


def _kinds(r: Random) -> Any:
    time, duration = Time, Duration

    def span() -> Any:
        return duration(0, r.integer(-(2**31) * 10**9, 2**31 * 10**9 - 1))

    return store().message_class(KINDS_TYPE)(
        flag=bool(r.rng.random() < 0.5),
        flags=[bool(v) for v in r.rng.random(r.integer(0, 4)) < 0.5],
        small=r.integer(-128, 127),
        smalls=[r.integer(-128, 127) for _ in range(r.integer(0, 4))],
        octet=r.integer(0, 255),
        quad=[r.integer(0, 255) for _ in range(4)],
        letter=r.integer(0, 255),
        letters=bytes(r.integer(0, 255) for _ in range(r.integer(0, 5))),
        three=b"a'" + bytes([r.integer(0, 255)]),
        signed=r.integer(-128, 127),
        signeds=[r.integer(-128, 127) for _ in range(r.integer(0, 3))],
        short=r.integer(-(2**15), 2**15 - 1),
        ushort=r.integer(0, 2**16 - 1),
        word=r.integer(-(2**31), 2**31 - 1),
        uword=r.integer(0, 2**32 - 1),
        big=r.integer(-(2**63), 2**63 - 1),
        ubig=r.integer(0, 2**64 - 1),
        single=r.single(),
        singles=[r.finite() for _ in range(3)],
        double=r.real(),
        doubles=r.reals(r.integer(0, 4)),
        text=r.string(),
        pair=[r.string(), r.string()],
        when=time(*r.stamp()),
        span=span(),
        whens=[time(*r.stamp()) for _ in range(r.integer(0, 2))],
        spans=[span() for _ in range(r.integer(0, 2))],
        arrows=[_vector(r), _vector(r)],
        header=_header(r),
    )


def _messages(r: Random) -> dict[str, Any]:
    """One random message per topic."""
    scan = get_type("sensor_msgs/LaserScan")(
        header=_header(r),
        angle_min=r.single(),
        angle_max=r.finite(),
        angle_increment=r.finite(),
        time_increment=r.finite(),
        scan_time=r.finite(),
        range_min=r.finite(),
        range_max=r.single(),
        ranges=[r.finite() for _ in range(r.integer(0, 5))] + [float("inf")],
        intensities=[r.finite() for _ in range(r.integer(0, 3))],
    )
    height, width = r.integer(0, 2), r.integer(0, 3)
    image = get_type("sensor_msgs/Image")(
        header=_header(r),
        height=height,
        width=width,
        encoding=r.string(),
        is_bigendian=r.integer(0, 1),
        step=width * 3,
        data=bytes(int(v) for v in r.rng.integers(0, 256, size=height * width * 3)),
    )
    joints = get_type("sensor_msgs/JointState")(
        header=_header(r),
        name=r.strings(),
        position=r.reals(r.integer(0, 4)),
        velocity=r.reals(r.integer(0, 2)),
        effort=[],
    )
    odom = get_type("nav_msgs/Odometry")(
        header=_header(r),
        child_frame_id=r.string(),
        pose=get_type("geometry_msgs/PoseWithCovariance")(pose=_pose(r), covariance=r.reals(36)),
        twist=get_type("geometry_msgs/TwistWithCovariance")(
            twist=_twist(r), covariance=r.reals(36)
        ),
    )
    return {
        "/chatter": get_type("std_msgs/String")(data=r.string()),
        "/empty": get_type("std_msgs/Empty")(),
        "/header": _header(r),
        "/cmd_vel": _twist(r),
        "/pose": get_type("geometry_msgs/PoseStamped")(header=_header(r), pose=_pose(r)),
        "/transform": _transform_stamped(r),
        "/scan": scan,
        "/joint_states": joints,
        "/camera/image": image,
        "/tf": get_type("tf2_msgs/TFMessage")(
            transforms=[_transform_stamped(r) for _ in range(r.integer(0, 3))]
        ),
        "/odom": odom,
        "/diagnostics": _diagnostics(r),
        "/kinds": _kinds(r),
    }


# More messages or another seed: WORKBENCH_ECHO_ROUNDS=60 WORKBENCH_ECHO_SEED=3 pytest ...
ROUNDS = int(os.environ.get("WORKBENCH_ECHO_ROUNDS", "6"))
SEED = int(os.environ.get("WORKBENCH_ECHO_SEED", "14"))


@pytest.fixture(scope="module")
def bag(tmp_path_factory) -> Path:
    if KINDS_TYPE not in {cls._type for cls in store().classes.values()}:
        store().register_message(KINDS_TYPE, KINDS_TEXT)
    r = Random(SEED)
    path = tmp_path_factory.mktemp("echo") / "echo.bag"
    with BagWriter(path) as writer:
        stamp = 1_700_000_000 * 10**9
        for _ in range(ROUNDS):
            for topic, msg in _messages(r).items():
                stamp += 1_000_003
                writer.write(topic, msg, stamp)
    return path


# (topic or field path, options); every one is echoed by both tools.
CASES: list[tuple[str, list[str]]] = [
    (topic, options)
    for topic in (
        "/chatter",
        "/empty",
        "/header",
        "/cmd_vel",
        "/pose",
        "/transform",
        "/scan",
        "/joint_states",
        "/camera/image",
        "/tf",
        "/odom",
        "/diagnostics",
        "/kinds",
    )
    for options in ([], ["--noarr"], ["--nostr"], ["-p"])
] + [
    ("/kinds", ["-w", "5"]),
    ("/odom", ["-w", "3"]),
    ("/scan", ["-p", "--noarr"]),
    ("/diagnostics", ["--nostr", "--noarr"]),
    ("/odom/pose/pose", []),
    ("/odom/pose/covariance", []),
    ("/odom/header/stamp", []),
    ("/header/stamp/nsecs", []),
    ("/chatter/data", []),
    ("/joint_states/name", []),
    ("/tf/transforms", []),
    ("/tf/transforms", ["--noarr"]),
    ("/tf/transforms[0:2]/child_frame_id", []),
    ("/kinds/whens", []),
    ("/kinds/spans", []),
    ("/kinds/arrows[1]", []),
    ("/kinds/pair[-1]", []),
    ("/kinds/letters", []),
    ("/kinds/three[1:]", []),
    ("/kinds/three[0]", ["--noarr"]),
    ("/scan/ranges[0:3]", []),
    ("/scan/ranges[-1]", []),
    ("/diagnostics/status[0:2]/values", []),
    ("/diagnostics/status[0:2]/values", ["-p"]),
    ("/odom/pose/pose", ["-p"]),
    ("/odom/header/stamp", ["-p"]),
    ("/chatter/data", ["-p"]),
    ("/camera/image/data", ["-p"]),
    ("/kinds", ["-p", "--nostr"]),
    ("/joint_states", ["-n", "2"]),
    # rostopic -b tests every message of the bag, whatever its topic: hence the hasattr
    ("/chatter", ["--filter", "len(getattr(m, 'data', '')) > 3"]),
    ("/kinds/text", ["--filter", "hasattr(m, 'small') and m.small < 100"]),
    ("/scan", ["--filter", "len(getattr(m, 'ranges', ())) > 3", "-c", "-n", "2"]),
    ("", ["-a"]),
]

ROS_SCRIPT = """\
import io, json, sys
import rostopic

out = []
for words in json.loads(sys.argv[1]):
    sys.stdout = buffer = io.StringIO()
    try:
        rostopic._rostopic_cmd_echo(["rostopic", "echo"] + words)
    finally:
        sys.stdout = sys.__stdout__
    out.append(buffer.getvalue())
print(json.dumps(out))
"""


def _rostopic_words(bag: Path, topic: str, options: list[str]) -> list[str]:
    return ["-b", str(bag), *options] + ([topic] if topic else [])


def _workbench(bag: Path, topic: str, options: list[str]) -> str:
    width = int(options[options.index("-w") + 1]) if "-w" in options else None
    count = int(options[options.index("-n") + 1]) if "-n" in options else None
    expression = options[options.index("--filter") + 1] if "--filter" in options else None
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        topic_cli.echo(
            topic,
            bag=str(bag),
            noarr="--noarr" in options,
            nostr="--nostr" in options,
            plot="-p" in options,
            width=width,
            count=count,
            all_topics="-a" in options,
            filter_expr=expression,
            clear="-c" in options,
        )
    return buffer.getvalue()


def _compare(expected: str, actual: str, what: str) -> int:
    want, got = expected.splitlines(), actual.splitlines()
    for number, (a, b) in enumerate(zip(want, got, strict=False), 1):
        assert a == b, f"{what}, line {number}:\n rostopic:  {a!r}\n workbench: {b!r}"
    assert len(want) == len(got), f"{what}: {len(want)} lines from rostopic, {len(got)} here"
    assert expected == actual, what
    return len(want)


def test_echo_matches_rostopic(bag, ros_python):
    words = [_rostopic_words(bag, topic, options) for topic, options in CASES]
    done = subprocess.run(
        [ros_python, "-c", ROS_SCRIPT, json.dumps(words)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout)
    lines = 0
    for (topic, options), text in zip(CASES, expected, strict=True):
        assert text, f"rostopic printed nothing for {topic} {options}"
        lines += _compare(text, _workbench(bag, topic, options), f"{topic} {' '.join(options)}")
    assert lines > 2000 * ROUNDS // 6


def test_the_rostopic_program_prints_the_same(bag, ros_python, tmp_path):
    """The real ``rostopic echo -b`` and ``workbench topic echo -b`` command lines.

    The workbench process has never seen ``echo_test/Kinds``: it learns the type from
    the bag, as rostopic does.
    """
    ros = subprocess.run(
        [ros_python, "/usr/bin/rostopic", "echo", "-b", str(bag), "/kinds", "--noarr"],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=tmp_path,
    )
    assert ros.returncode == 0, ros.stderr
    ours = subprocess.run(
        [sys.executable, "-m", "workbench", "topic", "echo", "-b", str(bag), "/kinds", "--noarr"],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=tmp_path,
        env={**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])},
    )
    assert ours.returncode == 0, ours.stderr
    _compare(ros.stdout, ours.stdout, "rostopic echo -b BAG /kinds --noarr")
    assert ros.stdout.count("---\n") == ROUNDS


LIVE_SCRIPT = """\
import io, json, sys
import rosbag, rostopic

out = []
cases = json.loads(sys.argv[2])
with rosbag.Bag(sys.argv[1]) as bag:
    messages = {}
    for topic, msg, _ in bag.read_messages():
        messages.setdefault(topic, msg)
for topic, field, type_information, noarr, nostr in cases:
    echo = rostopic.CallbackEcho(
        topic + field, rostopic.msgevalgen(field),
        value_transform_fn=rostopic.create_value_transform(nostr, noarr))
    sys.stdout = buffer = io.StringIO()
    try:
        echo.callback(messages[topic], {"topic": topic + field, "type_information": type_information})
    finally:
        sys.stdout = sys.__stdout__
    out.append(buffer.getvalue())
print(json.dumps(out))
"""

LIVE_CASES = [
    ("/joint_states", "/name", False, True),
    ("/joint_states", "/name", True, False),
    ("/chatter", "/data", False, True),
    ("/scan", "/ranges", True, False),
    ("/tf", "/transforms", True, False),
    ("/tf", "/transforms", False, True),
    ("/odom", "/pose", True, True),
    ("/odom", "/pose/covariance", True, False),
    ("/kinds", "/pair", False, True),
    ("/kinds", "/pair", True, False),
    ("/kinds", "/pair[0]", True, False),
    ("/kinds", "/pair[1]", False, True),
    ("/kinds", "/letters", False, False),
    ("/kinds", "/three", True, False),
    ("/kinds", "/header/frame_id", False, True),
    ("/diagnostics", "/status", False, True),
]


def test_live_field_echo_matches_rostopic(bag, ros_python):
    """A live topic's field: rostopic knows its declared type and hides arrays/strings."""
    first: dict[str, Any] = {}
    for record in read_messages(bag):
        first.setdefault(record.topic, record.msg)
    cases = []
    for topic, field, noarr, nostr in LIVE_CASES:
        fields = field.strip("/").split("/")
        cases.append([topic, field, field_type(type(first[topic]), fields), noarr, nostr])
    done = subprocess.run(
        [ros_python, "-c", LIVE_SCRIPT, str(bag), json.dumps(cases)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    for (topic, field, ros_type, noarr, nostr), text in zip(
        cases, json.loads(done.stdout), strict=True
    ):
        value = get_field(first[topic], field.strip("/").split("/"))
        ours = format_echo(value, noarr=noarr, nostr=nostr, ros_type=ros_type) + "\n"
        _compare(text, ours, f"live {topic}{field} noarr={noarr} nostr={nostr}")
