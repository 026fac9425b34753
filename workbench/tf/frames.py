"""The frame tree as a graphviz drawing (tf2_tools ``view_frames``, ``rqt_tf_tree``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from workbench.errors import TransformError


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def frames_dot(info: dict[str, dict[str, Any]], recorded_at: float | None = None) -> str:
    """Graphviz source of the frame tree from :meth:`BufferCore.frames_info`.

    Each edge parent -> child is labelled like view_frames: broadcaster, average
    rate (Hz), buffer length (s), most recent and oldest transform (s); static
    frames say so instead of a rate.
    """
    lines = ["digraph G {", '  node [shape=ellipse, fontname="Helvetica"];']
    for child, entry in info.items():
        if entry.get("static"):
            label = (
                f"Broadcaster: {entry['broadcaster']}\\nStatic transform (valid at all times)\\n"
            )
        else:
            label = (
                f"Broadcaster: {entry['broadcaster']}\\n"
                f"Average rate: {entry['rate']:.3f} Hz\\n"
                f"Buffer length: {entry['buffer_length']:.3f} s\\n"
                f"Most recent transform: {entry['most_recent_transform']:.3f}\\n"
                f"Oldest transform: {entry['oldest_transform']:.3f}\\n"
            )
        lines.append(f'  {_quote(entry["parent"])} -> {_quote(child)} [label="{label}"];')
    if recorded_at is not None:
        lines.append("  edge [style=invis];")
        lines.append(
            '  subgraph cluster_legend { style=bold; color=black; label="view_frames Result";'
        )
        lines.append(f'    "Recorded at time: {recorded_at:.3f}" [shape=plaintext];')
        lines.append("  }")
    lines.append("}")
    return "\n".join(lines) + "\n"


def write_frames(dot_source: str, path: str | Path) -> Path:
    """Write the drawing: ``.gv``/``.dot`` as text, ``.png``/``.pdf``/``.svg`` through graphviz ``dot``.

    Raises:
        MissingDependencyError: graphviz ``dot`` is not installed (for images).
        TransformError: an unknown file extension.
    """
    path = Path(path)
    suffix = path.suffix.lower().lstrip(".")
    if suffix in ("gv", "dot"):
        path.write_text(dot_source)
        return path
    if suffix not in ("png", "pdf", "svg"):
        raise TransformError(
            f"cannot write the frame tree as '{path.name}'",
            hint="use a .png, .pdf, .svg or .gv file name",
        )
    import subprocess

    from workbench.optional import require_program

    dot = require_program("dot")
    result = subprocess.run(
        [dot, f"-T{suffix}", "-o", str(path)],
        input=dot_source,
        text=True,
        capture_output=True,
        check=False,
    )
    if result.returncode != 0:
        raise TransformError(f"graphviz failed to draw {path}: {result.stderr.strip()}")
    return path
