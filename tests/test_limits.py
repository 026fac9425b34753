"""Bounds on input: regular files only, sizes, YAML depth and alias expansion, nested values."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from workbench.errors import BusError, WorkbenchError
from workbench.limits import (
    TreeLimits,
    check_regular_file,
    check_tree,
    load_yaml,
    load_yaml_file,
    read_bytes_bounded,
    read_text_bounded,
    tree_size,
)

#: A "billion laughs" document: 9**7 strings from seven lines of aliases.
LAUGHS = (Path(__file__).parent / "data/hostile/parameters/alias_bomb.yaml").read_text()


def test_a_billion_laughs_is_refused_before_it_is_built():
    assert len(LAUGHS) < 400
    with pytest.raises(WorkbenchError, match="more than 1,000,000 elements once its aliases"):
        load_yaml(LAUGHS, "the bomb")
    # the same shape within the bound loads, with its aliases shared
    small = LAUGHS.splitlines()[:3]
    data = load_yaml("\n".join(small))
    assert len(data["c"]) == 9 and data["c"][0][0][0] == "lol"


def test_depth_and_size_bounds_name_the_input():
    limits = TreeLimits(max_depth=3, max_nodes=50, max_bytes=100)
    with pytest.raises(BusError, match="the value is nested more than 3 levels deep") as info:
        load_yaml("[[[[1]]]]", "the value", limits, BusError, "v.yaml")
    assert info.value.path == "v.yaml" and info.value.line == 1
    with pytest.raises(BusError, match="more than 50 elements"):
        load_yaml(str(list(range(60))), "x", limits, BusError)
    with pytest.raises(BusError, match="more than 100 bytes of text"):
        load_yaml("x" * 101, "x", limits, BusError)
    # an alias counts at its depth: the anchored list is two deep, used two deep -> four
    with pytest.raises(BusError, match="nested more than 3"):
        load_yaml("a: &a [[1]]\nb: [[*a]]\n", "x", limits, BusError)
    assert load_yaml("a: &a [[1]]\nb: *a\n", "x", limits, BusError) == {"a": [[1]], "b": [[1]]}
    with pytest.raises(WorkbenchError, match="nested more than 64 levels"):
        load_yaml("[" * 3000 + "]" * 3000)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("&a [*a]", r"alias \*a refers to a node that is not complete"),
        ("a: [1, 2", r"is not valid YAML: did not find expected ',' or '\]'"),
        ("1" * 5000, "a value YAML cannot build"),
        ("!!python/object/apply:os.system [id]", "could not determine a constructor"),
        (
            "a: 1\n---\nb: 2\n",
            "is not valid YAML: expected a single document in the stream but found another",
        ),
    ],
)
def test_bad_yaml_is_one_line(text, message):
    with pytest.raises(WorkbenchError, match=message) as info:
        load_yaml(text, "value")
    assert "\n" not in info.value.one_line()


def test_only_regular_files_are_read(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(BusError, match="is a FIFO .named pipe.; a thing must be a regular file"):
        read_text_bounded(fifo, "thing", BusError)  # would block forever if opened
    with pytest.raises(BusError, match="is a device; a thing must be a regular file"):
        read_bytes_bounded("/dev/zero", "thing", 10, BusError)  # would never end
    with pytest.raises(BusError, match="is a directory, not a thing"):
        check_regular_file(tmp_path, "thing", BusError)
    with pytest.raises(BusError, match="cannot read thing: no such file"):
        check_regular_file(tmp_path / "nope", "thing", BusError)


def test_size_and_encoding_bounds(tmp_path):
    big = tmp_path / "big.bin"
    big.write_bytes(b"x" * 11)
    assert read_bytes_bounded(big, "blob", 11) == b"x" * 11
    with pytest.raises(WorkbenchError, match="blob is larger than 10 bytes"):
        read_bytes_bounded(big, "blob", 10)
    binary = tmp_path / "params.yaml"
    binary.write_bytes(b"a: 1\n\xff\xfe\x00")
    with pytest.raises(WorkbenchError, match=r"not UTF-8 text \(byte 0xff at offset 5\)") as info:
        load_yaml_file(binary, "parameter file")
    assert info.value.line == 2


def test_check_tree_walks_without_recursion():
    deep: list = []
    for _ in range(100_000):  # far past the interpreter's recursion limit
        deep = [deep]
    with pytest.raises(WorkbenchError, match="nested more than 64 levels"):
        check_tree(deep, "the list", TreeLimits())
    loop: list = []
    loop.append(loop)  # a list containing itself is infinitely deep
    with pytest.raises(WorkbenchError, match="nested more than"):
        check_tree(loop, "the loop", TreeLimits())
    check_tree({"a": [1, "xy"]}, "ok", TreeLimits(max_depth=2, max_nodes=5, max_bytes=12))
    assert tree_size({"a": [1, "xy"]}) == (5, 11)  # dict, key, list, 1 (8), "xy" (2) + key (1)
