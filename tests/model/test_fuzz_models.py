"""Seeded fuzzing of model files (URDF, xacro, SDF): a result or one clean error, always.

Real models from ``urdf/`` and the xacro feature file are mutated (numbers made
NaN, infinite, huge or garbage; names made long, quoted, multi-line; elements
deleted, duplicated, moved and nested deeply; hostile xacro expressions and
includes; bytes cut and flipped) and each mutant goes through what ``check``,
``graph`` and ``show`` do: ``check_robot`` (which loads the model into Drake when it
finds no error), the urdf_to_graphviz text, and ``load_robot``. A few mutants also go
through the real command line. See :mod:`model_fuzz_helpers` for what is asserted.
"""

from __future__ import annotations

import copy
import random
import shutil
from pathlib import Path

import pytest
from lxml import etree
from model_fuzz_helpers import (
    HOSTILE_EXPRESSIONS,
    HOSTILE_NAMES,
    HOSTILE_NUMBERS,
    hang_guard,
    outside_writes,
    run_workbench,
    watched,
)
from model_hostile_corpus import REPO, snapshot

from workbench.errors import WorkbenchError

SEEDS = ["arm3.urdf", "robot_arm.urdf", "flexible.urdf", "custom_bot.urdf", "table.urdf.xacro"]
SEEDS += ["two_wheeled_robot.sdf", "features.urdf.xacro"]
#: Mutants per run; the seed makes every run the same.
MUTANTS = 300
SEED = 17
FEATURES = REPO / "tests" / "data" / "xacro_features"

#: Mesh file names that are not meshes, or not files at all.
HOSTILE_FILES = ["/dev/zero", "/proc/self/mem", "/etc", "/etc/passwd.obj", "x" * 5000 + ".obj"]
HOSTILE_FILES += ["package://no_such/x.obj", "file:///etc/hostname.stl", "", "../../x.dae", "a.3ds"]
NUMERIC = {"xyz", "rpy", "size", "radius", "length", "scale", "value", "lower", "upper"}
NUMERIC |= {"effort", "velocity", "ixx", "ixy", "ixz", "iyy", "iyz", "izz", "rgba", "damping"}


def _source(name: str) -> Path:
    if name == "features.urdf.xacro":
        return FEATURES / "urdf" / name
    return REPO / "urdf" / name


def _mutate_tree(root, rng: random.Random, sentinel: Path, xacro: bool) -> str:
    """Change the XML tree in place; returns what was done."""
    elements = [e for e in root.iter() if isinstance(e.tag, str)]
    element = rng.choice(elements)
    kind = rng.choice(
        ["number", "number", "name", "delete", "duplicate", "attribute", "move", "nest", "text"]
        + ["filename"]
        + (["expression", "expression", "macro", "include"] if xacro else [])
    )
    if kind == "number":
        candidates = [
            (e, a) for e in elements for a in e.attrib if a in NUMERIC and e is not root
        ] or [(element, "xyz")]
        target, attribute = rng.choice(candidates)
        value = " ".join(rng.choice(HOSTILE_NUMBERS) for _ in range(rng.choice([1, 3])))
        target.set(attribute, value)
        return f"{target.tag} {attribute}={value[:30]!r}"
    if kind == "name":
        named = [e for e in elements if "name" in e.attrib] or [root]
        target = rng.choice(named)
        value = rng.choice(HOSTILE_NAMES)
        target.set("name", value)
        return f"{target.tag} name={value[:30]!r}"
    if kind == "filename":
        value = rng.choice(HOSTILE_FILES)
        meshes = [e for e in elements if e.tag == "mesh"]
        uris = [e for e in elements if e.tag == "uri"]
        if meshes:
            rng.choice(meshes).set("filename", value)
        elif uris:
            rng.choice(uris).text = value
        else:
            visual = etree.SubElement(rng.choice(elements), "visual")
            geometry = etree.SubElement(visual, "geometry")
            etree.SubElement(geometry, "mesh", filename=value)
        return f"mesh file {value[:40]!r}"
    if kind == "delete" and element is not root:
        element.getparent().remove(element)
        return f"deleted <{element.tag}>"
    if kind == "duplicate" and element is not root:
        for _ in range(rng.choice([1, 2, 50])):
            element.addnext(copy.deepcopy(element))
        return f"duplicated <{element.tag}>"
    if kind == "attribute" and element.attrib:
        name = rng.choice(list(element.attrib))
        del element.attrib[name]
        return f"<{element.tag}> without {name}"
    if kind == "move" and element is not root:
        target = rng.choice(elements)
        if element not in target.iterancestors() and target is not element:
            element.getparent().remove(element)
            target.append(element)
            return f"<{element.tag}> moved into <{target.tag}>"
    if kind == "nest" and element is not root:
        depth = rng.choice([50, 300, 3000])
        parent, index = element.getparent(), element.getparent().index(element)
        outer = wrapper = etree.Element("x")
        for _ in range(depth - 1):
            wrapper = etree.SubElement(wrapper, "x")
        parent.remove(element)
        wrapper.append(element)
        parent.insert(index, outer)
        return f"<{element.tag}> nested {depth} deep"
    if kind == "text" and len(element) == 0:
        element.text = rng.choice(HOSTILE_NUMBERS + HOSTILE_NAMES[:4])
        return f"<{element.tag}> text {element.text[:20]!r}"
    if kind == "expression":
        expression = rng.choice(HOSTILE_EXPRESSIONS).replace("{sentinel}", str(sentinel))
        target = rng.choice([e for e in elements if e.attrib] or [root])
        attribute = rng.choice(list(target.attrib) or ["name"])
        target.set(attribute, expression)
        return f"{target.tag} {attribute}={expression[:40]!r}"
    if kind == "macro":
        namespace = "http://www.ros.org/wiki/xacro"
        depth = rng.choice([5, 25, 40])
        for level in range(depth + 1):
            macro = etree.SubElement(root, f"{{{namespace}}}macro", name=f"m{level}")
            if level == 0:
                etree.SubElement(macro, "link", name="fuzz")
            else:
                for _ in range(2):
                    etree.SubElement(macro, f"{{{namespace}}}m{level - 1}")
        etree.SubElement(root, f"{{{namespace}}}m{depth}")
        return f"macro bomb 2^{depth}"
    if kind == "include":
        namespace = "http://www.ros.org/wiki/xacro"
        target = rng.choice(["/etc/hosts", "/dev/zero", "../../../../etc/passwd", "missing.xacro"])
        root.insert(0, etree.Element(f"{{{namespace}}}include", filename=target))
        return f"include {target}"
    element.set("fuzz", rng.choice(HOSTILE_NAMES[2:]))
    return f"<{element.tag}> extra attribute"


