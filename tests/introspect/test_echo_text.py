"""``topic echo`` text, pinned to what ROS 1's ``rostopic echo`` (1.15) prints for the same messages.

These run without ROS; ``test_echo_ros_differential.py`` compares against the real tool.
"""

from __future__ import annotations

import contextlib
import io

import pytest

from workbench.bag import BagWriter
from workbench.cli import topic as topic_cli
from workbench.errors import BusError
from workbench.introspect.echo import (
    field_type,
    format_echo,
    format_plot,
    format_plot_header,
    format_value,
    get_field,
)
from workbench.msgs import Duration, Time, get_type


def _header(frame: str = "") -> object:
    return get_type("std_msgs/Header")(seq=3, stamp=Time(5, 47642753), frame_id=frame)


def test_nsecs_are_padded_and_empty_strings_quoted():
    assert format_value(_header()) == (
        "seq: 3\nstamp: \n  secs: 5\n  nsecs:  47642753\nframe_id: ''"
    )
    assert format_value(Time(0, 0)) == "\nsecs: 0\nnsecs:         0"
    assert format_value(Duration(-1, 500_000_000)) == "\nsecs: -1\nnsecs: 500000000"


@pytest.mark.parametrize(
    ("text", "shown"),
    [
        ("hello", '"hello"'),
        ("h\u00e9llo", '"h\\xE9llo"'),
        ("\u4e2d", '"\\u4E2D"'),
        ("\U0001f600", '"\\U0001F600"'),
        ('say "hi"', '"say \\"hi\\""'),
        ("multi\nline", '"multi\\nline"'),
        ("yes", '"yes"'),
        ("", "''"),
    ],
)
def test_strings_are_double_quoted_yaml(text, shown):
    assert format_value(get_type("std_msgs/String")(data=text)) == f"data: {shown}"


def test_string_arrays_are_block_lists_quoted_where_yaml_needs_it():
    joints = get_type("sensor_msgs/JointState")(
        header=_header(), name=["a", "", "h\u00e9", "yes", "a: b", "it's"], position=[1.0, 2.5]
    )
    assert format_value(joints).split("\n")[6:] == [
        "name: ",
        "  - a",
        "  - ''",
        '  - "h\\xE9"',
        "  - 'yes'",
        "  - 'a: b'",
        "  - it's",
        "position: [1.0, 2.5]",
        "velocity: []",
        "effort: []",
    ]


def test_numbers_as_python_prints_them():
    kinds = get_type("std_msgs/Float32")(data=0.1)
    assert format_value(kinds) == "data: 0.10000000149011612"
    assert format_value(get_type("std_msgs/Float64")(data=float("nan"))) == "data: nan"
    assert format_value(get_type("std_msgs/Float64")(data=-float("inf"))) == "data: -inf"
    assert format_value(get_type("std_msgs/Float64")(data=1e20)) == "data: 1e+20"
    assert format_value(get_type("std_msgs/UInt64")(data=2**64 - 1)) == (
        "data: 18446744073709551615"
    )
    assert format_value(get_type("std_msgs/Bool")(data=True)) == "data: True"
    image = get_type("sensor_msgs/Image")(data=b"\x01\x02\xff")
    assert format_value(image).endswith("\ndata: [1, 2, 255]")


def test_lists_of_messages_and_empty_messages():
    vector = get_type("geometry_msgs/Vector3")
    tf = get_type("tf2_msgs/TFMessage")(transforms=[])
    assert format_value(tf) == "transforms: []"
    stamped = get_type("geometry_msgs/TransformStamped")(child_frame_id="b")
    text = format_value(get_type("tf2_msgs/TFMessage")(transforms=[stamped]))
    assert text.startswith("transforms: \n  - \n    header: \n      seq: 0\n")
    assert format_echo(get_type("std_msgs/Empty")()) == "\n---"
    assert format_value([vector(x=1.0), vector()]) == (
        "\n- \n  x: 1.0\n  y: 0.0\n  z: 0.0\n- \n  x: 0.0\n  y: 0.0\n  z: 0.0"
    )


def test_noarr_and_nostr_as_rostopic_replaces_them():
    info = get_type("sensor_msgs/CameraInfo")(header=_header("cam"), D=[0.1, 0.2])
    lines = format_value(info, noarr=True, nostr=True).split("\n")
    assert '  frame_id: "<string length: 3>"' in lines
    assert 'D: "<array type: float64, length: 2>"' in lines
    # rostopic strips '[' and ']' from the right of the type, digits stay
    assert 'K: "<array type: float64[9, length: 9>"' in lines
    # not inside arrays of messages
    status = get_type("diagnostic_msgs/DiagnosticStatus")(name="motor")
    diagnostics = get_type("diagnostic_msgs/DiagnosticArray")(status=[status])
    assert '    name: "motor"' in format_value(diagnostics, nostr=True).split("\n")


def test_noarr_skips_a_nested_message_with_a_nan():
    """rostopic recurses only into nested messages equal to themselves: NaN is not."""
    odom = get_type("nav_msgs/Odometry")()
    odom.pose.pose.position.x = float("nan")
    text = format_value(odom, noarr=True)
    assert "  covariance: [0.0, 0.0," in text
    assert '  covariance: "<array type: float64[36, length: 36>"' in text


def test_a_live_field_hides_by_its_declared_type():
    joints = get_type("sensor_msgs/JointState")(name=["a", "b"])
    ros_type = field_type(type(joints), ["name"])
    assert ros_type == "string[]"
    names = get_field(joints, ["name"])
    assert format_value(names, noarr=True, ros_type=ros_type) == (
        '"<array type: string, length: 2>"'
    )
    assert format_value(names, noarr=True) == "\n- a\n- b"  # a bag's field: no type known


