"""``rosserial_arduino make_libraries.py DIR``: Arduino message headers for every known type.

``workbench run rosserial_arduino make_libraries.py DIR`` writes
``DIR/ros_lib/<package>/<Type>.h`` for every message and service type workbench
knows (see :mod:`workbench.serial.headers_sources`), in the layout and with the
serialization of rosserial_client's generator (see
:mod:`workbench.serial.headers_cpp`), so custom messages work with the Arduino
IDE's "Rosserial Arduino Library". Options beyond the original's::

    --msgs PKG_DIR   also export a ROS package folder's msg/*.msg and srv/*.srv (repeatable)
    --package NAME   export only this package (repeatable)

It prints ``Exporting to DIR/ros_lib`` and one line per package, as the original
prints each package with its messages and services. Unlike the original it writes
message headers only, into the existing folder, without deleting anything: the
runtime (``ros.h``, ``ros/node_handle.h``, ``ros/msg.h``, ``ArduinoHardware.h``)
is the Arduino library's.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from workbench.errors import SerialError
from workbench.serial.headers_cpp import message_header, service_header
from workbench.serial.headers_sources import PackageTypes, known_packages, register_package_dir

USAGE = "usage: make_libraries.py DIR [--msgs PKG_DIR]... [--package NAME]..."
RUNTIME_NOTE = (
    "These are message headers: ros.h, ros/node_handle.h, ros/msg.h and ArduinoHardware.h "
    'come with the Arduino IDE\'s "Rosserial Arduino Library" (Library Manager); copy the '
    "package folders you need into its src/ folder."
)


def _write(path: Path, text: str) -> None:
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    except OSError as error:
        raise SerialError(
            f"cannot write {path}: {error.strerror}",
            hint="give a folder you can write to",
        ) from None


def write_package(root: Path, package: PackageTypes) -> list[Path]:
    """Write the headers of one package into ``root/<package>/``.

    Args:
        root: The ``ros_lib`` folder.
        package: The package's types.

    Returns:
        The files written, messages first, then services.
    """
    written = []
    for cls in package.messages:
        path = root / package.name / f"{cls.__name__}.h"
        _write(path, message_header(cls))
        written.append(path)
    for service in package.services:
        path = root / package.name / f"{service.__name__}.h"
        _write(path, service_header(service))
        written.append(path)
    return written


def _ros_lib(directory: str | os.PathLike[str]) -> Path:
    folder = Path(directory)
    if folder.exists() and not folder.is_dir():
        raise SerialError(f"{folder} is a file, not a folder", hint="give the folder to write into")
    return folder / "ros_lib"


def write_libraries(
    directory: str | os.PathLike[str], packages: Sequence[str] | None = None
) -> list[Path]:
    """Write ``directory/ros_lib/<package>/<Type>.h`` for every known message and service type.

    Args:
        directory: The folder that gets (or has) ``ros_lib``; created if missing.
        packages: Only these packages; None exports every package.

    Returns:
        The header files written.

    Raises:
        SerialError: An unknown package, a type whose dependencies are not registered,
            or a folder that cannot be written.
    """
    root = _ros_lib(directory)
    return [path for package in known_packages(packages) for path in write_package(root, package)]


@dataclass
class Options:
    """The command line of make_libraries.py."""

    directory: str | None = None
    msgs: list[str] = field(default_factory=list)
    packages: list[str] = field(default_factory=list)
    show_help: bool = False


def parse_arguments(argv: Sequence[str]) -> Options:
    """Options from the node's arguments (remappings already removed).

    Raises:
        SerialError: An unknown option, an option without its value, or no / two folders.
    """
    options = Options()
    values = list(argv)
    while values:
        arg = values.pop(0)
        if arg in ("-h", "--help"):
            options.show_help = True
            return options
        name, equals, value = arg.partition("=")
        if name in ("--msgs", "--package"):
            if not equals:
                if not values:
                    raise SerialError(f"make_libraries.py: {name} needs a value", hint=USAGE)
                value = values.pop(0)
            (options.msgs if name == "--msgs" else options.packages).append(value)
        elif arg.startswith("-") and arg != "-":
            raise SerialError(f"make_libraries.py: unknown option '{arg}'", hint=USAGE)
        elif options.directory is not None:
            raise SerialError(
                f"make_libraries.py: one output folder, not '{options.directory}' and '{arg}'",
                hint=USAGE,
            )
        else:
            options.directory = arg
    if options.directory is None and not options.show_help:
        raise SerialError("make_libraries.py needs the folder to write ros_lib into", hint=USAGE)
    return options


def _names(classes: Sequence[type]) -> str:
    return ", ".join(cls.__name__ for cls in classes)


def main(argv: Sequence[str] = ()) -> int:
    """``rosserial_arduino/make_libraries.py``: write the headers, one line per package.

    Args:
        argv: ``DIR`` and options (remappings such as ``__name:=x`` are ignored).

    Returns:
        0 when every header was written.
    """
    from workbench.bus.names import myargv

    options = parse_arguments(myargv(list(argv)))
    if options.show_help:
        print(USAGE)
        return 0
    assert options.directory is not None
    root = _ros_lib(options.directory)
    custom = [register_package_dir(folder) for folder in options.msgs]
    wanted = options.packages or None
    packages = known_packages(wanted)
    print(f"\nExporting to {root}")
    count = 0
    for package in packages:
        parts = []
        if package.messages:
            parts.append(f"Messages: {_names(package.messages)}")
        if package.services:
            parts.append(f"Services: {_names(package.services)}")
        print(f"Exporting {package.name}  {'  '.join(parts)}", flush=True)
        count += len(write_package(root, package))
    extra = f" (with {', '.join(custom)})" if custom else ""
    print(f"\nWrote {count} headers of {len(packages)} packages into {root}{extra}.")
    print(RUNTIME_NOTE)
    return 0


__all__ = ["Options", "main", "parse_arguments", "write_libraries", "write_package"]
