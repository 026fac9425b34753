"""ROS name rules: validation, resolution, remapping arguments."""

from __future__ import annotations

import pytest

from workbench.bus.names import (
    InvalidNameError,
    canonical_namespace,
    check_base_name,
    check_name,
    myargv,
    parse_command_line,
    resolve,
)


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("chatter", "/ns/chatter"),
        ("/chatter", "/chatter"),
        ("~rate", "/ns/talker/rate"),
        ("turtle1/cmd_vel", "/ns/turtle1/cmd_vel"),
        ("", "/ns"),
    ],
)
def test_resolve(name, expected):
    assert resolve(name, "/ns", "/ns/talker") == expected


def test_resolve_in_root_namespace():
    assert resolve("chatter", "/", "/talker") == "/chatter"
    assert resolve("~x", "/", "/talker") == "/talker/x"


@pytest.mark.parametrize("bad", ["1abc", "a//b", "a b", "a-b", "~/x", "chat ter", "a/", "/a/1b"])
def test_malformed_names_are_refused(bad):
    with pytest.raises(InvalidNameError, match="not a valid ROS topic name"):
        check_name(bad, "topic name")


def test_node_names_have_no_namespace():
    assert check_base_name("talker") == "talker"
    with pytest.raises(InvalidNameError, match="namespaces are not allowed"):
        check_base_name("ns/talker")
    with pytest.raises(InvalidNameError):
        check_base_name("9lives")


def test_canonical_namespace():
    assert canonical_namespace(None) == "/"
    assert canonical_namespace("robot1") == "/robot1"
    assert canonical_namespace("/a/b/") == "/a/b"


def test_command_line_arguments():
    line = parse_command_line(
        ["1", "chatter:=/other", "__name:=speaker", "__ns:=lab", "_rate:=5", "_names:=[a, b]", "3"]
    )
    assert line.remappings == {"chatter": "/other"}
    assert line.node_name == "speaker" and line.namespace == "/lab"
    assert line.params == {"rate": 5, "names": ["a", "b"]}
    assert line.others == ["1", "3"]
    assert myargv(["prog", "a:=b", "x"]) == ["prog", "x"]
    with pytest.raises(InvalidNameError):
        parse_command_line(["bad name:=x"])