def test_fixed_width():
    twist = get_type("geometry_msgs/Twist")()
    twist.linear.x = 3.14159
    assert format_value(twist, width=5).split("\n")[1] == "  x: 3.141"
    assert format_value(get_type("std_msgs/Int32")(data=42), width=4) == "data:   42"


def test_plot_rows():
    pose = get_type("geometry_msgs/PoseStamped")(header=_header("map"))
    pose.pose.position.x = 1.5
    assert format_plot_header(pose) == (
        "%time,field.header.seq,field.header.stamp,field.header.frame_id,"
        "field.pose.position.x,field.pose.position.y,field.pose.position.z,"
        "field.pose.orientation.x,field.pose.orientation.y,field.pose.orientation.z,"
        "field.pose.orientation.w"
    )
    assert format_plot(pose, 7) == "7,3,5047642753,map,1.5,0.0,0.0,0.0,0.0,0.0,0.0"
    assert format_plot(pose, None).startswith("5047642753,")
    image = get_type("sensor_msgs/Image")(data=b"\x01")
    assert "data" not in format_plot_header(image)


def test_field_paths_with_slices():
    tf = get_type("tf2_msgs/TFMessage")(
        transforms=[
            get_type("geometry_msgs/TransformStamped")(child_frame_id=name) for name in "abc"
        ]
    )
    assert get_field(tf, ["transforms[0:2]", "child_frame_id"]) == ["a", "b"]
    assert get_field(tf, ["transforms[-1]", "child_frame_id"]) == "c"
    assert get_field(tf, ["transforms[::2]", "child_frame_id"]) == ["a", "c"]
    assert get_field(_header(), ["stamp", "nsecs"]) == 47642753
    with pytest.raises(BusError, match="out of range"):
        get_field(tf, ["transforms[5]"])
    with pytest.raises(BusError, match="bad index"):
        get_field(tf, ["transforms[a]"])


def _echo(**kwargs) -> str:
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        assert topic_cli.echo(**kwargs) == 0
    return buffer.getvalue()


def test_echo_a_bag(tmp_path):
    path = tmp_path / "run.bag"
    string = get_type("std_msgs/String")
    with BagWriter(path) as bag:
        for i, text in enumerate(["one", "", "three"]):
            bag.write("/chatter", string(data=text), 10.0 + i)
            bag.write("/header", _header(text), 10.5 + i)
    assert (
        _echo(topic="/chatter", bag=str(path))
        == 'data: "one"\n---\ndata: \'\'\n---\ndata: "three"\n---\n'
    )
    assert _echo(topic="chatter/data", bag=str(path), count=1) == '"one"\n---\n'
    assert _echo(topic="/header/stamp", bag=str(path), count=1) == (
        "\nsecs: 5\nnsecs:  47642753\n---\n"
    )
    assert _echo(topic="/chatter", bag=str(path), plot=True, count=2) == (
        "%time,field.data\n10000000000,one\n11000000000,\n"
    )
    assert _echo(topic="/chatter", bag=str(path), filter_expr="m.data == 'three'") == (
        'data: "three"\n---\n'
    )
    assert _echo(topic="", bag=str(path), all_topics=True).count("---\n") == 6
    with pytest.raises(BusError, match="not in"):
        _echo(topic="/nothing", bag=str(path))
    with pytest.raises(BusError, match="--filter"):
        _echo(topic="/chatter", bag=str(path), filter_expr="m.nope")
    with pytest.raises(BusError, match="at least 2"):
        _echo(topic="/chatter", bag=str(path), width=1)


def test_char_arrays_print_as_python_bytes():
    from workbench.msgs._store import store

    chars = store().register_message("echo_text/Chars", "char letter\nchar[] letters\nbyte[] bs\n")
    msg = chars(letter=65, letters=b"hi'\x00", bs=[1, -2])
    assert format_value(msg) == 'letter: 65\nletters: b"hi\'\\x00"\nbs: [1, -2]'
    assert format_value(msg, noarr=True).split("\n")[1] == (
        'letters: "<array type: char, length: 4>"'
    )
    letters = get_field(msg, ["letters[0:2]"])
    assert format_value(letters, ros_type="char[]", typed=False) == "b'hi'"


def test_live_echo_of_a_field_hides_by_its_type(capsys):
    """On a live topic rostopic knows the echoed field's type: --noarr reaches it."""
    import uuid

    from workbench.bus import Node

    joints = get_type("sensor_msgs/JointState")
    name = f"joints_{uuid.uuid4().hex[:8]}"
    node = Node(name)
    topic = f"/{name}/joint_states"
    node.create_publisher(topic, joints, latch=True).publish(
        joints(header=_header("base"), name=["a", "b"], position=[0.5, 1.0])
    )
    try:
        assert topic_cli.echo(f"{topic}/name", count=1, noarr=True, timeout=10) == 0
        assert capsys.readouterr().out == '"<array type: string, length: 2>"\n---\n'
        assert topic_cli.echo(f"{topic}/name", count=1, timeout=10) == 0
        assert capsys.readouterr().out == "\n- a\n- b\n---\n"
        assert topic_cli.echo(topic, count=1, plot=True, noarr=True, timeout=10) == 0
        header, row = capsys.readouterr().out.splitlines()
        assert header == "%time,field.header.seq,field.header.stamp,field.header.frame_id"
        # the time of a live message with a header is its stamp; the publisher numbers seq
        assert row.startswith("5047642753,") and row.endswith(",5047642753,base")
    finally:
        node.shutdown()
