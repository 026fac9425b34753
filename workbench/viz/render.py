"""Render an HTML snapshot to PNG with headless Chromium."""

from __future__ import annotations

import subprocess
import tempfile
from pathlib import Path

from workbench.errors import ViewerError
from workbench.optional import require_program

#: Flags that keep a headless Chromium quiet, offline and independent of any profile.
CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--hide-scrollbars",
    "--mute-audio",
)


def render_png(
    html_path: str | Path,
    png_path: str | Path,
    *,
    width: int = 1024,
    height: int = 768,
    budget_ms: int = 5000,
    timeout: float = 180.0,
) -> Path:
    """Load ``html_path`` in headless Chromium and save a screenshot.

    Args:
        html_path: A local HTML file (e.g. a Meshcat snapshot).
        png_path: Where to write the PNG.
        width: Window width in pixels.
        height: Window height in pixels.
        budget_ms: Virtual time the page gets to load and draw its WebGL scene.
        timeout: Wall-clock seconds before Chromium is stopped.

    Raises:
        MissingDependencyError: Chromium is not installed.
        ViewerError: Chromium failed or wrote no image.
    """
    chromium = require_program("chromium")
    html_path = Path(html_path).resolve()
    png_path = Path(png_path).resolve()
    if not html_path.is_file():
        raise ViewerError("no such HTML file", path=html_path)
    png_path.parent.mkdir(parents=True, exist_ok=True)
    if png_path.exists():
        png_path.unlink()
    with tempfile.TemporaryDirectory(prefix="workbench-chromium-") as profile:
        command = [
            chromium,
            *CHROMIUM_FLAGS,
            f"--user-data-dir={profile}",
            f"--window-size={width},{height}",
            f"--virtual-time-budget={budget_ms}",
            f"--screenshot={png_path}",
            html_path.as_uri(),
        ]
        try:
            result = subprocess.run(
                command, capture_output=True, text=True, timeout=timeout, check=False
            )
        except subprocess.TimeoutExpired:
            raise ViewerError(
                f"Chromium did not finish within {timeout:.0f} s", path=html_path
            ) from None
    if not png_path.is_file() or png_path.stat().st_size == 0:
        tail = (result.stderr or "").strip().splitlines()[-1:] or ["no output"]
        raise ViewerError(
            f"Chromium wrote no screenshot (exit {result.returncode}: {tail[0]})",
            path=html_path,
            hint="check that Chromium runs headless on this machine",
        )
    return png_path
