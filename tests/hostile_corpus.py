"""The hostile-input corpus of ``tests/data/hostile/<kind>/``: cases, inputs, and running them.

Importable by name from any test folder (``from hostile_corpus import cases, run_case``).
Each kind (parameters, launch, bags, logs, maps) has a ``cases.yaml``: a list of

``name``    what the case is;
``argv``    the ``workbench`` command line, with ``{dir}`` (the kind's folder), ``{input}``
            (the input ``make`` created), ``{tmp}`` (the case's own empty folder) and
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
    return word.replace("{dir}", str(folder)).replace("{tmp}", str(tmp)).replace("{input}", made)


def _unexpand(text: str, kind: str, tmp: Path, made: str) -> str:
    if made:
        text = text.replace(made, "{input}")
    return text.replace(str(tmp), "{tmp}").replace(str(HOSTILE / kind), "{dir}")


def run_case(case: dict[str, Any], kind: str, tmp: Path) -> dict[str, Any]:
    """Run one case in ``tmp``; returns ``{"status", "stderr", "stdout"}`` as the corpus has them."""
    from workbench.cli import main

    made = GENERATORS[case["make"]](tmp) if case.get("make") else ""
    argv = [_expand(word, kind, tmp, made) for word in case["argv"]]
    stdout, stderr = io.StringIO(), io.StringIO()
    cwd = Path.cwd()
    os.chdir(tmp)
    try:
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            status = main(argv)
    finally:
        os.chdir(cwd)
    return {
        "status": status,
        "stderr": _unexpand(stderr.getvalue().strip(), kind, tmp, made),
        "stdout": _unexpand(stdout.getvalue(), kind, tmp, made),
    }
