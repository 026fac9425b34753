"""Finding and loading sketches: a shipped one by name, or your own ``.py`` file.

Each load executes the file afresh, as each board gets its own copy of a compiled
sketch: two boards running the same sketch share nothing.
"""

from __future__ import annotations

import importlib.util
import itertools
import traceback
from pathlib import Path
from types import ModuleType

from workbench.errors import SerialError

SKETCH_DIR = Path(__file__).resolve().parent / "sketches"
_count = itertools.count()


def list_sketches() -> list[str]:
    """The names of the shipped sketches (``hello_world``, ``button_motor`` ...)."""
    return sorted(p.stem for p in SKETCH_DIR.glob("*.py") if not p.name.startswith("_"))


def find_sketch(name: str) -> Path:
    """The file of sketch ``name``: a path to a ``.py`` file, or a shipped sketch's name.

    Raises:
        SerialError: No such file or sketch (the message lists the shipped ones).
    """
    path = Path(name).expanduser()
    if path.suffix == ".py" and path.is_file():
        return path.resolve()
    shipped = SKETCH_DIR / f"{Path(name).stem}.py"
    if path.suffix in ("", ".py") and "/" not in name and shipped.is_file():
        return shipped
    raise SerialError(
        f"no sketch '{name}'",
        hint=f"give a .py sketch file or one of: {', '.join(list_sketches())}",
    )


def load_sketch(name: str) -> ModuleType:
    """Load sketch ``name`` (see :func:`find_sketch`) into a fresh module.

    Raises:
        SerialError: Not found, it fails to load (its file and line are named), or it
            lacks ``setup()`` or ``loop()``.
    """
    path = find_sketch(name)
    spec = importlib.util.spec_from_file_location(f"_workbench_sketch_{next(_count)}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except SyntaxError as error:
        raise SerialError(
            f"the sketch does not parse: {error.msg}", path=path, line=error.lineno
        ) from None
    except Exception as error:
        line = next(
            (
                f.lineno
                for f in reversed(traceback.extract_tb(error.__traceback__))
                if Path(f.filename) == path
            ),
            None,
        )
        raise SerialError(
            f"the sketch fails to load: {type(error).__name__}: {error}", path=path, line=line
        ) from None
    for function in ("setup", "loop"):
        if not callable(getattr(module, function, None)):
            raise SerialError(f"the sketch has no {function}() function", path=path)
    return module


def wiring(sketch: ModuleType) -> dict[str, int]:
    """What is connected to which pin (the sketch's ``WIRING``), ``{}`` if it says nothing.

    Raises:
        SerialError: ``WIRING`` is not a dict of names to pin numbers.
    """
    wired = getattr(sketch, "WIRING", {})
    if not isinstance(wired, dict) or not all(
        isinstance(k, str) and isinstance(v, int) for k, v in wired.items()
    ):
        raise SerialError(
            "WIRING must map names to pin numbers, e.g. {'button': 7, 'motor': 13}",
            path=getattr(sketch, "__file__", None),
        )
    return dict(wired)


def is_button(name: str) -> bool:
    """Whether a wired part is an input the user presses (its name says button or switch)."""
    return "button" in name.lower() or "switch" in name.lower()
