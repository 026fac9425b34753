"""The hostile-input corpus of ``tests/data/hostile/<kind>/``: cases, inputs, and running them.

Importable by name from any test folder (``from hostile_corpus import cases, run_case``).
Each kind (parameters, launch, bags, logs, maps) has a ``cases.yaml``: a list of

``name``    what the case is;
``argv``    the ``workbench`` command line, with ``{dir}`` (the kind's folder), ``{input}``
            (the input ``make`` created), ``{repo}`` (the checkout), ``{tmp}`` (the case's own empty folder) and
            ``{text:FILE}`` (the contents of ``FILE`` of the kind's folder);
``make``    optional: the name of a generator below, for inputs too large or too special to
            store (a FIFO, a 2 MB gzip bomb, a 100,000-character name);
``status``  the exit status;
``stderr``  everything the command prints on stderr (its one error line, or its warnings);
``stdout``  optional: lines that must appear on stdout.

The commands run in this process (``workbench.cli.main``) on an in-process bus, in the case's
own folder. Regenerate the expected output after a deliberate change with
``python tests/data/hostile/regenerate_data.py`` and review the diff.
"""

from __future__ import annotations

import contextlib
import gzip
import io
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import yaml

HOSTILE = Path(__file__).resolve().parent / "data" / "hostile"


def _fifo(tmp: Path) -> str:
    path = tmp / "input.fifo"
    os.mkfifo(path)
    return str(path)


def _gzip_bomb(tmp: Path) -> str:
    """2 GiB of newlines in about 2 MB: one gzip member of 16 MiB, repeated 128 times."""
    member = gzip.compress(b"\n" * (16 * 1024 * 1024), compresslevel=9, mtime=0)
    path = tmp / "bomb.log.gz"
    with open(path, "wb") as stream:
        for _ in range(128):
            stream.write(member)
    return str(path)


def _long_line_log(tmp: Path) -> str:
    """A CARMEN log whose only line is 64 MiB long (no newline)."""
    path = tmp / "long.log"
    with open(path, "wb") as stream:
        stream.write(b"FLASER 3 ")
        stream.write(b"1.0 " * (16 * 1024 * 1024))
    return str(path)


def _map_with_fifo_image(tmp: Path) -> str:
    """A map YAML whose image is a FIFO."""
    os.mkfifo(tmp / "map.pgm")
    path = tmp / "map.yaml"
    path.write_text(
        "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
    )
    return str(path)


def _dev_zero(tmp: Path) -> str:
    return "/dev/zero"


def _directory(tmp: Path) -> str:
    path = tmp / "a_directory"
    path.mkdir()
    return str(path)


def _plugin_absolute_world(tmp: Path) -> str:
    """A world whose plugin is a file outside its folder, named by absolute path."""
    plugin = HOSTILE / "plugins" / "outside" / "pwned_plugin.py"
    return _world(tmp, f'<plugin name="pwned" filename="{plugin}"/>')


def _include_absolute_world(tmp: Path) -> str:
    """A world including a model file outside its folder by absolute path."""
    model = HOSTILE / "plugins" / "outside" / "pwned_model" / "model.sdf"
    return _world(tmp, f"<include><uri>{model}</uri></include>")


def _plugin_long_name_world(tmp: Path) -> str:
    return _world(tmp, f'<plugin name="{"p" * 5000}" filename="model_push.py"/>')


def _plugin_long_filename_world(tmp: Path) -> str:
    return _world(tmp, f'<plugin name="long" filename="{"f" * 5000}.py"/>')


def _deep_json_plan(tmp: Path) -> str:
    """A JSON plan whose walls are nested 100,000 lists deep (Python's decoder recurses)."""
    path = tmp / "deep.json"
    path.write_text('{"walls": ' + "[" * 100_000 + "]" * 100_000 + "}")
    return str(path)


def _plan_of_20000_walls(tmp: Path) -> str:
    """A JSON plan of 20,000 parallel walls (a crossing check over all pairs is 2e8 pairs)."""
    import json

    walls = [{"name": f"w{i}", "start": [0, i * 0.5], "end": [3, i * 0.5]} for i in range(20_000)]
    path = tmp / "walls.json"
    path.write_text(json.dumps({"walls": walls}))
    return str(path)


def _foreign_world_file(tmp: Path) -> str:
    """A world file the user wrote by hand, where ``world build -o`` is pointed."""
    path = tmp / "mine.world"
    path.write_text('<?xml version="1.0"?>\n<sdf version="1.6"><world name="mine"/></sdf>\n')
    return str(path)