def _mutate_bytes(data: bytes, rng: random.Random) -> tuple[bytes, str]:
    kind = rng.choice(["truncate", "flip", "insert"])
    at = rng.randrange(len(data))
    if kind == "truncate":
        return data[:at], f"cut at byte {at}"
    if kind == "flip":
        flipped = bytearray(data)
        for _ in range(rng.choice([1, 10])):
            flipped[rng.randrange(len(flipped))] = rng.randrange(256)
        return bytes(flipped), "bytes flipped"
    junk = rng.choice([b"\x00", b"\xff\xfe", "\u202e".encode(), b"<![CDATA[", b"&x;", b"]]>"])
    return data[:at] + junk + data[at:], f"{junk!r} inserted at {at}"


def _mutant(name: str, rng: random.Random, sentinel: Path) -> tuple[bytes, str]:
    data = _source(name).read_bytes()
    if rng.random() < 0.15:
        return _mutate_bytes(data, rng)
    parser = etree.XMLParser(remove_comments=False, resolve_entities=False, huge_tree=True)
    root = etree.fromstring(data, parser)
    done = [
        _mutate_tree(root, rng, sentinel, name.endswith(".xacro"))
        for _ in range(rng.choice([1, 1, 2, 3]))
    ]
    return etree.tostring(root, xml_declaration=True, encoding="utf-8"), "; ".join(done)


def _exercise(path: Path) -> None:
    """What check, graph and show do with a file, in-process."""
    from workbench.model.check import check_robot
    from workbench.model.graph import graph_source, read_graph_document
    from workbench.model.loader import load_robot

    for step in (
        lambda: check_robot(path),
        lambda: graph_source(read_graph_document(path)),
        lambda: load_robot(path),
    ):
        try:
            step()
        except WorkbenchError as error:
            text = error.one_line()
            assert "\n" not in text and len(text) < 20000, text[:300]


@pytest.fixture
def fuzz_folder(tmp_path, monkeypatch):
    """A folder holding a copy of the feature package (mutants of it live inside)."""
    shutil.copytree(FEATURES, tmp_path / "features")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("WORKBENCH_CACHE_DIR", str(tmp_path / "cache"))
    for variable in ("WORKBENCH_PACKAGE_PATH", "ROS_PACKAGE_PATH"):
        monkeypatch.delenv(variable, raising=False)
    return tmp_path


def _target(folder: Path, name: str, index: int) -> Path:
    suffix = ".urdf.xacro" if name.endswith(".xacro") else Path(name).suffix
    home = folder / "features" / "urdf" if name == "features.urdf.xacro" else folder
    return home / f"mutant{index}{suffix}"


def test_model_mutants_end_cleanly(fuzz_folder):
    rng = random.Random(SEED)
    sentinel = fuzz_folder.parent / f"{fuzz_folder.name}-sentinel"
    before = snapshot(watched())
    failures = []
    for index in range(MUTANTS):
        name = rng.choice(SEEDS)
        data, what = _mutant(name, rng, sentinel)
        path = _target(fuzz_folder, name, index)
        path.write_bytes(data)
        label = f"mutant {index} of {name} ({what})"
        try:
            with hang_guard(label):
                _exercise(path)
        except (Exception, SystemExit) as error:  # anything but a WorkbenchError is a bug
            failures.append(f"{label}: {type(error).__name__}: {str(error)[:300]}")
        path.unlink()
    assert not failures, "\n".join(failures[:20])
    assert outside_writes(before, [sentinel]) == []
    assert sorted(p.name for p in fuzz_folder.iterdir()) == ["cache", "features"] or sorted(
        p.name for p in fuzz_folder.iterdir()
    ) == ["features"]


@pytest.mark.parametrize("index", range(4))
def test_model_mutants_through_the_command_line(tmp_path, index):
    """A few mutants in a fresh process: no traceback, no signal, no guard line."""
    rng = random.Random(SEED * 100 + index)
    sentinel = tmp_path.parent / f"{tmp_path.name}-sentinel"
    name = rng.choice(SEEDS[:-1])
    data, what = _mutant(name, rng, sentinel)
    path = _target(tmp_path, name, index)
    path.write_bytes(data)
    for command in (["check", str(path)], ["graph", str(path), "-o", str(tmp_path / "g.gv")]):
        run_workbench(command, tmp_path, what)
    assert not sentinel.exists()