def _plain_file(tmp: Path) -> str:
    """A file where a folder is expected."""
    path = tmp / "notes"
    path.write_text("my notes\n")
    return str(path)


def _world(tmp: Path, body: str, name: str = "input.world") -> str:
    path = tmp / name
    path.write_text(
        '<?xml version="1.0"?>\n<sdf version="1.6">\n<world name="default">\n'
        f"<include><uri>model://ground_plane</uri></include>\n{body}\n</world>\n</sdf>\n"
    )
    return str(path)


def _box_model(name: str, x: float = 0.0, links: int = 1, plugin: str = "") -> str:
    """An SDF model of ``links`` 10 cm boxes in a row, ``x`` m along the world's x axis."""
    body = "".join(
        f'<link name="link{i}"><pose>{0.2 * i} 0 0.05 0 0 0</pose><inertial><mass>1</mass>'
        "<inertia><ixx>0.002</ixx><iyy>0.002</iyy><izz>0.002</izz></inertia></inertial>"
        '<collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry>'
        "</collision></link>"
        for i in range(links)
    )
    return f'<model name="{name}"><pose>{x} 0 0 0 0 0</pose>{plugin}{body}</model>\n'


def _world_long_model_name(tmp: Path) -> str:
    """A world whose one model is named with 45,000 characters (Drake crashed on it)."""
    return _world(tmp, _box_model("m" * 45_000))


def _world_long_include_name(tmp: Path) -> str:
    """A world including a model folder under a ``<name>`` of 5,000 characters."""
    folder = tmp / "crate"
    folder.mkdir()
    (folder / "model.config").write_text(
        '<?xml version="1.0"?>\n<model><name>crate</name><sdf version="1.6">model.sdf</sdf></model>\n'
    )
    (folder / "model.sdf").write_text(f'<sdf version="1.6">{_box_model("crate")}</sdf>\n')
    return _world(tmp, f"<include><uri>crate</uri><name>{'n' * 5_000}</name></include>")


def _world_long_include_uri(tmp: Path) -> str:
    """A world including ``model://`` of a 5,000-character model name."""
    return _world(tmp, f"<include><uri>model://{'n' * 5_000}</uri></include>")


def _world_2000_models(tmp: Path) -> str:
    return _world(tmp, "".join(_box_model(f"box{i}", i * 0.5) for i in range(2_000)))


def _world_3000_links(tmp: Path) -> str:
    return _world(tmp, _box_model("row", links=3_000))


def _world_3000_static_links(tmp: Path) -> str:
    """3,000 wall links in one static model (a traced map of the Intel lab has 1,606)."""
    walls = _box_model("walls", links=3_000).replace("<pose>", "<static>true</static><pose>", 1)
    return _world(tmp, walls)


def _world_500_plugins(tmp: Path) -> str:
    plugins = "".join(
        f'<plugin name="p{i}" filename="libgazebo_ros_p3d.so"><bodyName>link0</bodyName>'
        f"<topicName>odom{i}</topicName></plugin>"
        for i in range(500)
    )
    return _world(tmp, _box_model("box", plugin=plugins))


def _world_includes_1200_links(tmp: Path) -> str:
    """Three includes of one 400-link model folder: each is within bounds, together not."""
    folder = tmp / "row"
    folder.mkdir()
    (folder / "model.config").write_text(
        '<?xml version="1.0"?>\n<model><name>row</name><sdf version="1.6">model.sdf</sdf></model>\n'
    )
    (folder / "model.sdf").write_text(f'<sdf version="1.6">{_box_model("row", links=400)}</sdf>\n')
    includes = "".join(
        f"<include><uri>row</uri><name>row{i}</name><pose>0 {i} 0 0 0 0</pose></include>"
        for i in range(3)
    )
    return _world(tmp, includes)


_RVIZ_HEAD = "Visualization Manager:\n  Global Options:\n    Fixed Frame: map\n  Displays:\n"


def _rviz_long_comment(tmp: Path) -> str:
    """A valid .rviz config after a 20 MB comment."""
    path = tmp / "commented.rviz"
    with open(path, "w") as stream:
        for _ in range(20):
            stream.write("#" + "x" * (1024 * 1024 - 2) + "\n")
        stream.write(_RVIZ_HEAD + "    - Class: rviz/Grid\n      Name: Grid\n")
    return str(path)


def _rviz_5000_displays(tmp: Path) -> str:
    """An .rviz config listing 5,000 Marker displays."""
    path = tmp / "displays.rviz"
    entry = "    - Class: rviz/Marker\n      Name: Marker {0}\n      Marker Topic: m{0}\n"
    path.write_text(_RVIZ_HEAD + "".join(entry.format(i) for i in range(5000)))
    return str(path)


def _rviz_1000_deep_groups(tmp: Path) -> str:
    """An .rviz config with display groups nested 1,000 deep (flow style)."""
    path = tmp / "deep.rviz"
    group = "{Class: rviz/Group, Name: G, Displays: ["
    path.write_text(_RVIZ_HEAD + "    - " + group * 1000 + "]}" * 1000 + "\n")
    return str(path)


#: ``make:`` name -> function(tmp folder) -> the ``{input}`` path.
GENERATORS: dict[str, Callable[[Path], str]] = {
    "fifo": _fifo,
    "gzip_bomb": _gzip_bomb,
    "long_line_log": _long_line_log,
    "dev_zero": _dev_zero,
    "directory": _directory,
    "map_with_fifo_image": _map_with_fifo_image,
    "plugin_absolute_world": _plugin_absolute_world,
    "include_absolute_world": _include_absolute_world,
    "plugin_long_name_world": _plugin_long_name_world,
    "plugin_long_filename_world": _plugin_long_filename_world,
    "deep_json_plan": _deep_json_plan,
    "plan_of_20000_walls": _plan_of_20000_walls,
    "foreign_world_file": _foreign_world_file,
    "plain_file": _plain_file,
    "world_long_model_name": _world_long_model_name,
    "world_long_include_name": _world_long_include_name,
    "world_long_include_uri": _world_long_include_uri,
    "world_2000_models": _world_2000_models,
    "world_3000_links": _world_3000_links,
    "world_500_plugins": _world_500_plugins,
    "world_3000_static_links": _world_3000_static_links,
    "world_includes_1200_links": _world_includes_1200_links,
    "rviz_long_comment": _rviz_long_comment,
    "rviz_5000_displays": _rviz_5000_displays,
    "rviz_1000_deep_groups": _rviz_1000_deep_groups,
}


def cases(kind: str) -> list[dict[str, Any]]:
    """The cases of ``tests/data/hostile/<kind>/cases.yaml``."""
    return yaml.safe_load((HOSTILE / kind / "cases.yaml").read_text())


def case_ids(kind: str) -> list[str]:
    return [case["name"] for case in cases(kind)]


def _expand(word: str, kind: str, tmp: Path, made: str) -> str:
    folder = HOSTILE / kind
    while "{text:" in word:
        start = word.index("{text:")
        end = word.index("}", start)
        name = word[start + len("{text:") : end]
        word = word[:start] + (folder / name).read_text() + word[end + 1 :]
    word = word.replace("{repo}", str(HOSTILE.parents[2]))
    return word.replace("{dir}", str(folder)).replace("{tmp}", str(tmp)).replace("{input}", made)


def _unexpand(text: str, kind: str, tmp: Path, made: str) -> str:
    if made:
        text = text.replace(made, "{input}")
    text = text.replace(str(tmp), "{tmp}").replace(str(HOSTILE / kind), "{dir}")
    return text.replace(str(HOSTILE.parents[2]), "{repo}")


@contextlib.contextmanager
def _logging_to(stream: io.StringIO) -> Any:
    """Log records reach ``stream`` as a fresh process prints them (the message, WARNING and
    up), whatever handlers an earlier case or test left on the root logger: Drake configures
    logging the first time it logs, which would bind the output to that case's stream."""
    import logging

    handler = logging.StreamHandler(stream)
    handler.setFormatter(logging.Formatter("%(message)s"))
    handler.setLevel(logging.WARNING)
    root = logging.getLogger()
    saved = root.handlers[:]
    root.handlers = [handler]
    try:
        yield
    finally:
        root.handlers = saved


def run_case(case: dict[str, Any], kind: str, tmp: Path) -> dict[str, Any]:
    """Run one case in ``tmp``; returns ``{"status", "stderr", "stdout"}`` as the corpus has them."""
    from workbench.cli import main

    made = GENERATORS[case["make"]](tmp) if case.get("make") else ""
    argv = [_expand(word, kind, tmp, made) for word in case["argv"]]
    stdout, stderr = io.StringIO(), io.StringIO()
    cwd = Path.cwd()
    os.chdir(tmp)
    try:
        with (
            contextlib.redirect_stdout(stdout),
            contextlib.redirect_stderr(stderr),
            _logging_to(stderr),
        ):
            status = main(argv)
    finally:
        os.chdir(cwd)
    return {
        "status": status,
        "stderr": _unexpand(stderr.getvalue().strip(), kind, tmp, made),
        "stdout": _unexpand(stdout.getvalue(), kind, tmp, made),
    }
